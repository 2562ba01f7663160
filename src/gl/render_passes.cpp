// render_passes.cpp — one frame: supersample passes, accumulation, the post pass, tiles.
#include "marchbox/gl/renderer.h"

#include "marchbox/gl/offscreen_context.h"

#include <algorithm>

namespace mb {

enum : GLuint { kAccumUnit = 2 };  // units 0 and 1 hold the object grid

const Program* Renderer::postProgram(PostMode mode, std::string* error) {
    std::unique_ptr<Program>& slot = postPrograms_[int(mode)];
    if (!slot)
        slot = screenProgram(
            "post.frag", "#version 330 core\n#define POST_MODE " + std::to_string(int(mode)) + "\n",
            error);
    return slot.get();
}

bool Renderer::beginFrame(int width, int height, bool accumulate, std::string* error) {
    frameWidth_ = width;
    frameHeight_ = height;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &frameTarget_);
    frameCheckerboard_ = checkerboard_;
    frameSamples_ = samples_;
    framePost_ = post_;
    accumulating_ =
        accumulate || frameSamples_ > 1 || framePost_ != PostMode::None || frameCheckerboard_;
    if (!accumulating_) return true;
    // One sample a pixel, drawn whole (draw()), is written over the target, not added: no clear,
    // no blend, and 8 bits hold the checkerboard's half, which the fill fetches for 40% less
    // than half floats (480x270, one llvmpipe thread: 0.84 against 1.42 ms).
    blending_ = accumulate || frameSamples_ > 1;
    const int marchWidth = frameCheckerboard_ ? CheckerboardFill::packedWidth(width) : width;
    const GLenum packedFormat = blending_ ? GL_RGBA16F : GL_RGBA8;
    if (!accum_.resize(width, height) ||
        (frameCheckerboard_ && !packed_.resize(marchWidth, height, packedFormat)) ||
        !postProgram(framePost_, error) || (frameCheckerboard_ && !fill_.prepare(error))) {
        if (error->empty())
            *error = "cannot create a " + std::to_string(width) + "x" + std::to_string(height) +
                     " float target";
        accumulating_ = false;
        return false;
    }
    marchTarget().bind();
    glViewport(0, 0, marchWidth, height);
    if (blending_) {
        glClearColor(0, 0, 0, 0);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    return true;
}

void Renderer::resumeFrame() {
    if (accumulating_) marchTarget().bind();
}

// With the checkerboard, packed column i holds pixels 2i and 2i + 1 (one of them per row).
void Renderer::marchViewport(int x, int y, int w, int h) {
    if (frameCheckerboard_) {
        glViewport(0, 0, CheckerboardFill::packedWidth(frameWidth_), frameHeight_);
        w = CheckerboardFill::packedWidth(x + w) - x / 2;
        x /= 2;
    } else {
        glViewport(0, 0, frameWidth_, frameHeight_);
    }
    glEnable(GL_SCISSOR_TEST);
    glScissor(x, y, w, h);
}

// A pixel spans 2·tan(fov/2)/height per metre along a primary ray, and each of its n×n samples
// stands for 1/n of that across: the floor's checkers are averaged over the sample's share.
void Renderer::setPixelUniforms(const Program& p) const {
    const float pixelRadius = tanHalfFov_ / float(frameHeight_);
    p.set("uResolution", glm::vec2(frameWidth_, frameHeight_));
    p.set("uPixelRadius", pixelRadius);
    p.set("uSampleRadius", pixelRadius / float(frameSamples_));
}

void Renderer::drawRegion(int x, int y, int w, int h) {
    if (!current_ || w <= 0 || h <= 0) return;
    const Program& p = *current_;
    glUseProgram(p.id());
    setPixelUniforms(p);
    p.set("uSampleWeight", 1.0f / float(frameSamples_ * frameSamples_));
    marchViewport(x, y, w, h);
    if (accumulating_ && blending_) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE);
    }
    const int n = frameSamples_;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            p.set("uSubpixel", glm::vec2((i + 0.5f) / float(n), (j + 0.5f) / float(n)));
            quad_.draw();
        }
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
}

void Renderer::endFrame(const ColorTarget* into) {
    if (!accumulating_) return;
    resolve(into);
    accumulating_ = false;
}

void Renderer::resolve(const ColorTarget* into) {
    std::string error;
    auto bindInto = [&] {
        into ? into->bind() : glBindFramebuffer(GL_FRAMEBUFFER, GLuint(frameTarget_));
    };
    glViewport(0, 0, frameWidth_, frameHeight_);
    if (frameCheckerboard_) {  // without a post pass the filled-in picture is the result
        framePost_ == PostMode::None ? bindInto() : accum_.bind();
        fill_.draw(packed_, frameWidth_, frameHeight_, quad_);
        if (framePost_ == PostMode::None) return;
    }
    const Program* post = postProgram(framePost_, &error);
    bindInto();
    glUseProgram(post->id());
    accum_.bindTexture(kAccumUnit);
    post->set("uImage", int(kAccumUnit));
    quad_.draw();
}

void Renderer::drawSample(int x, int y, int w, int h, glm::vec2 subpixel, float weight) {
    if (!current_ || !accumulating_ || w <= 0 || h <= 0) return;
    const Program& p = *current_;
    glUseProgram(p.id());
    setPixelUniforms(p);
    p.set("uSampleWeight", 1.0f);  // the blend below weighs the sample
    p.set("uSubpixel", subpixel);
    marchViewport(x, y, w, h);
    glEnable(GL_BLEND);
    glBlendColor(0.0f, 0.0f, 0.0f, weight);
    glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
    quad_.draw();
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
}

