// renderer.cpp — the full-screen quad, the program cache and the scene's uniforms.
#include "marchbox/gl/renderer.h"

#include "marchbox/camera.h"
#include "marchbox/gl/gpu_scene.h"
#include "marchbox/gl/offscreen_context.h"
#include "marchbox/object_grid.h"
#include "marchbox/sdf.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace mb {

enum BindingPoint : GLuint { kObjectsBinding = 0, kMaterialsBinding = 1, kLightsBinding = 2 };
enum TextureUnit : GLuint { kGridCellsUnit = 0, kGridItemsUnit = 1 };

bool Renderer::init(std::string* error) {
    const float corners[] = {-1, -1, 1, -1, 1, 1, -1, 1};
    const unsigned indices[] = {0, 1, 2, 0, 2, 3};
    quad_.bind();
    quadVertices_.upload(corners, sizeof corners);
    quadIndices_.upload(indices, sizeof indices);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    glGetIntegerv(GL_MAX_UNIFORM_BLOCK_SIZE, &maxUniformBlock_);
    if (GLenum e = glGetError()) {
        *error = "OpenGL error " + std::to_string(e) + " while building the screen quad";
        return false;
    }
    return true;
}

Program* Renderer::programFor(const ShaderFeatures& f, std::string* error) {
    for (Cached& c : cache_)
        if (c.features == f) return c.program.get();
    std::string source;
    if (!fragmentSource(f, &source, error)) return nullptr;
    Shader vs, fs;
    if (!vs.compileFile(GL_VERTEX_SHADER, shaderDir() + "/fullscreen.vert")) {
        *error = "vertex shader: " + vs.log();
        return nullptr;
    }
    if (!fs.compile(GL_FRAGMENT_SHADER, source)) {
        *error = "fragment shader: " + fs.log();
        return nullptr;
    }
    auto program = std::make_unique<Program>();
    if (!program->link(vs, fs)) {
        *error = "link: " + program->log();
        return nullptr;
    }
    program->bindBlock("Objects", kObjectsBinding);
    program->bindBlock("Materials", kMaterialsBinding);
    program->bindBlock("Lights", kLightsBinding);
    GLuint store = glGetProgramResourceIndex ? glGetProgramResourceIndex(program->id(), GL_SHADER_STORAGE_BLOCK, "ObjectStore") : GL_INVALID_INDEX;
    if (store != GL_INVALID_INDEX) glShaderStorageBlockBinding(program->id(), store, kObjectsBinding);
    cache_.push_back({f, std::move(program)});
    return cache_.back().program.get();
}

// Uniform arrays are sized to their capacity in the shader, so the upload is padded to it.
template <typename T>
static void uploadPadded(UniformBuffer& ub, const std::vector<T>& items, int capacity, GLuint point) {
    std::vector<T> padded(size_t(std::max(1, capacity)), T{});
    std::copy_n(items.begin(), std::min(items.size(), padded.size()), padded.begin());
    ub.upload(padded.data(), padded.size() * sizeof(T), GL_DYNAMIC_DRAW);
    ub.bindBase(point);
}

void Renderer::upload(const Scene& scene, const ShaderFeatures& f) {
    GpuScene g = packScene(scene);
    if (f.objectsInStorage) {
        objectStore_.upload(g.objects.data(), g.objects.size() * sizeof(GpuObject), GL_DYNAMIC_DRAW);
        objectStore_.bindBase(kObjectsBinding);
    } else {
        uploadPadded(objects_, g.objects, f.objects, kObjectsBinding);
    }
    uploadPadded(materials_, g.materials, f.materials, kMaterialsBinding);
    uploadPadded(lights_, g.lights, f.pointLights + f.dirLights, kLightsBinding);
}

static void setUniform(const Program& p, const char* name, glm::vec3 v) {
    if (GLint loc = p.uniform(name); loc >= 0) glUniform3f(loc, v.x, v.y, v.z);
}
static void setUniform(const Program& p, const char* name, float v) {
    if (GLint loc = p.uniform(name); loc >= 0) glUniform1f(loc, v);
}
static void setUniform(const Program& p, const char* name, int v) {
    if (GLint loc = p.uniform(name); loc >= 0) glUniform1i(loc, v);
}

static void setCamera(const Program& p, const CameraBasis& b) {
    setUniform(p, "uCamPos", b.pos);
    setUniform(p, "uCamForward", b.forward);
    setUniform(p, "uCamRight", b.right);
    setUniform(p, "uCamUp", b.up);
}

