// marchbox/gl/framebuffer.h — an off-screen colour target: one framebuffer owning one texture.
#pragma once

#include "marchbox/gl/gl.h"

#include <utility>

namespace mb {

// An RGBA target: half floats to accumulate supersamples in, or 8 bits to read a result from.
class ColorTarget {
public:
    ColorTarget() = default;
    ~ColorTarget() { release(); }
    ColorTarget(ColorTarget&& o) noexcept
        : fbo_(std::exchange(o.fbo_, 0)),
          texture_(std::exchange(o.texture_, 0)),
          width_(o.width_),
          height_(o.height_),
          format_(o.format_) {}
    ColorTarget& operator=(ColorTarget&& o) noexcept {
        std::swap(fbo_, o.fbo_);
        std::swap(texture_, o.texture_);
        std::swap(width_, o.width_);
        std::swap(height_, o.height_);
        std::swap(format_, o.format_);
        return *this;
    }
    ColorTarget(const ColorTarget&) = delete;
    ColorTarget& operator=(const ColorTarget&) = delete;

    // (Re)allocates when the size or format changes; false if the driver rejects the target.
    bool resize(int width, int height, GLenum internalFormat = GL_RGBA16F);
    void bind() const { glBindFramebuffer(GL_FRAMEBUFFER, fbo_); }
    GLuint framebuffer() const { return fbo_; }
    void bindTexture(GLuint unit) const {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_2D, texture_);
    }
    int width() const { return width_; }
    int height() const { return height_; }
    // Copies the whole image, scaled with `filter` (GL_NEAREST, GL_LINEAR), over the bottom-left
    // width × height pixels of `to`, or of the window's framebuffer when `to` is null; leaves
    // that framebuffer bound. The scissor test, if enabled, clips it.
    void blitTo(const ColorTarget* to, int width, int height, GLenum filter) const;

private:
    void release();
    GLuint fbo_ = 0, texture_ = 0;
    int width_ = 0, height_ = 0;
    GLenum format_ = 0;
};

}  // namespace mb
