// marchbox/gl/shader.h — RAII, move-only owners of one shader or program object each.
#pragma once

#include "marchbox/gl/gl.h"
#include "marchbox/gl/shader_lines.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <unordered_map>

namespace mb {

// Reads a GLSL file and replaces each `#include "name"` line with the file shaders/name,
// recursively (each file once), and gives each line's origin. Errors say which file could not
// be read.
bool readShaderSource(const std::string& path, std::string* out, LineMap* lines,
                      std::string* error);

// Where shaders/ is: $MARCHBOX_SHADERS if set, else the source tree's shaders/.
std::string shaderDir();

class Shader {
public:
    Shader() = default;
    ~Shader();
    Shader(Shader&& o) noexcept;
    Shader& operator=(Shader&& o) noexcept;
    Shader(const Shader&) = delete;
    Shader& operator=(const Shader&) = delete;

    // The log names lines by `lines`, the origin of each line of `source`, where it has one.
    bool compile(GLenum type, const std::string& source,
                 LineMap lines = {});  // keeps the log either way
    void start(GLenum type, const std::string& source,
               LineMap lines = {});  // compile without waiting
    bool finish();                   // wait, keep the log, say if it built
    bool compileFile(GLenum type, const std::string& path, const std::string& prefix = "");

    GLuint id() const { return id_; }
    const std::string& log() const { return log_; }

private:
    GLuint id_ = 0;
    std::string log_;
    LineMap lines_;
};

class Program {
public:
    Program() = default;
    ~Program();
    Program(Program&& o) noexcept;
    Program& operator=(Program&& o) noexcept;
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;

    // Links, keeps the log, and caches every active uniform's location.
    bool link(const Shader& vertex, const Shader& fragment);
    void startLink(const Shader& vertex, const Shader& fragment);  // the shaders may be compiling
    bool linkDone() const;  // true once finishLink() would not wait
    bool finishLink();

    GLuint id() const { return id_; }
    const std::string& log() const { return log_; }
    GLint uniform(const char* name) const;  // -1 if inactive; no GL call
    // Set a uniform of the program in use; names the linker dropped are ignored.
    void set(const char* name, int v) const;
    void set(const char* name, float v) const;
    void set(const char* name, glm::vec2 v) const;
    void set(const char* name, glm::vec3 v) const;
    void bindBlock(const char* blockName, GLuint bindingPoint) const;

private:
    GLuint id_ = 0;
    std::string log_;
    std::unordered_map<std::string, GLint> uniforms_;
};

}  // namespace mb
