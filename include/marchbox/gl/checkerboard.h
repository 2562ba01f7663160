// marchbox/gl/checkerboard.h — draft's checkerboard: the march shades half the pixels, in a
// checkerboard, packed into a half-width target (march.frag's CHECKERBOARD), so the driver
// runs half the fragments; this pass fills in the whole picture (shaders/checkerboard.frag).
#pragma once

#include "marchbox/gl/framebuffer.h"
#include "marchbox/gl/screen_quad.h"

#include <memory>
#include <string>

namespace mb {

class CheckerboardFill {
public:
    // Fragment (i, y) of the packed target shades pixel (2i + (y & 1), y).
    static int packedWidth(int width) { return (width + 1) / 2; }

    // Compiles the fill's shader once; false with the log. A frame that would need it asks
    // first, so a broken checkerboard.frag fails the frame instead of leaving it undrawn.
    bool prepare(std::string* error);
    // Draws the width × height picture held in `packed` into the bound framebuffer, the
    // viewport and any scissor as set. Needs prepare() to have succeeded.
    void draw(const ColorTarget& packed, int width, int height, ScreenQuad& quad);

private:
    std::unique_ptr<Program> program_;
};

}  // namespace mb
