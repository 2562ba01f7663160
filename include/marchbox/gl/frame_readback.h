// marchbox/gl/frame_readback.h — finished frames copied back to memory through a ring of
// pixel-buffer objects, so that the GPU draws the next frame while the last one travels.
//
// glReadPixels into client memory stalls until the GPU has drawn everything before it and then
// copies while the GPU waits. Into a pack buffer it only queues the copy: the frame is fetched
// (mapped) a few frames later, when it is long finished. On llvmpipe the copy is a memcpy
// either way. On a GPU the copy runs beside the next frame's first tile, since TiledRender
// waits for each tile (glFinish) to report progress; what that buys there is not measured.
#pragma once

#include "marchbox/gl/gl.h"
#include "marchbox/gl/image.h"

#include <deque>
#include <string>
#include <vector>

namespace mb {

struct ReadFrame {
    int frame = 0;
    Image image;  // row 0 at the top
};

class FrameReadback {
public:
    explicit FrameReadback(int depth = 3);  // frames in flight at the most
    ~FrameReadback();                       // the context that made it must be current
    FrameReadback(const FrameReadback&) = delete;
    FrameReadback& operator=(const FrameReadback&) = delete;

    // Queues a copy of the bound framebuffer's bottom-left width × height pixels, as frame
    // `frame`; false with *error where the ring is full() or the driver has no room for it.
    bool start(int frame, int width, int height, std::string* error);
    bool full() const { return int(inFlight_.size()) == depth_; }
    bool empty() const { return inFlight_.empty(); }
    // The oldest frame started, once its copy has arrived; frames come out in the order they
    // went in. False with *error where the ring is empty() or the copy cannot be read.
    bool take(ReadFrame* out, std::string* error);

private:
    struct Slot {
        GLuint buffer = 0;
        GLsync fence = nullptr;
        int frame = 0, width = 0, height = 0;
    };
    int depth_;
    std::vector<Slot> slots_;
    std::deque<int> inFlight_;  // indices into slots_, oldest first
    int next_ = 0;              // the slot the next start fills
};

}  // namespace mb
