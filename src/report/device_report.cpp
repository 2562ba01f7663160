// device_report.cpp — frame times, a sequence's pace and the pictures' agreement on the EGL
// device, each from this executable run as a separate process.
#include "device_report.h"

#include "processes.h"
#include "report_plot.h"
#include "report_template.h"

#include "marchbox/gl/image.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <vector>

namespace mb {

namespace {

constexpr const char* kBegin = "<!-- device section: written by report render --backend egl -->";
constexpr const char* kEnd = "<!-- end of device section -->";
constexpr int kBenchFrames = 20;
constexpr int kSequenceFrames = 90;  // 3 s at 30 fps
const char* const kSizes[] = {"1280x720", "1920x1080", "3840x2160"};

// Runs a command of this executable (args[0]) on the device, or through OSMesa; its output.
bool run(std::vector<std::string> args, bool onDevice, std::string* out) {
    if (onDevice) args.insert(args.end(), {"--backend", "egl"});
    return runForOutput(args, out);
}

// `bench`'s "median_ms: X" line, as a cell; "failed" where it did not run.
std::string medianCell(const std::string& exe, const std::string& scene, const char* size) {
    std::string out;
    const bool ok =
        run({exe, "bench", scene, "--frames", std::to_string(kBenchFrames), "--size", size}, true,
            &out);
    const size_t at = out.rfind("median_ms: ");
    if (!ok || at == std::string::npos) return "failed";
    return fmt("%.1f ms", std::atof(out.c_str() + at + 11));
}

std::string frameTimes(const std::string& exe, const std::string& root) {
    std::ostringstream md;
    md << "| scene | " << kSizes[0] << " | " << kSizes[1] << " | " << kSizes[2]
       << " |\n| --- | ---: | ---: | ---: |\n";
    for (const char* name : {"default", "pile", "mixed_pile", "dominoes"}) {
        md << "| " << name;
        for (const char* size : kSizes)
            md << " | " << medianCell(exe, root + "/scenes/" + name + ".txt", size);
        md << " |\n";
    }
    return md.str();
}

std::string sequencePace(const std::string& exe, const std::string& root, const std::string& dir) {
    const std::string last = std::to_string(kSequenceFrames - 1);
    const double seconds =
        timedRun({exe, "render", root + "/scenes/pile.txt", "-o", dir + "/f_%05d.png", "--frames",
                  "0-" + last, "--size", "1920x1080", "--backend", "egl"});
    char lastFile[32];
    std::snprintf(lastFile, sizeof lastFile, "/f_%05d.png", kSequenceFrames - 1);
    if (seconds <= 0.0 || !std::filesystem::exists(dir + lastFile))
        return "The sequence failed to render.\n";
    return "`render scenes/pile.txt --frames 0-" + last +
           " --size 1920x1080 --backend egl` wrote its " + std::to_string(kSequenceFrames) +
           " PNG files in " + fmt("%.1f s", seconds) + ": **" +
           fmt("%.1f", kSequenceFrames / seconds) +
           " frames a second** (target 30), simulation, readback and encoding included.\n";
}

// Each example scene at 640x360 through EGL and through OSMesa.
std::string agreement(const std::string& exe, const std::string& root, const std::string& dir) {
    std::ostringstream md;
    md << "| scene | PSNR dB, EGL against OSMesa |\n| --- | ---: |\n";
    for (const std::filesystem::path& scene : exampleSceneFiles(root)) {
        const std::string a = dir + "/egl.png", b = dir + "/osmesa.png";
        auto render = [&](const std::string& png, bool onDevice, Image* img) {
            std::string out, error;
            return run({exe, "render", scene, "-o", png, "--size", "640x360"}, onDevice, &out) &&
                   loadPng(png, img, &error);
        };
        Image ia, ib;
        const bool ok = render(a, true, &ia) && render(b, false, &ib);
        md << "| " << scene.stem().string() << " | " << (ok ? fmt("%.1f", psnr(ia, ib)) : "failed")
           << " |\n";
        std::filesystem::remove(a);
        std::filesystem::remove(b);
    }
    return md.str();
}

}  // namespace

std::string deviceSection(const std::string& root, const std::string& device) {
    const std::string exe = executablePath();
    char dirTemplate[] = "/tmp/marchbox-device-XXXXXX";
    if (exe.empty() || !mkdtemp(dirTemplate)) return "";
    const std::string dir = dirTemplate;
    std::ostringstream md;
    md << kBegin << "\n## On " << device << ", through `--backend egl`\n\n"
       << "Measured by `build/marchbox report render --backend egl` on " << machineDescription()
       << "; the sections above are OSMesa's. Each figure comes from this executable run as a "
          "separate process, as a user runs it.\n\n### Frame time\n\nMedian of "
       << kBenchFrames << " frames after a warm-up, `bench SCENE --size WxH --backend egl`:\n\n"
       << frameTimes(exe, root) << "\n### A sequence\n\n"
       << sequencePace(exe, root, dir) << "\n### The same pictures\n\n"
       << "Each example scene at 640x360, drawn on this device and by OSMesa (llvmpipe):\n\n"
       << agreement(exe, root, dir) << kEnd << "\n";
    std::filesystem::remove_all(dir);
    return md.str();
}

std::string keptDeviceSection(const std::string& report) {
    const size_t begin = report.find(kBegin), end = report.find(kEnd);
    if (begin != std::string::npos && end != std::string::npos && begin < end)
        return report.substr(begin, end + std::string(kEnd).size() - begin) + "\n";
    return std::string(kBegin) +
           "\n## On a GPU\n\nNot measured here: run `build/marchbox report render --backend egl` "
           "on a machine with a GPU. It measures this section alone, under the device's name, "
           "and leaves the rest of the report as it is.\n" +
           kEnd + "\n";
}

std::string withDeviceSection(const std::string& report, const std::string& section) {
    const size_t begin = report.find(kBegin), end = report.find(kEnd);
    if (begin == std::string::npos || end == std::string::npos || end < begin)
        return report + "\n" + section;
    size_t after = end + std::string(kEnd).size();
    if (after < report.size() && report[after] == '\n') ++after;
    return report.substr(0, begin) + section + report.substr(after);
}

}  // namespace mb
