// args.h — command-line options: parsed strictly, each error one line for standard error.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mb {

enum ExitCode : int { kExitOk = 0, kExitBadInput = 1, kExitUsage = 2, kExitNoGl = 3 };

// Frames first to last, inclusive: render --frames A-B.
struct FrameRange {
    int first = 0, last = 0;
};

struct Args {
    std::vector<std::string> positional;
    std::string output;                    // -o
    int width = 640, height = 360;         // --size WxH
    std::optional<double> seconds;         // --seconds (0 when absent)
    std::optional<int> frameCount;         // --frames N: bench's frames (20 when absent)
    std::optional<FrameRange> frameRange;  // --frames A-B: render's frames
    std::optional<double> fps;             // --fps, with --frames A-B (30 when absent)
    std::optional<double> voxel;           // --voxel S: export's voxel, m (default: from the scene)
    bool skipExisting = false;             // --skip-existing, with --frames A-B
    int threads = 1;                       // --threads 1|2: the simulator's (same bytes either way)
    bool uber = false;                     // --uber
    std::string mode = "shaded";           // --mode
    std::string post = "none";             // --post none|fxaa|fxaa-edges|fxaa-direction
    std::string backend = "osmesa";        // --backend osmesa|egl
    std::string quality = "normal";        // --quality draft|normal|final
    std::vector<std::string> given;        // the options on the command line, in order
};

// Parses argv[first..argc). Returns false with *error set on an unknown option, a missing or
// malformed value, or a value out of range.
bool parseArgs(int argc, char** argv, int first, Args* out, std::string* error);

// The first of a.given that `allowed` (options separated by spaces) does not hold; empty where
// every option belongs. Each command takes its own (docs/cli.md's Options).
std::string optionNotIn(const Args& a, std::string_view allowed);

// An argument quoted for an error message: control characters shown as '?' so the message
// stays one line, and cut at 60 bytes so a pasted file does not fill the terminal.
std::string quoteArg(const std::string& arg);

constexpr int kMaxImageSide = 16384;
// Off-screen renders run on the CPU (llvmpipe): 4096x4096 takes minutes and 64 MiB a copy;
// 16384x16384 would take an hour and gigabytes, which looks like a hang.
constexpr long kMaxImagePixels = 4096L * 4096L;
// The one limit on an image's size, for --size and File > Render... alike, and its words.
constexpr const char* kImageSizeRule = "WxH, each side 1 to 16384, at most 4096x4096 pixels in all";
bool validImageSize(long width, long height);
constexpr double kMaxSeconds = 3600;
constexpr const char* kFramesNotRange = "render --frames takes a range A-B, such as 0-299";
constexpr int kMaxFrame = 10000000;  // --frames A-B: 3600 s at 2778 fps
constexpr double kMaxFps = 1000;

}  // namespace mb
