// marchbox/gl/renderer.h — draws a scene with its raymarching shader into the current context.
#pragma once

#include "marchbox/gl/buffers.h"
#include "marchbox/gl/checkerboard.h"
#include "marchbox/gl/frame_readback.h"
#include "marchbox/gl/framebuffer.h"
#include "marchbox/gl/gpu_scene.h"
#include "marchbox/gl/offscreen_context.h"
#include "marchbox/gl/screen_quad.h"
#include "marchbox/gl/shader.h"
#include "marchbox/gl/shader_source.h"
#include "marchbox/gl/image.h"
#include "marchbox/scene/scene.h"
#include "marchbox/scene/sdf.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mb {

// What the post pass does after the supersamples are added up.
enum class PostMode : int { None = 0, Fxaa = 1, FxaaEdges = 2, FxaaDirection = 3 };
constexpr int kPostModeCount = 4;

struct RenderOptions {
    RenderMode mode = RenderMode::Shaded;
    bool uber = false;  // the general shader with every feature behind uniforms
    RenderQuality quality;
    PostMode post = PostMode::None;
    bool fog = true;  // false draws the scene's fog as 0 (the editor's F key); the file keeps it
    // The editor's selection ring (uHighlight). Off, the shader leaves it out: it costs a
    // frame 8% though nothing is selected, and renders of files select nothing.
    bool outline = false;

    bool operator==(const RenderOptions&) const = default;
};

// A scene as a renderer draws it, looked at once (Renderer::requestFor): the options' fog switch
// applied, and the feature sets, object layout included, of the program that draws it and of
// the uber program that stands in while that one compiles. Every way to a program starts here,
// so a change is copied and examined once, however many questions are asked of it.
struct SceneRequest {
    Scene scene;  // as drawn: fog 0 where options.fog is off
    RenderOptions options;
    ShaderFeatures features;  // the program's
    ShaderFeatures standIn;   // the uber program's

    // Whether a program of features f holds every object: the uber shader's array is capped.
    bool fits(const ShaderFeatures& f) const;
};

class Renderer {
public:
    // Needs a current context with GL loaded. Builds the quad and reads the driver's limits.
    bool init(std::string* error);

    // The scene and options as this renderer would draw them (its uniform-block limit decides
    // where objects go): a copy of the scene, with the feature sets worked out.
    SceneRequest requestFor(Scene scene, const RenderOptions& options) const;

    // Picks (compiling on first use) the request's program and uploads its scene. On a compile
    // or link failure the previous program stays in use and *error holds the log.
    bool setScene(const SceneRequest& request, std::string* error);
    bool setScene(const Scene& scene, const RenderOptions& options, std::string* error) {
        return setScene(requestFor(scene, options), error);
    }

    // The same without waiting for a compile: a program not yet built starts compiling (on the
    // driver's threads where it offers GL_KHR_parallel_shader_compile) and the uber program, if
    // built, draws the scene meanwhile; else the old program keeps drawing the old scene.
    // poll() swaps the new program in once linked; false with the log if it failed.
    bool requestScene(SceneRequest request, std::string* error);
    bool poll(std::string* error);
    bool compiling() const { return pending_ || uberBuild_; }  // poll() has work left
    bool compilingScene() const {
        return pending_ != nullptr;
    }  // the scene's own program is on its way
    // True when requestScene would start building a program: none is built or on its way for
    // the request's features (a driver without background compiles then blocks).
    bool wouldCompile(const SceneRequest& request) const;
    void prepareUber(const SceneRequest& request);  // builds the stand-in

    // Draws the whole width × height image, every supersample, into the framebuffer bound now.
    void draw(int width, int height);

    // A frame in pieces (tiles of a large render). beginFrame remembers the bound framebuffer;
    // with `accumulate`, or when the scene supersamples, post-processes or shades a checkerboard
    // (RenderQuality::checkerboard), the samples go to a float target first and endFrame
    // resolves them into `into` (or the remembered framebuffer). Without `accumulate`, one
    // sample a pixel is written over the target, not added: draw every pixel of such a frame.
    bool beginFrame(int width, int height, bool accumulate, std::string* error);
    void resumeFrame();                           // binds the frame's target again
    void drawRegion(int x, int y, int w, int h);  // pixels from the bottom-left corner; x even
    void endFrame(const ColorTarget* into = nullptr);

    // A frame refined while it is shown (the editor's view), after beginFrame with `accumulate`.
    // drawSample adds one sample of each pixel in the region, at `subpixel` inside it, as a
    // running mean: target·(1 − weight) + sample·weight; with weight 1/k for a pixel's k-th
    // sample the target holds the mean of its samples whenever it is resolved. seedFrame fills
    // the target with `image` scaled to the frame: what shows until a pixel's first sample
    // (weight 1) replaces it. resolveFrame runs the post pass into `into` for the region (and
    // FXAA's reach around it) and keeps the frame open for more samples.
    void drawSample(int x, int y, int w, int h, glm::vec2 subpixel, float weight);
    void seedFrame(const ColorTarget& image);
    void resolveFrame(const ColorTarget& into, int x, int y, int w, int h);

    // Binds this renderer's scene buffers and grid textures to their binding points again:
    // another Renderer in the same context (File > Render...'s) binds its own to the same ones.
    void rebind() const;

