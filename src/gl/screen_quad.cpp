// screen_quad.cpp — the full-screen quad and its programs.
#include "marchbox/gl/screen_quad.h"

namespace mb {

bool ScreenQuad::init(std::string* error) {
    const float corners[] = {-1, -1, 1, -1, 1, 1, -1, 1};
    const unsigned indices[] = {0, 1, 2, 0, 2, 3};
    vao_.bind();
    vertices_.upload(corners, sizeof corners);
    indices_.upload(indices, sizeof indices);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    if (GLenum e = glGetError()) {
        *error = "OpenGL error " + std::to_string(e) + " while building the screen quad";
        return false;
    }
    return true;
}

void ScreenQuad::draw() {
    vao_.bind();
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_INT, nullptr);
}

std::unique_ptr<Program> screenProgram(const std::string& fragment, const std::string& prefix,
                                       std::string* error) {
    Shader vs, fs;
    if (!vs.compileFile(GL_VERTEX_SHADER, shaderDir() + "/fullscreen.vert") ||
        !fs.compileFile(GL_FRAGMENT_SHADER, shaderDir() + "/" + fragment, prefix)) {
        *error = fragment + ": " + fs.log() + vs.log();
        return nullptr;
    }
    auto program = std::make_unique<Program>();
    if (!program->link(vs, fs)) {
        *error = fragment + " link: " + program->log();
        return nullptr;
    }
    return program;
}

}  // namespace mb
