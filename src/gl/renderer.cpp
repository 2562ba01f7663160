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


static void setCamera(const Program& p, const CameraBasis& b) {
    p.set("uCamPos", b.pos);
    p.set("uCamForward", b.forward);
    p.set("uCamRight", b.right);
    p.set("uCamUp", b.up);
}

void Renderer::uploadGrid(const Scene& scene) {
    ObjectGrid grid = buildObjectGrid(makeSceneSdf(scene));
    gridCells_.upload(grid.cellStart.data(), grid.cellStart.size());
    gridItems_.upload(grid.items.data(), grid.items.size());
    gridCells_.bind(kGridCellsUnit);
    gridItems_.bind(kGridItemsUnit);
    const Program& p = *current_;
    p.set("uGridCells", int(kGridCellsUnit));
    p.set("uGridItems", int(kGridItemsUnit));
    p.set("uGridOrigin", grid.origin);
    p.set("uGridCell", grid.cellSize);
    if (GLint loc = p.uniform("uGridDims"); loc >= 0) glUniform3i(loc, grid.dims.x, grid.dims.y, grid.dims.z);
}

// The colour of the brightest light, scaled so its largest channel is 1: it tints the sky.
static glm::vec3 skyTint(const Scene& scene) {
    glm::vec3 best(1.0f);
    float bestPower = -1.0f;
    for (const Light& l : scene.lights) {
        glm::vec3 c = l.color * l.intensity;
        float power = std::max(c.r, std::max(c.g, c.b));
        if (power > bestPower && power > 0.0f) bestPower = power, best = c / power;
    }
    return best;
}

void Renderer::setUniforms(const Scene& scene, const ShaderFeatures& f, const RenderQuality& q) {
    const Program& p = *current_;
    glUseProgram(p.id());
    CameraBasis basis = cameraBasis(scene.camera);
    setCamera(p, basis);
    tanHalfFov_ = glm::length(basis.up);
    p.set("uEpsilon", scene.render.epsilon);
    p.set("uMaxDist", maxRayDistance(scene));
    p.set("uFloor", scene.world.floor);
    p.set("uFog", scene.render.fog);
    p.set("uSkyTint", skyTint(scene));
    p.set("uSoftness", q.softness);
    bool useGrid = f.grid && (!f.uber || int(scene.objects.size()) > kGridMinObjects);
    if (useGrid) uploadGrid(scene);
    if (!f.uber) return;
    p.set("uUseGrid", int(useGrid));
    GpuScene counts = packScene(scene);
    p.set("uObjectCount", int(scene.objects.size()));
    p.set("uPointLights", counts.pointLights);
    p.set("uDirLights", counts.dirLights);
    p.set("uSteps", scene.render.steps);
    p.set("uShadows", scene.lights.empty() ? 0 : scene.render.shadows);
    p.set("uReflections", scene.render.reflections);
    p.set("uGround", int(scene.world.ground));
    p.set("uAo", int(scene.render.ao));
}

bool operator==(const RenderOptions& a, const RenderOptions& b) {
    const RenderQuality &p = a.quality, &q = b.quality;
    return a.mode == b.mode && a.uber == b.uber && a.post == b.post && a.fog == b.fog &&
           p.relaxPercent == q.relaxPercent && p.coneEpsilon == q.coneEpsilon &&
           p.shadowSteps == q.shadowSteps && p.grid == q.grid && p.softness == q.softness;
}

bool Renderer::setScene(const Scene& original, const RenderOptions& options, std::string* error) {
    Scene fogless;
    if (!options.fog) fogless = original, fogless.render.fog = 0.0f;
    const Scene& scene = options.fog ? original : fogless;
    ShaderFeatures f = shaderFeatures(scene, options.mode, options.uber, maxUniformBlock_, options.quality);
    if (f.uber && int(scene.objects.size()) > f.objects) {
        *error = "the uber shader holds at most " + std::to_string(f.objects) + " objects";
        return false;
    }
    Program* p = programFor(f, error);
    if (!p) return false;
    current_ = p;
    currentFeatures_ = f;
    samples_ = options.mode == RenderMode::ObjectId ? 1 : scene.render.aa;  // ids do not average
    post_ = options.mode == RenderMode::ObjectId ? PostMode::None : options.post;
    upload(scene, f);
    setUniforms(scene, f, options.quality);
    return true;
}

}  // namespace mb
