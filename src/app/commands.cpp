// commands.cpp — render, simulate, check, shader and bench: load, act, report in one line.
#include "commands.h"
#include "frame_output.h"
#include "interrupt.h"

#include "marchbox/export/export.h"
#include "marchbox/gl/offscreen_context.h"
#include "marchbox/gl/quality_preset.h"
#include "marchbox/gl/renderer.h"
#include "marchbox/physics/physics.h"
#include "marchbox/scene/camera_path.h"
#include "marchbox/scene/scene_io.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace mb {

bool loadOrReport(const std::string& path, Scene* scene) {
    std::vector<std::string> errors;
    if (loadScene(path, scene, &errors)) return true;
    for (const std::string& e : errors) std::cerr << e << '\n';
    return false;
}

bool needOne(const Args& a, const char* usage) {
    if (a.positional.size() == 1) return true;
    std::cerr << "usage: " << usage << '\n';
    return false;
}

bool needOutput(const Args& a, const char* command, const char* what) {
    if (!a.output.empty()) return true;
    std::cerr << command << " needs -o " << what << '\n';
    return false;
}

// A driver's log runs to several lines (warnings, the error, a blank); the CLI promises one line
// per error, and the first error is the one to fix. The label in front ("fragment shader: ")
// is kept when the error is further down. Drivers write `...: error:` (Mesa, NVIDIA) or
// `ERROR: ...` (AMD, Intel); a bare "error" could be part of a shader's path.
static bool isErrorLine(const std::string& line) {
    return line.find(": error") != std::string::npos || line.find("ERROR: ") != std::string::npos;
}

static std::string firstErrorLine(const std::string& text) {
    const std::string first = text.substr(0, text.find('\n'));
    for (size_t at = 0; at < text.size();) {
        size_t end = std::min(text.find('\n', at), text.size());
        std::string line = text.substr(at, end - at);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        size_t label = first.find(": ");
        if (isErrorLine(line))
            return at == 0 || label == std::string::npos ? line : first.substr(0, label + 2) + line;
        at = end + 1;
    }
    return first;
}

// `doing` is what failed: "render", "build the shader".
int glFailure(const char* doing, const std::string& error) {
    std::cerr << "cannot " << doing << ": " << firstErrorLine(error) << '\n';
    return kExitNoGl;
}

int flushStdout() {
    if (std::cout.flush()) return kExitOk;
    std::cerr << "marchbox: cannot write to standard output\n";
    return kExitBadInput;
}

static bool parsePost(const std::string& s, PostMode* out) {
    static const char* names[kPostModeCount] = {"none", "fxaa", "fxaa-edges", "fxaa-direction"};
    for (int i = 0; i < kPostModeCount; ++i)
        if (s == names[i]) return *out = PostMode(i), true;
    return false;
}

bool offscreenBackend(const Args& a, OffscreenBackend* out) {
    if (parseBackend(a.backend, out)) return true;
    std::cerr << "unknown backend " << quoteArg(a.backend) << ": expected osmesa or egl\n";
    return false;
}

// --quality: applied to the scene once it is loaded, after the simulation has run.
bool qualityPreset(const Args& a, QualityPreset* out) {
    if (parseQualityPreset(a.quality, out)) return true;
    std::cerr << "unknown quality " << quoteArg(a.quality) << ": expected draft, normal or final\n";
    return false;
}

bool renderOptions(const Args& a, RenderOptions* o) {
    o->uber = a.uber;
    if (!parsePost(a.post, &o->post)) {
        std::cerr << "unknown post pass " << quoteArg(a.post)
                  << ": expected none, fxaa, fxaa-edges or fxaa-direction\n";
        return false;
    }
    if (parseRenderMode(a.mode, &o->mode)) return true;
    std::cerr << "unknown mode " << quoteArg(a.mode)
              << ": expected shaded, normals, depth, steps, ao, shadow or id\n";
    return false;
}

// Large renders and simulations report progress on a terminal; scripts reading stderr see
// only errors.
static void showProgress(const char* doing, double done) {
    std::fprintf(stderr, "\r%s %3d%%%s", doing, int(done * 100.0 + 0.5), done >= 1.0 ? "\n" : "");
}
static bool printRenderProgress(float done, void*) {
    showProgress("rendering", done);
    return true;
}
static void printSimulateProgress(double done) { showProgress("simulating", done); }

// `ok`, with `error` on standard error where it is false. render and simulate check where they
// will write before the work (checkSavePng, checkSaveScene), then the save reports what only the
// write meets (a full disk).
static bool reported(bool ok, const std::string& error) {
    if (!ok) std::cerr << error << '\n';
    return ok;
}

