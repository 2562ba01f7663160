// render_frames.cpp — render --frames A-B: the scene played once from t = 0 (frame_sequence.h),
// each frame rendered with renderFrame as it is reached and handed to its output.
#include "commands.h"
#include "frame_output.h"
#include "frame_sequence.h"
#include "interrupt.h"

#include "marchbox/scene/scene_io.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace mb {

namespace {

constexpr const char* kUsage =
    "marchbox render SCENE -o PATTERN|OUT.mp4 --frames A-B [--fps F] [--size WxH] [--quality Q] "
    "[--skip-existing]";

// Usage errors (exit 2) the options alone show, before any file is read.
bool framesUsable(const Args& a, FramePattern* pattern) {
    const std::string error = framesError(a, pattern);
    if (!error.empty()) std::cerr << error << '\n';
    return error.empty();
}

// One line on a terminal, rewritten after each frame: where the run is and when it ends.
class FrameProgress {
public:
    FrameProgress(int first, int last)
        : first_(first), last_(last), shown_(isatty(STDERR_FILENO)) {}
    void frameDone(int frame) {
        if (!shown_) return;
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        const int done = frame - first_ + 1, total = last_ - first_ + 1;
        const double perSecond = done / std::max(elapsed, 1e-6);
        const int left = int((total - done) / perSecond + 0.5);
        std::fprintf(stderr, "\rframe %d (%d of %d), %.1f frames/s, %d:%02d left  %s", frame, done,
                     total, perSecond, left / 60, left % 60, done == total ? "\n" : "");
    }

private:
    int first_, last_;
    bool shown_;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// Hands the oldest frame in flight to `out`. A terminal's Ctrl-C reaches ffmpeg too, which
// then takes no more frames: that failure is the interruption's.
int handOver(FrameReadback& ring, FrameOutput& out) {
    ReadFrame f;
    std::string error;
    if (!ring.take(&f, &error)) return out.abandon(), glFailure("render", error);
    if (!out.write(f.frame, f.image, &error) && !interrupted())
        return out.abandon(), std::cerr << error << '\n', kExitBadInput;
    return kExitOk;
}

// Plays the scene and hands each frame to `out`, in order, a few frames after it is drawn;
// the exit status. Ctrl-C ends the process (endInterrupted) once `out` has removed what was
// not whole; frames still in flight are dropped.
int playFrames(const Scene& scene, const RenderOptions& options, const Args& a, FrameOutput& out) {
    OffscreenRun run;
    OffscreenContext context;
    Renderer renderer;
    std::string error;
    if (!offscreenBackend(a, &run.backend)) return kExitUsage;
    if (!context.create(1, 1, &error, run.backend) || !renderer.init(&error))
        return glFailure("render", error);
    run.progress = [](float, void*) { return !interrupted(); };  // a large frame stops midway
    FrameSequence sequence(scene, physicsSettings(a), a.fps.value_or(30));
    FrameReadback ring;
    const FrameRange range = *a.frameRange;
    FrameProgress progress(range.first, range.last);
    int status = kExitOk;
    for (int k = range.first; k <= range.last && !interrupted() && status == kExitOk; ++k) {
        if (sequence.reach(k, interrupted) && out.wanted(k)) {
            if (ring.full()) status = handOver(ring, out);
            bool ok = status == kExitOk && renderFrame(renderer, sequence.scene(k), options,
                                                       a.width, a.height, ring, k, &error, run);
            if (interrupted() || status != kExitOk) break;
            if (!ok) return out.abandon(), glFailure("render", error);
        }
        progress.frameDone(k);
    }
    while (status == kExitOk && !ring.empty() && !interrupted()) status = handOver(ring, out);
    if (interrupted()) out.abandon(), endInterrupted();
    if (status != kExitOk) return status;
    if (out.finish(&error)) return kExitOk;
    std::cerr << error << '\n';
    return kExitBadInput;
}

}  // namespace

int runRenderFrames(const Args& a) {
    RenderOptions options;
    QualityPreset preset;
    FramePattern pattern;
    if (!needOne(a, kUsage) || !needOutput(a, "render", "PATTERN or OUT.mp4") ||
        !renderOptions(a, &options) || !qualityPreset(a, &preset) || !framesUsable(a, &pattern))
        return kExitUsage;
    Scene scene;
    if (!loadOrReport(a.positional[0], &scene)) return kExitBadInput;
    // Catch Ctrl-C before ffmpeg starts: a video's temporary file is removed whenever it comes.
    catchInterrupts();
    std::string error;
    std::unique_ptr<FrameOutput> out =
        openFrames(a.output, pattern, a.frameRange->first, a.width, a.height, a.fps.value_or(30),
                   a.skipExisting, &error);
    if (!out) {
        std::cerr << error << '\n';
        return kExitBadInput;
    }
    applyQualityPreset(preset, &scene.render, &options);
    return playFrames(scene, options, a, *out);
}

}  // namespace mb
