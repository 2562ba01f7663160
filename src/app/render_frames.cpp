// render_frames.cpp — render --frames A-B: the scene played once from t = 0 at the fixed
// physics step, frame k rendered when the simulation reaches t = k / fps.
//
// Frame k is the picture `render --seconds k/fps` makes: the same number of steps (stepsFor),
// the same camera (cameraAt), the same renderFrame. So a range gives the same bytes in one
// process or split over many, each simulating from t = 0 to its first frame.
#include "commands.h"
#include "frame_output.h"
#include "interrupt.h"

#include "marchbox/scene/camera_path.h"
#include "marchbox/scene/scene_io.h"

#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <unistd.h>

namespace mb {

namespace {

constexpr const char* kUsage =
    "marchbox render SCENE -o PATTERN|OUT.mp4 --frames A-B [--fps F] [--size WxH] [--quality Q] "
    "[--skip-existing]";

// .mp4 in any case: .MP4 is as common a spelling, and no frame pattern either way.
bool isVideo(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    return ext == ".mp4";
}

// Usage errors (exit 2) the options alone show, before any file is read.
bool framesUsable(const Args& a, FramePattern* pattern) {
    const double fps = a.fps.value_or(30);
    std::string error;
    if (a.seconds) error = "--seconds does not go with --frames: frame k shows t = k / fps";
    else if (a.frameRange->last / fps > kMaxSeconds)
        error = "frame " + std::to_string(a.frameRange->last) + " is past 3600 s at this --fps";
    else if (isVideo(a.output) && a.skipExisting)
        error = "--skip-existing takes a PATTERN of files, not a video";
    else if (isVideo(a.output) && (a.width % 2 || a.height % 2))
        error = "an H.264 video needs an even width and height (--size)";
    else if (!isVideo(a.output)) parseFramePattern(a.output, pattern, &error);
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

// Plays the scene and hands each frame to `out`; the exit status. Ctrl-C ends the process
// (endInterrupted) once `out` has removed what was not whole.
int playFrames(const Scene& scene, const RenderOptions& options, const Args& a, FrameOutput& out) {
    OffscreenRun run;
    OffscreenContext context;
    Renderer renderer;
    std::string error;
    if (!offscreenBackend(a, &run.backend)) return kExitUsage;
    if (!context.create(1, 1, &error, run.backend) || !renderer.init(&error))
        return glFailure("render", error);
    run.progress = [](float, void*) { return !interrupted(); };  // a large frame stops midway
    const PhysicsSettings settings = physicsSettings(a);
    PhysicsWorld world(scene, settings);
    const FrameRange range = *a.frameRange;
    const double fps = a.fps.value_or(30);
    FrameProgress progress(range.first, range.last);
    for (int k = range.first; k <= range.last && !interrupted(); ++k) {
        const double t = k / fps;
        for (const int steps = stepsFor(t, settings); world.stepCount() < steps && !interrupted();)
            world.step();
        if (!interrupted() && out.wanted(k)) {
            Scene frame = scene;
            world.writeBack(frame);
            frame.camera = cameraAt(frame.keyframes, frame.camera, t);
            Image img;
            bool ok = renderFrame(renderer, frame, options, a.width, a.height, &img, &error, run);
            if (interrupted()) break;
            if (!ok) return out.abandon(), glFailure("render", error);
            // A terminal's Ctrl-C reaches ffmpeg too, which then takes no more frames.
            if (!out.write(k, img, &error) && !interrupted())
                return out.abandon(), std::cerr << error << '\n', kExitBadInput;
        }
        progress.frameDone(k);
    }
    if (interrupted()) out.abandon(), endInterrupted();
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
        isVideo(a.output) ? videoFrames(a.output, a.width, a.height, a.fps.value_or(30), &error)
                          : pngFrames(pattern, a.frameRange->first, a.skipExisting, &error);
    if (!out) {
        std::cerr << error << '\n';
        return kExitBadInput;
    }
    applyQualityPreset(preset, &scene.render, &options);
    return playFrames(scene, options, a, *out);
}

}  // namespace mb