// One thread by default: a second waits for a core wherever other work holds them.
PhysicsSettings physicsSettings(const Args& a) {
    PhysicsSettings settings;
    settings.threads = a.threads;
    return settings;
}

// --frames N is bench's; render's frames are a range, and --fps and --skip-existing go with it.
static bool frameOptionsFit(const Args& a) {
    if (a.frameCount) std::cerr << kFramesNotRange << '\n';
    else if (a.fps || a.skipExisting)
        std::cerr << "--fps and --skip-existing go with --frames A-B\n";
    return !a.frameCount && !a.fps && !a.skipExisting;
}

int runRender(const Args& a) {
    if (a.frameRange) return runRenderFrames(a);
    RenderOptions options;
    QualityPreset preset;
    if (!frameOptionsFit(a) ||
        !needOne(a,
                 "marchbox render SCENE -o OUT.png [--size WxH] [--seconds T] [--uber] [--mode M] "
                 "[--post P] [--quality Q] [--backend B] [--threads N]") ||
        !needOutput(a, "render", "OUT.png") || !renderOptions(a, &options) ||
        !qualityPreset(a, &preset))
        return kExitUsage;
    Scene scene;
    std::string error;
    if (!loadOrReport(a.positional[0], &scene) || !reported(checkSavePng(a.output, &error), error))
        return kExitBadInput;
    if (!hasExtension(a.output, ".png")) {  // PNG bytes in an .mp4 or .stl would pass for one
        std::cerr << "render writes one frame as a PNG: -o must end in .png"
                  << (isVideo(a.output) ? " (a video takes --frames A-B)" : "") << '\n';
        return kExitUsage;
    }
    const double seconds = a.seconds.value_or(0);
    simulate(scene, seconds, physicsSettings(a));
    scene.camera = cameraAt(scene.keyframes, scene.camera, seconds);
    applyQualityPreset(preset, &scene.render, &options);
    Image img;
    OffscreenRun run;
    if (!offscreenBackend(a, &run.backend)) return kExitUsage;
    if (a.width * a.height > 1024 * 1024 && isatty(STDERR_FILENO))
        run.progress = printRenderProgress;
    if (!renderOffscreen(scene, options, a.width, a.height, &img, &error, run))
        return glFailure("render", error);
    return reported(savePng(a.output, img, &error), error) ? kExitOk : kExitBadInput;
}

int runSimulate(const Args& a) {
    if (!needOne(a, "marchbox simulate SCENE --seconds T [-o OUT.txt] [--threads N]"))
        return kExitUsage;
    if (!a.seconds) {  // left out, it would write the scene as it was and look like a result
        std::cerr << "simulate needs --seconds T\n";
        return kExitUsage;
    }
    Scene scene;
    std::string error;
    if (!loadOrReport(a.positional[0], &scene) ||
        (!a.output.empty() && !reported(checkSaveScene(a.output, &error), error)))
        return kExitBadInput;
    // Ctrl-C keeps its default: the process ends at once, before anything is written.
    simulate(scene, a.seconds.value_or(0), physicsSettings(a),
             isatty(STDERR_FILENO) ? printSimulateProgress : nullptr);
    if (a.output.empty()) {
        std::cout << formatScene(scene);
        return flushStdout();
    }
    return reported(saveScene(a.output, scene, &error), error) ? kExitOk : kExitBadInput;
}

// The options alone, before the scene is read: a usage error (exit 2) in one line, or "".
static std::string exportUsageError(const Args& a) {
    MeshFormat format;
    if (!meshFormatOf(a.output, &format))
        return "cannot tell the format of " + quoteArg(a.output) +
               ": -o takes a .stl, .obj, .ply or .glb file";
    if (a.frameCount) return "export --frames takes a range A-B, such as 0-299";
    if (a.frameRange && format != MeshFormat::Glb)
        return "export --frames writes an animated .glb, not " + quoteArg(a.output);
    if (a.frameRange && a.seconds)
        return "--seconds does not go with --frames: frame k shows t = k / fps";
    if (a.fps && !a.frameRange) return "--fps goes with --frames A-B";
    if (a.frameRange && a.frameRange->last / a.fps.value_or(30) > kMaxSeconds)
        return "frame " + std::to_string(a.frameRange->last) + " is past 3600 s at this --fps";
    return "";
}