    const Program* program() const { return current_; }
    const ShaderFeatures* features() const;  // what the program drawing now was built for
    int maxUniformBlockBytes() const { return maxUniformBlock_; }

private:
    struct Cached {
        ShaderFeatures features;
        std::unique_ptr<Program> program;
    };
    struct Build {  // a program on its way: shaders compiling, link started
        ShaderFeatures features;
        std::string vertexSource;
        Shader vs, fs;
        std::unique_ptr<Program> program;
        SceneRequest request;  // what the scene's own program draws once it links
    };
    Cached* cached(const ShaderFeatures& f);
    bool startBuild(const ShaderFeatures& f, Build* b, std::string* error);
    Program* finishBuild(Build* b, std::string* error);
    Program* programFor(const ShaderFeatures& f, std::string* error);
    ShaderFeatures featuresFor(const Scene& scene, const RenderOptions& options) const;
    void use(Program* p, const ShaderFeatures& f, const SceneRequest& request);
    void upload(const GpuScene& g, const ShaderFeatures& f);
    void setUniforms(const Scene& scene, const GpuScene& g, const ShaderFeatures& f,
                     const RenderQuality& q);
    void uploadGrid(const SceneSdf& sdf);
    void uploadPlainGrid(const SceneSdf& sdf, const std::vector<bool>& plain);
    const Program* postProgram(PostMode mode, std::string* error);
    ColorTarget& marchTarget() { return frameCheckerboard_ ? packed_ : accum_; }
    void setPixelUniforms(const Program& p) const;   // resolution and footprints, per frame
    void marchViewport(int x, int y, int w, int h);  // and the scissor, for the region in pixels
    // The post pass: accum_ (filled in from packed_ first, with the checkerboard) into `into`
    // or frameTarget_.
    void resolve(const ColorTarget* into);

    std::vector<Cached> cache_;
    std::unique_ptr<Build> pending_, uberBuild_;
    struct Failure {
        ShaderFeatures features;
        std::string log;
    };
    std::optional<Failure> failed_;  // not built again until the shaders reload
    Program* current_ = nullptr;
    ScreenQuad quad_;
    UniformBuffer objects_, materials_, lights_, groups_;
    StorageBuffer objectStore_, groupStore_;
    bool objectsInStorage_ = false;  // which of the two holds the objects (rebind)
    TextureBuffer gridCells_, gridItems_;
    TextureBuffer plainCells_, plainItems_, plainShapes_;  // the plain members' grid
    int maxUniformBlock_ = 16384;
    float tanHalfFov_ = 0.0f;
    int samples_ = 1;  // supersamples per axis
    PostMode post_ = PostMode::None;
    std::unique_ptr<Program> postPrograms_[kPostModeCount];
    ColorTarget accum_;
    bool checkerboard_ = false;  // the program shades half the pixels into packed_
    ColorTarget packed_;
    CheckerboardFill fill_;
    int frameWidth_ = 0, frameHeight_ = 0;
    GLint frameTarget_ = 0;  // the framebuffer bound at beginFrame
    // Latched by beginFrame: a setScene before endFrame changes neither the frame's layout, nor
    // its samples, nor how it is resolved.
    bool frameCheckerboard_ = false;
    int frameSamples_ = 1;
    PostMode framePost_ = PostMode::None;
    bool accumulating_ = false;
    bool blending_ = false;  // samples add up in the march target; else one is written
};

// Reads the bound framebuffer's bottom-left width × height pixels into an image, top row first.
Image readFramebuffer(int width, int height);

// A large image drawn a tile at a time, so no single draw stalls the driver and the caller can
// show progress and cancel between tiles. Leaves the framebuffer that was bound alone.
class TiledRender {
public:
    TiledRender(Renderer& renderer, int width, int height, int tileSize = 256);
    bool start(std::string* error);
    bool done() const { return next_ >= tileCount(); }
    void step();  // draws the next tile
    float progress() const { return tileCount() ? float(next_) / float(tileCount()) : 1.0f; }
    Image finish();  // resolves and reads back; row 0 at the top
    // Resolves and queues the copy back in `ring` (not full) as frame `frame`.
    bool finish(FrameReadback& ring, int frame, std::string* error);

private:
    int tileCount() const { return tilesX_ * tilesY_; }
    Renderer& renderer_;
    int width_, height_, tile_, tilesX_, tilesY_, next_ = 0;
    ColorTarget result_;
};

// Called between tiles with the fraction done; returning false cancels the render.
using RenderProgress = bool (*)(float done, void* user);

struct OffscreenRun {
    OffscreenBackend backend = OffscreenBackend::OsMesa;
    RenderProgress progress = nullptr;
    void* user = nullptr;
};

// Renders one width × height frame of `scene` with `renderer` (its context current) in tiles and
// reads it back. A renderer that drew other scenes before draws the same bytes as a new one, so
// a sequence of frames keeps one renderer and its compiled program.
bool renderFrame(Renderer& renderer, const Scene& scene, const RenderOptions& options, int width,
                 int height, Image* out, std::string* error, const OffscreenRun& run = {});

// renderFrame, with the frame queued in `ring` as frame `frame` instead of read back at once:
// frames of a sequence travel back while the next ones are drawn.
bool renderFrame(Renderer& renderer, const Scene& scene, const RenderOptions& options, int width,
                 int height, FrameReadback& ring, int frame, std::string* error,
                 const OffscreenRun& run = {});

// Creates an off-screen context, renders one width × height frame in tiles and reads it back.
bool renderOffscreen(const Scene& scene, const RenderOptions& options, int width, int height,
                     Image* out, std::string* error, const OffscreenRun& run = {});

}  // namespace mb
