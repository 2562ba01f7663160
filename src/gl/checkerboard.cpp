// checkerboard.cpp — the pass that fills in a checkerboard-shaded picture.
#include "marchbox/gl/checkerboard.h"

namespace mb {

enum : GLuint { kPackedUnit = 2 };  // units 0 and 1 hold the object grid

bool CheckerboardFill::prepare(std::string* error) {
    if (!program_) program_ = screenProgram("checkerboard.frag", "#version 330 core\n", error);
    return program_ != nullptr;
}

void CheckerboardFill::draw(const ColorTarget& packed, int width, int height, ScreenQuad& quad) {
    glUseProgram(program_->id());
    packed.bindTexture(kPackedUnit);
    program_->set("uHalf", int(kPackedUnit));
    if (GLint loc = program_->uniform("uSize"); loc >= 0) glUniform2i(loc, width, height);
    quad.draw();
}

}  // namespace mb
