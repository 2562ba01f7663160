// marchbox/gl/screen_quad.h — the quad over the whole viewport, and the programs drawn on it.
#pragma once

#include "marchbox/gl/buffers.h"
#include "marchbox/gl/shader.h"

#include <memory>
#include <string>

namespace mb {

class ScreenQuad {
public:
    bool init(std::string* error);  // needs a current context with GL loaded
    void draw();                    // its two triangles, over the viewport

private:
    VertexArray vao_;
    VertexBuffer vertices_;
    IndexBuffer indices_;
};

// shaders/fullscreen.vert and shaders/<fragment> behind `prefix` (the #version line first);
// null with the log in *error.
std::unique_ptr<Program> screenProgram(const std::string& fragment, const std::string& prefix,
                                       std::string* error);

}  // namespace mb
