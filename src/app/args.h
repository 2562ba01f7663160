// args.h — command-line options: parsed strictly, each error one line for standard error.
#pragma once

#include <string>
#include <vector>

namespace mb {

enum ExitCode : int { kExitOk = 0, kExitBadInput = 1, kExitUsage = 2, kExitNoGl = 3 };

struct Args {
    std::vector<std::string> positional;
    std::string output;              // -o
    int width = 640, height = 360;   // --size WxH
    double seconds = 0;              // --seconds
    int frames = 20;                 // --frames
    int threads = 1;                 // --threads 1|2: the simulator's (same bytes either way)
    bool uber = false;               // --uber
    std::string mode = "shaded";     // --mode
    std::string post = "none";       // --post none|fxaa|fxaa-edges|fxaa-direction
    std::string backend = "osmesa";  // --backend osmesa|egl
    std::string quality = "normal";  // --quality draft|normal|final
};

// Parses argv[first..argc). Returns false with *error set on an unknown option, a missing or
// malformed value, or a value out of range.
bool parseArgs(int argc, char** argv, int first, Args* out, std::string* error);

// An argument quoted for an error message: control characters shown as '?' so the message
// stays one line, and cut at 60 bytes so a pasted file does not fill the terminal.
std::string quoteArg(const std::string& arg);

constexpr int kMaxImageSide = 16384;
// Off-screen renders run on the CPU (llvmpipe): 4096x4096 takes minutes and 64 MiB a copy;
// 16384x16384 would take an hour and gigabytes, which looks like a hang.
constexpr long kMaxImagePixels = 4096L * 4096L;
constexpr double kMaxSeconds = 3600;

}  // namespace mb
