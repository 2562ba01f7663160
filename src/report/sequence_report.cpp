// sequence_report.cpp — a sequence's cost is its frames, not its simulations: one
// `render --frames 0-299` of the pile against the same 300 frames drawn from a pile already
// simulated, and against the 300 separate `render --seconds` calls a sequence replaces.
#include "sequence_report.h"

#include "processes.h"
#include "report_template.h"

#include "marchbox/report/median.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <vector>

namespace mb {

namespace {

constexpr int kFrames = 300;             // 10 s at 30 fps
constexpr int kRounds = 3;               // of the sequence and its two comparisons, in turn
constexpr int kSingles = 10;             // separate calls timed, spread over the clip, then scaled
constexpr const char* kSize = "160x90";  // small frames: the simulation's share at its largest

struct Row {
    std::string what;
    double seconds;
};

std::string table(const std::vector<Row>& rows, double sequence) {
    std::ostringstream md;
    md << "| " << kFrames << " frames of `scenes/pile.txt` at " << kSize
       << " | seconds | sequence / this |\n| --- | ---: | ---: |\n";
    for (const Row& r : rows)
        md << "| " << r.what << " | " << fmt("%.1f", r.seconds) << " | "
           << fmt("%.2fx", sequence / r.seconds) << " |\n";
    return md.str();
}

// kSingles calls of `render` at frames spread over the clip, each its own process, scaled to
// kFrames: `seconds` true simulates to each frame's time, as a sequence once had to.
double separateCalls(const std::string& exe, const std::string& scene, const std::string& out,
                     bool seconds) {
    double total = 0.0;
    for (int i = 0; i < kSingles; ++i) {
        std::vector<std::string> args = {exe, "render", scene, "-o", out, "--size", kSize};
        if (seconds) {
            const int frame = i * kFrames / kSingles;
            args.insert(args.end(), {"--seconds", fmt("%.6f", frame / 30.0)});
        }
        const double t = timedRun(args);
        if (t < 0.0) return -1.0;
        total += t;
    }
    return total * kFrames / kSingles;
}

}  // namespace

std::string sequenceSection(const std::string& root) {
    const std::string exe = executablePath(), pile = root + "/scenes/pile.txt";
    char dirTemplate[] = "/tmp/marchbox-sequence-XXXXXX";
    if (exe.empty() || !mkdtemp(dirTemplate)) return "Not measured: no executable or no /tmp.\n";
    const std::string dir = dirTemplate, settled = dir + "/settled.txt";
    const std::string last = "0-" + std::to_string(kFrames - 1);
    std::string text = "Not measured: a command failed.\n";
    if (timedRun({exe, "simulate", pile, "--seconds", "10", "-o", settled}) >= 0.0) {
        std::vector<double> sequence, drawn, bench, vsDrawn, vsBench;
        for (int round = 0; round < kRounds; ++round) {
            const double s = timedRun({exe, "render", pile, "-o", dir + "/f_%05d.png", "--size",
                                       kSize, "--frames", last});
            const double d = timedRun({exe, "render", settled, "-o", dir + "/s_%05d.png", "--size",
                                       kSize, "--frames", last});
            const double b = timedRun(
                {exe, "bench", settled, "--size", kSize, "--frames", std::to_string(kFrames)});
            if (s < 0.0 || d < 0.0 || b < 0.0) break;
            sequence.push_back(s);
            drawn.push_back(d);
            bench.push_back(b);
            vsDrawn.push_back(s / d);
            vsBench.push_back(s / b);
        }
        const double singles = separateCalls(exe, settled, dir + "/one.png", false);
        const double fromStart = separateCalls(exe, pile, dir + "/one.png", true);
        if (int(sequence.size()) == kRounds && singles > 0.0 && fromStart > 0.0) {
            const double seq = median(sequence);
            text = table(
                {{"one `render --frames " + last + "`, the pile played from t = 0", seq},
                 {"the same, of the pile simulated 10 s first (at rest)", median(drawn)},
                 {"`bench --frames 300` of the simulated pile: drawing alone, no "
                  "readback or PNG",
                  median(bench)},
                 {"300 `render` calls of the simulated pile, a process each", singles},
                 {"300 `render --seconds k/30` calls, each simulating from t = 0", fromStart}},
                seq);
            text += "\nThe sequence takes **" + fmt("%.2fx", median(vsDrawn)) +
                    "** the time of the same 300 frames rendered from the pile already "
                    "simulated, PNGs and all (target at most 1.2x): one simulation adds that "
                    "much to 300 renders. Drawing alone is " +
                    fmt("%.0f%%", 100.0 / median(vsBench)) +
                    " of it; at this size the rest is reading each frame back and writing its "
                    "PNG, alike in both. The separate `render --seconds` calls it replaces "
                    "take " +
                    fmt("%.0f", fromStart / seq) + " times as long. Ratios are medians of " +
                    std::to_string(kRounds) +
                    " rounds' own, the first three rows run in turn; the last two rows time " +
                    std::to_string(kSingles) + " calls at frames spread over the clip, scaled to " +
                    std::to_string(kFrames) + ".\n";
        }
    }
    std::filesystem::remove_all(dir);
    return text;
}

}  // namespace mb
