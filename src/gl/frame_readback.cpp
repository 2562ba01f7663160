// frame_readback.cpp — the ring of pack buffers behind FrameReadback.
#include "marchbox/gl/frame_readback.h"

#include <algorithm>

namespace mb {

FrameReadback::FrameReadback(int depth) : depth_(std::max(1, depth)), slots_(size_t(depth_)) {}

FrameReadback::~FrameReadback() {
    for (Slot& s : slots_) {
        if (s.fence) glDeleteSync(s.fence);
        if (s.buffer) glDeleteBuffers(1, &s.buffer);
    }
}

bool FrameReadback::start(int frame, int width, int height, std::string* error) {
    if (full()) {  // its oldest slot is still in flight
        *error = "cannot read back frame " + std::to_string(frame) + ": frames in flight not taken";
        return false;
    }
    Slot& s = slots_[size_t(next_)];
    const GLsizeiptr bytes = GLsizeiptr(width) * height * 4;
    if (!s.buffer) glGenBuffers(1, &s.buffer);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, s.buffer);
    if (s.width != width || s.height != height)
        glBufferData(GL_PIXEL_PACK_BUFFER, bytes, nullptr, GL_STREAM_READ);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    if (GLenum e = glGetError()) {
        *error = "cannot read back a " + std::to_string(width) + "x" + std::to_string(height) +
                 " frame (OpenGL error " + std::to_string(e) + ")";
        s.width = s.height = 0;  // the buffer's size is not known now
        return false;
    }
    s.fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    s.frame = frame, s.width = width, s.height = height;
    inFlight_.push_back(next_);
    next_ = (next_ + 1) % depth_;
    return true;
}

bool FrameReadback::take(ReadFrame* out, std::string* error) {
    if (empty()) {
        *error = "no frame in flight to read back";
        return false;
    }
    Slot& s = slots_[size_t(inFlight_.front())];
    inFlight_.pop_front();
    const GLenum waited = glClientWaitSync(s.fence, GL_SYNC_FLUSH_COMMANDS_BIT, GLuint64(-1));
    glDeleteSync(s.fence);
    s.fence = nullptr;
    glBindBuffer(GL_PIXEL_PACK_BUFFER, s.buffer);
    const GLsizeiptr bytes = GLsizeiptr(s.width) * s.height * 4;
    const auto* pixels = waited == GL_WAIT_FAILED
                             ? nullptr
                             : static_cast<const uint8_t*>(glMapBufferRange(
                                   GL_PIXEL_PACK_BUFFER, 0, bytes, GL_MAP_READ_BIT));
    bool whole = pixels != nullptr;
    if (pixels) {
        *out = {s.frame, imageFromBottomUp(pixels, s.width, s.height)};
        whole = glUnmapBuffer(GL_PIXEL_PACK_BUFFER) == GL_TRUE;  // false: the copy was lost
    }
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    if (!whole)
        *error = "cannot read back frame " + std::to_string(s.frame) + " (OpenGL error " +
                 std::to_string(glGetError()) + ")";
    return whole;
}

}  // namespace mb