// With the checkerboard the seed is squeezed to half width: a stand-in, like the image itself.
void Renderer::seedFrame(const ColorTarget& image) {
    if (accumulating_) image.blitTo(&marchTarget(), marchTarget().width(), frameHeight_, GL_LINEAR);
}

void Renderer::resolveFrame(const ColorTarget& into, int x, int y, int w, int h) {
    if (!accumulating_) return;
    // post.frag's FXAA reads up to FXAA_SPAN_MAX / 2 + 1 = 5 pixels away, so a changed band
    // changes the picture that far around it; 8 leaves room for a wider span. A pixel the
    // checkerboard fills in reads its neighbours, one further.
    const int reach = (framePost_ == PostMode::None ? 0 : 8) + int(frameCheckerboard_);
    glEnable(GL_SCISSOR_TEST);
    glScissor(x - reach, y - reach, w + 2 * reach, h + 2 * reach);
    resolve(&into);
    glDisable(GL_SCISSOR_TEST);
}

void Renderer::draw(int width, int height) {
    std::string error;
    beginFrame(width, height, false, &error);
    drawRegion(0, 0, width, height);
    endFrame();
}

// One read of the whole picture, not one per row: on a GPU each read waits for the drawing.
Image readFramebuffer(int width, int height) {
    std::vector<uint8_t> bottomUp(size_t(width) * size_t(height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    return imageFromBottomUp(bottomUp.data(), width, height);
}

// Tiles start at even x: a checkerboard's packed column holds two pixels (Renderer::drawRegion).
TiledRender::TiledRender(Renderer& renderer, int width, int height, int tileSize)
    : renderer_(renderer),
      width_(width),
      height_(height),
      tile_(std::max(16, tileSize) & ~1),
      tilesX_((width + tile_ - 1) / tile_),
      tilesY_((height + tile_ - 1) / tile_) {}

// Tiles may interleave with other drawing (the editor's window): each call leaves the
// framebuffer that was bound as it found it.
class FramebufferGuard {
public:
    FramebufferGuard() { glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous_); }
    ~FramebufferGuard() { glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previous_)); }

private:
    GLint previous_ = 0;
};

bool TiledRender::start(std::string* error) {
    FramebufferGuard guard;
    if (!result_.resize(width_, height_, GL_RGBA8)) {
        *error = "cannot create a " + std::to_string(width_) + "x" + std::to_string(height_) +
                 " image target";
        return false;
    }
    return renderer_.beginFrame(width_, height_, true, error);
}

void TiledRender::step() {
    if (done()) return;
    FramebufferGuard guard;
    renderer_.resumeFrame();
    int x = (next_ % tilesX_) * tile_, y = (next_ / tilesX_) * tile_;
    renderer_.drawRegion(x, y, std::min(tile_, width_ - x), std::min(tile_, height_ - y));
    glFinish();  // one tile at a time: the driver never holds a whole large frame
    ++next_;
}

Image TiledRender::finish() {
    FramebufferGuard guard;
    renderer_.endFrame(&result_);
    return readFramebuffer(width_, height_);
}

bool TiledRender::finish(FrameReadback& ring, int frame, std::string* error) {
    FramebufferGuard guard;
    renderer_.endFrame(&result_);
    return ring.start(frame, width_, height_, error);
}

namespace {

// Sets the scene and draws every tile, asking run.progress between them.
bool drawTiles(TiledRender& tiles, const Scene& scene, const RenderOptions& options,
               Renderer& renderer, std::string* error, const OffscreenRun& run) {
    if (!renderer.setScene(scene, options, error) || !tiles.start(error)) return false;
    while (!tiles.done()) {
        tiles.step();
        if (run.progress && !run.progress(tiles.progress(), run.user)) {
            *error = "cancelled";
            return false;
        }
    }
    return true;
}

bool noGlError(std::string* error) {
    const GLenum e = glGetError();
    if (e != GL_NO_ERROR) *error = "OpenGL error " + std::to_string(e) + " while rendering";
    return e == GL_NO_ERROR;
}

}  // namespace

bool renderFrame(Renderer& renderer, const Scene& scene, const RenderOptions& options, int width,
                 int height, Image* out, std::string* error, const OffscreenRun& run) {
    TiledRender tiles(renderer, width, height);
    if (!drawTiles(tiles, scene, options, renderer, error, run)) return false;
    Image img = tiles.finish();
    if (!noGlError(error)) return false;
    *out = std::move(img);
    return true;
}

bool renderFrame(Renderer& renderer, const Scene& scene, const RenderOptions& options, int width,
                 int height, FrameReadback& ring, int frame, std::string* error,
                 const OffscreenRun& run) {
    TiledRender tiles(renderer, width, height);
    return drawTiles(tiles, scene, options, renderer, error, run) && noGlError(error) &&
           tiles.finish(ring, frame, error);
}

bool renderOffscreen(const Scene& scene, const RenderOptions& options, int width, int height,
                     Image* out, std::string* error, const OffscreenRun& run) {
    OffscreenContext context;
    if (!context.create(1, 1, error, run.backend))
        return false;  // pixels go to the renderer's targets
    Renderer renderer;
    return renderer.init(error) &&
           renderFrame(renderer, scene, options, width, height, out, error, run);
}

}  // namespace mb