void Renderer::uploadGrid(const Scene& scene) {
    ObjectGrid grid = buildObjectGrid(makeSceneSdf(scene));
    gridCells_.upload(grid.cellStart.data(), grid.cellStart.size());
    gridItems_.upload(grid.items.data(), grid.items.size());
    gridCells_.bind(kGridCellsUnit);
    gridItems_.bind(kGridItemsUnit);
    const Program& p = *current_;
    setUniform(p, "uGridCells", int(kGridCellsUnit));
    setUniform(p, "uGridItems", int(kGridItemsUnit));
    setUniform(p, "uGridOrigin", grid.origin);
    setUniform(p, "uGridCell", grid.cellSize);
    if (GLint loc = p.uniform("uGridDims"); loc >= 0) glUniform3i(loc, grid.dims.x, grid.dims.y, grid.dims.z);
}

void Renderer::setUniforms(const Scene& scene, const ShaderFeatures& f) {
    const Program& p = *current_;
    glUseProgram(p.id());
    CameraBasis basis = cameraBasis(scene.camera);
    setCamera(p, basis);
    tanHalfFov_ = glm::length(basis.up);
    setUniform(p, "uEpsilon", scene.render.epsilon);
    setUniform(p, "uMaxDist", maxRayDistance(scene));
    setUniform(p, "uFloor", scene.world.floor);
    setUniform(p, "uFog", scene.render.fog);
    bool useGrid = f.grid && (!f.uber || int(scene.objects.size()) > kGridMinObjects);
    if (useGrid) uploadGrid(scene);
    if (!f.uber) return;
    setUniform(p, "uUseGrid", int(useGrid));
    GpuScene counts = packScene(scene);
    setUniform(p, "uObjectCount", int(scene.objects.size()));
    setUniform(p, "uPointLights", counts.pointLights);
    setUniform(p, "uDirLights", counts.dirLights);
    setUniform(p, "uSteps", scene.render.steps);
    setUniform(p, "uShadows", scene.lights.empty() ? 0 : scene.render.shadows);
    setUniform(p, "uReflections", scene.render.reflections);
    setUniform(p, "uAA", f.mode == RenderMode::ObjectId ? 1 : scene.render.aa);
    setUniform(p, "uGround", int(scene.world.ground));
    setUniform(p, "uAo", int(scene.render.ao));
}

bool Renderer::setScene(const Scene& scene, const RenderOptions& options, std::string* error) {
    ShaderFeatures f = shaderFeatures(scene, options.mode, options.uber, maxUniformBlock_, options.quality);
    if (f.uber && int(scene.objects.size()) > f.objects) {
        *error = "the uber shader holds at most " + std::to_string(f.objects) + " objects";
        return false;
    }
    Program* p = programFor(f, error);
    if (!p) return false;
    current_ = p;
    currentFeatures_ = f;
    upload(scene, f);
    setUniforms(scene, f);
    return true;
}

void Renderer::draw(int x, int y, int w, int h, int fullW, int fullH) {
    if (!current_ || w <= 0 || h <= 0) return;
    glUseProgram(current_->id());
    if (GLint loc = current_->uniform("uViewport"); loc >= 0) glUniform4f(loc, float(x), float(y), float(fullW), float(fullH));
    // Half a pixel's footprint per metre of distance: the cone epsilon's slope.
    setUniform(*current_, "uPixelRadius", tanHalfFov_ / float(fullH));
    glViewport(0, 0, w, h);
    quad_.bind();
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_INT, nullptr);
}

bool renderOffscreen(const Scene& scene, const RenderOptions& options, int width, int height,
                     Image* out, std::string* error) {
    OffscreenContext context;
    if (!context.create(width, height, error)) return false;
    Renderer renderer;
    if (!renderer.init(error) || !renderer.setScene(scene, options, error)) return false;
    renderer.draw(width, height);
    Image img = makeImage(width, height);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glFinish();
    for (int row = 0; row < height; ++row)  // GL's row 0 is the bottom
        glReadPixels(0, height - 1 - row, width, 1, GL_RGBA, GL_UNSIGNED_BYTE, img.pixel(0, row));
    if (GLenum e = glGetError()) {
        *error = "OpenGL error " + std::to_string(e) + " while rendering";
        return false;
    }
    *out = std::move(img);
    return true;
}

}  // namespace mb