// Ctrl-C stops the run between steps and blocks, before anything is written; the process then
// ends by the signal.
int runExport(const Args& a) {
    if (!needOne(a,
                 "marchbox export SCENE -o OUT.stl|.obj|.ply|.glb [--voxel S] [--seconds T] "
                 "[--frames A-B [--fps F]]") ||
        !needOutput(a, "export", "OUT.stl, OUT.obj, OUT.ply or OUT.glb"))
        return kExitUsage;
    if (const std::string error = exportUsageError(a); !error.empty()) {
        std::cerr << error << '\n';
        return kExitUsage;
    }
    Scene scene;
    if (!loadOrReport(a.positional[0], &scene)) return kExitBadInput;
    catchInterrupts();
    ExportSettings settings;
    settings.voxel = a.voxel.value_or(0.0);
    settings.seconds = a.seconds.value_or(0.0);
    settings.physics = physicsSettings(a);
    settings.stop = interrupted;
    if (isatty(STDERR_FILENO)) settings.progress = showProgress;
    const ExportResult r =
        a.frameRange ? exportAnimation(
                           scene, a.output,
                           {a.frameRange->first, a.frameRange->last, a.fps.value_or(30)}, settings)
                     : exportScene(scene, a.output, settings);
    if (r.status == ExportResult::Stopped) endInterrupted();
    if (r.status == ExportResult::Failed) std::cerr << r.error << '\n';
    else if (settings.progress)
        std::fprintf(stderr, "%zu triangles at a voxel of %g m\n", r.triangles, r.voxel);
    return r.status == ExportResult::Written ? kExitOk : kExitBadInput;
}

int runCheck(const Args& a) {
    if (a.positional.empty()) {
        std::cerr << "usage: marchbox check SCENE...\n";
        return kExitUsage;
    }
    int status = kExitOk;
    for (const std::string& path : a.positional) {
        Scene scene;
        if (!loadOrReport(path, &scene)) status = kExitBadInput;
    }
    return status;
}

// The uniform-block limit decides where objects live, so ask the driver that render uses.
static int driverUniformBlockBytes() {
    OffscreenContext context;
    std::string error;
    Renderer renderer;
    if (!context.create(1, 1, &error) || !renderer.init(&error)) return 0;
    return renderer.maxUniformBlockBytes();
}

int runShader(const Args& a) {
    RenderOptions options;
    if (!needOne(a, "marchbox shader SCENE [--uber]") || !renderOptions(a, &options))
        return kExitUsage;
    Scene scene;
    if (!loadOrReport(a.positional[0], &scene)) return kExitBadInput;
    ShaderFeatures f = shaderFeatures(scene, options.mode, options.uber, driverUniformBlockBytes());
    std::string source, error;
    if (!fragmentSource(f, &source, &error)) return glFailure("build the shader", error);
    std::cout << source;
    return flushStdout();
}

int runBench(const Args& a) {
    RenderOptions options;
    OffscreenBackend backend;
    QualityPreset preset;
    if (a.frameRange) {
        std::cerr << "bench --frames takes a count N, not a range\n";
        return kExitUsage;
    }
    if (!needOne(a,
                 "marchbox bench SCENE [--uber] [--size WxH] [--frames N] [--quality Q] [--backend "
                 "osmesa|egl]") ||
        !renderOptions(a, &options) || !offscreenBackend(a, &backend) || !qualityPreset(a, &preset))
        return kExitUsage;
    Scene scene;
    if (!loadOrReport(a.positional[0], &scene)) return kExitBadInput;
    applyQualityPreset(preset, &scene.render, &options);
    OffscreenContext context;
    Renderer renderer;
    ColorTarget target;  // EGL has no default framebuffer: draw where both backends can
    std::string error;
    if (!context.create(1, 1, &error, backend) || !renderer.init(&error) ||
        !renderer.setScene(scene, options, &error))
        return glFailure("render", error);
    if (!target.resize(a.width, a.height, GL_RGBA8))
        return glFailure("render", "cannot create the target");
    target.bind();
    std::printf("device: %s, %s\n", context.platform().c_str(),
                reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
    std::vector<double> ms;
    for (int i = 0; i <= a.frameCount.value_or(20); ++i) {  // frame 0 warms up: shader JIT, caches
        auto t0 = std::chrono::steady_clock::now();
        renderer.draw(a.width, a.height);
        glFinish();
        double elapsed =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        if (i > 0) std::printf("frame %d: %.3f ms\n", i, elapsed), ms.push_back(elapsed);
    }
    std::sort(ms.begin(), ms.end());  // an even count's median: the mean of the middle two
    const size_t half = ms.size() / 2;
    std::printf("median_ms: %.3f\n", ms.size() % 2 ? ms[half] : 0.5 * (ms[half - 1] + ms[half]));
    return flushStdout();
}

}  // namespace mb
