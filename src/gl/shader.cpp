// shader.cpp — compiling, linking and the #include preprocessor for shaders/.
#include "marchbox/gl/shader.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

namespace mb {

std::string shaderDir() {
    const char* env = std::getenv("MARCHBOX_SHADERS");
    return env && *env ? env : MARCHBOX_SHADER_DIR;
}

// A file under the working folder is named from there, as a person would type it
// (`shaders/lighting.glsl:42`); anything else keeps the path it was opened by.
static std::string displayPath(const std::string& path) {
    std::error_code ec;
    const std::filesystem::path cwd = std::filesystem::current_path(ec);
    if (ec || !std::filesystem::path(path).is_absolute()) return path;
    const std::filesystem::path rel = std::filesystem::path(path).lexically_relative(cwd);
    return rel.empty() || *rel.begin() == ".." ? path : rel.string();
}

static bool expandIncludes(const std::string& path, std::set<std::string>* seen, std::string* out,
                           LineMap* lines, std::string* error) {
    std::ifstream in(path);
    if (!in) {
        *error = "cannot read shader '" + path + "'";
        return false;
    }
    seen->insert(path);
    const std::string shown = displayPath(path);
    std::string line;
    const std::string directive = "#include \"";
    for (int lineNo = 1; std::getline(in, line); ++lineNo) {
        if (line.compare(0, directive.size(), directive) != 0) {
            *out += line + "\n";
            lines->push_back({shown, lineNo});
            continue;
        }
        std::string name =
            line.substr(directive.size(), line.find('"', directive.size()) - directive.size());
        std::string inc = shaderDir() + "/" + name;
        if (!seen->count(inc) && !expandIncludes(inc, seen, out, lines, error)) return false;
    }
    return true;
}

bool readShaderSource(const std::string& path, std::string* out, LineMap* lines,
                      std::string* error) {
    std::set<std::string> seen;
    out->clear();
    lines->clear();
    return expandIncludes(path, &seen, out, lines, error);
}

Shader::~Shader() {
    if (id_) glDeleteShader(id_);
}
Shader::Shader(Shader&& o) noexcept
    : id_(std::exchange(o.id_, 0)), log_(std::move(o.log_)), lines_(std::move(o.lines_)) {}
Shader& Shader::operator=(Shader&& o) noexcept {
    std::swap(id_, o.id_);
    std::swap(log_, o.log_);
    std::swap(lines_, o.lines_);
    return *this;
}

static std::string infoLog(GLuint id, bool program) {
    GLint len = 0;
    program ? glGetProgramiv(id, GL_INFO_LOG_LENGTH, &len)
            : glGetShaderiv(id, GL_INFO_LOG_LENGTH, &len);
    std::vector<char> buf(size_t(len > 0 ? len : 1), '\0');
    program ? glGetProgramInfoLog(id, len, nullptr, buf.data())
            : glGetShaderInfoLog(id, len, nullptr, buf.data());
    return buf.data();
}

bool Shader::compile(GLenum type, const std::string& source, LineMap lines) {
    start(type, source, std::move(lines));
    return finish();
}

void Shader::start(GLenum type, const std::string& source, LineMap lines) {
    lines_ = std::move(lines);
    if (!id_) id_ = glCreateShader(type);
    const char* src = source.c_str();
    glShaderSource(id_, 1, &src, nullptr);
    glCompileShader(id_);
}

bool Shader::finish() {
    GLint ok = 0;
    glGetShaderiv(id_, GL_COMPILE_STATUS, &ok);
    log_ = rewriteShaderLog(infoLog(id_, false), lines_);
    return ok == GL_TRUE;
}

bool Shader::compileFile(GLenum type, const std::string& path, const std::string& prefix) {
    std::string body;
    LineMap lines;
    if (!readShaderSource(path, &body, &lines, &log_)) return false;
    return compile(type, prefix + body, withPrefix(prefix, lines));
}

Program::~Program() {
    if (!id_) return;
    // A program deleted while in use lives on until unbound, and whoever saved it as the one in
    // use (ImGui's backend does, around its draw) puts back a name that then no longer exists:
    // GL_INVALID_VALUE, which the next check reports as this context's failure.
    GLint current = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    if (GLuint(current) == id_) glUseProgram(0);
    glDeleteProgram(id_);
}
Program::Program(Program&& o) noexcept
    : id_(std::exchange(o.id_, 0)), log_(std::move(o.log_)), uniforms_(std::move(o.uniforms_)) {}
Program& Program::operator=(Program&& o) noexcept {
    std::swap(id_, o.id_);
    std::swap(log_, o.log_);
    std::swap(uniforms_, o.uniforms_);
    return *this;
}

bool Program::link(const Shader& vertex, const Shader& fragment) {
    startLink(vertex, fragment);
    return finishLink();
}

void Program::startLink(const Shader& vertex, const Shader& fragment) {
    if (!id_) id_ = glCreateProgram();
    glAttachShader(id_, vertex.id());
    glAttachShader(id_, fragment.id());
    glLinkProgram(id_);
    glDetachShader(id_, vertex.id());
    glDetachShader(id_, fragment.id());
}

// With GL_KHR_parallel_shader_compile the driver compiles and links on its own threads; asking
// for the status before GL_COMPLETION_STATUS_KHR says so would wait for it.
bool Program::linkDone() const {
    if (!GLEW_KHR_parallel_shader_compile) return true;
    GLint done = GL_TRUE;
    glGetProgramiv(id_, GL_COMPLETION_STATUS_KHR, &done);
    return done == GL_TRUE;
}

bool Program::finishLink() {
    GLint ok = 0;
    glGetProgramiv(id_, GL_LINK_STATUS, &ok);
    log_ = infoLog(id_, true);
    uniforms_.clear();
    if (ok != GL_TRUE) return false;
    GLint count = 0;
    glGetProgramiv(id_, GL_ACTIVE_UNIFORMS, &count);
    for (GLint i = 0; i < count; ++i) {
        char name[256];
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(id_, GLuint(i), sizeof name, nullptr, &size, &type, name);
        GLint loc = glGetUniformLocation(id_, name);
        if (loc >= 0) uniforms_[name] = loc;
    }
    return true;
}

GLint Program::uniform(const char* name) const {
    auto it = uniforms_.find(name);
    return it == uniforms_.end() ? -1 : it->second;
}

void Program::set(const char* name, int v) const {
    if (GLint loc = uniform(name); loc >= 0) glUniform1i(loc, v);
}
void Program::set(const char* name, float v) const {
    if (GLint loc = uniform(name); loc >= 0) glUniform1f(loc, v);
}
void Program::set(const char* name, glm::vec2 v) const {
    if (GLint loc = uniform(name); loc >= 0) glUniform2f(loc, v.x, v.y);
}
void Program::set(const char* name, glm::vec3 v) const {
    if (GLint loc = uniform(name); loc >= 0) glUniform3f(loc, v.x, v.y, v.z);
}

void Program::bindBlock(const char* blockName, GLuint bindingPoint) const {
    GLuint index = glGetUniformBlockIndex(id_, blockName);
    if (index != GL_INVALID_INDEX) glUniformBlockBinding(id_, index, bindingPoint);
}

}  // namespace mb
