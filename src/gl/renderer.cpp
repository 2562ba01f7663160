// renderer.cpp — a scene's program and data: builds and caches a program per feature set (in
// the background for requestScene, with the uber program standing in), then uploads the
// scene's buffers, grid and uniforms for it. Drawing is render_passes.cpp's.
#include "marchbox/gl/renderer.h"

#include "marchbox/scene/camera.h"
#include "marchbox/gl/gpu_scene.h"
#include "marchbox/gl/offscreen_context.h"
#include "marchbox/gl/plain_members.h"
#include "marchbox/scene/object_grid.h"
#include "marchbox/scene/sdf.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace mb {

enum BindingPoint : GLuint {
    kObjectsBinding = 0,
    kMaterialsBinding = 1,
    kLightsBinding = 2,
    kGroupsBinding = 3
};
// Unit 2 is the passes' (render_passes.cpp, checkerboard.cpp).
enum TextureUnit : GLuint {
    kGridCellsUnit = 0,
    kGridItemsUnit = 1,
    kPlainCellsUnit = 3,
    kPlainItemsUnit = 4,
    kPlainShapesUnit = 5
};

bool Renderer::init(std::string* error) {
    if (!quad_.init(error)) return false;
    glGetIntegerv(GL_MAX_UNIFORM_BLOCK_SIZE, &maxUniformBlock_);
    return true;
}

Renderer::Cached* Renderer::cached(const ShaderFeatures& f) {
    for (Cached& c : cache_)
        if (c.features == f) return &c;
    return nullptr;
}

bool Renderer::startBuild(const ShaderFeatures& f, Build* b, std::string* error) {
    std::string source;
    LineMap fragmentLines, vertexLines;
    if (!fragmentSource(f, &source, error, &fragmentLines) ||
        !readShaderSource(shaderDir() + "/fullscreen.vert", &b->vertexSource, &vertexLines, error))
        return false;
    b->features = f;
    b->vs.start(GL_VERTEX_SHADER, b->vertexSource, std::move(vertexLines));
    b->fs.start(GL_FRAGMENT_SHADER, source, std::move(fragmentLines));
    b->program = std::make_unique<Program>();
    b->program->startLink(b->vs, b->fs);
    return true;
}

Program* Renderer::finishBuild(Build* b, std::string* error) {
    if (!b->vs.finish()) return *error = "vertex shader: " + b->vs.log(), nullptr;
    if (!b->fs.finish()) return *error = "fragment shader: " + b->fs.log(), nullptr;
    if (!b->program->finishLink()) return *error = "link: " + b->program->log(), nullptr;
    Program& p = *b->program;
    p.bindBlock("Objects", kObjectsBinding);
    p.bindBlock("Materials", kMaterialsBinding);
    p.bindBlock("Lights", kLightsBinding);
    p.bindBlock("Groups", kGroupsBinding);
    using Store = std::pair<const char*, GLuint>;
    for (auto [name, point] :
         {Store{"ObjectStore", kObjectsBinding}, Store{"GroupStore", kGroupsBinding}}) {
        GLuint store = glGetProgramResourceIndex
                           ? glGetProgramResourceIndex(p.id(), GL_SHADER_STORAGE_BLOCK, name)
                           : GL_INVALID_INDEX;
        if (store != GL_INVALID_INDEX) glShaderStorageBlockBinding(p.id(), store, point);
    }
    cache_.push_back({b->features, std::move(b->program)});
    return cache_.back().program.get();
}

Program* Renderer::programFor(const ShaderFeatures& f, std::string* error) {
    if (Cached* c = cached(f)) return c->program.get();
    Build b;
    return startBuild(f, &b, error) ? finishBuild(&b, error) : nullptr;
}

// Uniform arrays are sized to their capacity in the shader, so the upload is padded to it.
template <typename T>
static void uploadPadded(UniformBuffer& ub, const std::vector<T>& items, int capacity,
                         GLuint point) {
    std::vector<T> padded(size_t(std::max(1, capacity)), T{});
    std::copy_n(items.begin(), std::min(items.size(), padded.size()), padded.begin());
    ub.upload(padded.data(), padded.size() * sizeof(T), GL_DYNAMIC_DRAW);
    ub.bindBase(point);
}

void Renderer::upload(const GpuScene& g, const ShaderFeatures& f) {
    objectsInStorage_ = f.objectsInStorage;
    if (f.objectsInStorage) {
        objectStore_.upload(g.objects.data(), g.objects.size() * sizeof(GpuObject),
                            GL_DYNAMIC_DRAW);
        objectStore_.bindBase(kObjectsBinding);
        if (f.groups > 0) {
            groupStore_.upload(g.groups.data(), g.groups.size() * sizeof(GpuGroup),
                               GL_DYNAMIC_DRAW);
            groupStore_.bindBase(kGroupsBinding);
        }
    } else {
        uploadPadded(objects_, g.objects, f.objects, kObjectsBinding);
        if (f.groups > 0) uploadPadded(groups_, g.groups, f.groups, kGroupsBinding);
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

// One of the shader's grids, its uniforms named `prefix` + Cells, Items, Origin, Cell, Dims. An
// upload binds its texture to the active unit: rebind() puts every texture back afterwards.
static void uploadGridTo(const Program& p, const ObjectGrid& grid, const std::string& prefix,
                         TextureBuffer* cells, TextureBuffer* items, GLuint cellsUnit,
                         GLuint itemsUnit) {
    cells->upload(grid.cellStart.data(), grid.cellStart.size());
    items->upload(grid.items.data(), grid.items.size());
    p.set((prefix + "Cells").c_str(), int(cellsUnit));
    p.set((prefix + "Items").c_str(), int(itemsUnit));
    p.set((prefix + "Origin").c_str(), grid.origin);
    p.set((prefix + "Cell").c_str(), grid.cellSize);
    if (GLint loc = p.uniform((prefix + "Dims").c_str()); loc >= 0)
        glUniform3i(loc, grid.dims.x, grid.dims.y, grid.dims.z);
}

void Renderer::uploadGrid(const SceneSdf& sdf) {
    uploadGridTo(*current_, buildObjectGrid(sdf), "uGrid", &gridCells_, &gridItems_, kGridCellsUnit,
                 kGridItemsUnit);
}

void Renderer::uploadPlainGrid(const SceneSdf& sdf, const std::vector<bool>& plain) {
    PlainGrid g = buildPlainGrid(sdf, plain);
    uploadGridTo(*current_, g.grid, "uPlain", &plainCells_, &plainItems_, kPlainCellsUnit,
                 kPlainItemsUnit);
    plainShapes_.upload(g.shapes.data(), g.shapes.size());
    current_->set("uPlainShapes", int(kPlainShapesUnit));
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

void Renderer::setUniforms(const Scene& scene, const GpuScene& g, const ShaderFeatures& f,
                           const RenderQuality& q) {
    const Program& p = *current_;
    glUseProgram(p.id());
    CameraBasis basis = cameraBasis(scene.camera);
    setCamera(p, basis);
    tanHalfFov_ = glm::length(basis.up);
    p.set("uEpsilon", scene.render.epsilon);
    p.set("uMaxDist", maxRayDistance(scene));
    // Once per update: the bounds and the grids read it, members placed in the world. Only a
    // flat chain reaches the grid (shaderFeatures), whose cells list world objects.
    SceneSdf sdf = makeSceneSdf(scene);
    Box bounds = objectBounds(sdf);
    p.set("uBoundLo", bounds.lo);
    p.set("uBoundHi", bounds.hi);
    std::vector<bool> plain(sdf.objects.size(), false);
    if (f.plain) plain = plainMembers(scene);
    Box rest = membersBounds(sdf, plain, false), members = membersBounds(sdf, plain, true);
    p.set("uRestLo", rest.lo);
    p.set("uRestHi", rest.hi);
    p.set("uPlainLo", members.lo);
    p.set("uPlainHi", members.hi);
    if (f.plain == 2) uploadPlainGrid(sdf, plain);
    p.set("uFloor", scene.world.floor);
    p.set("uFog", scene.render.fog);
    p.set("uSkyTint", skyTint(scene));
    p.set("uSoftness", q.softness);
    bool useGrid = f.grid && usesGrid(scene, q);  // the uber shader has the grid code, maybe unused
    if (useGrid) uploadGrid(sdf);
    rebind();
    if (!f.uber) return;
    p.set("uUseGrid", int(useGrid));
    p.set("uObjectCount", int(scene.objects.size()));
    p.set("uPointLights", g.pointLights);
    p.set("uDirLights", g.dirLights);
    p.set("uSteps", scene.render.steps);
    p.set("uShadows", shadowKind(scene));
    p.set("uReflections", scene.render.reflections);
    p.set("uGround", int(scene.world.ground));
    p.set("uAo", int(scene.render.ao));
}

bool SceneRequest::fits(const ShaderFeatures& f) const {
    return !f.uber || int(scene.objects.size()) <= f.objects;
}

ShaderFeatures Renderer::featuresFor(const Scene& scene, const RenderOptions& options) const {
    ShaderFeatures f =
        shaderFeatures(scene, options.mode, options.uber, maxUniformBlock_, options.quality);
    f.outline = options.outline && options.mode == RenderMode::Shaded;
    return f;
}

// The editor's F key hides fog without touching the file's value.
SceneRequest Renderer::requestFor(Scene scene, const RenderOptions& options) const {
    if (!options.fog) scene.render.fog = 0.0f;
    RenderOptions uber = options;
    uber.uber = true;
    ShaderFeatures features = featuresFor(scene, options), standIn = featuresFor(scene, uber);
    return {std::move(scene), options, std::move(features), std::move(standIn)};
}

static bool fitsOrSays(const SceneRequest& r, std::string* error) {
    if (r.fits(r.features)) return true;
    *error = "the uber shader holds at most " + std::to_string(r.features.objects) + " objects";
    return false;
}

void Renderer::use(Program* p, const ShaderFeatures& f, const SceneRequest& r) {
    current_ = p;
    const bool ids = r.options.mode == RenderMode::ObjectId;
    samples_ = ids ? 1 : r.scene.render.aa;  // ids do not average
    post_ = ids ? PostMode::None : r.options.post;
    checkerboard_ = f.checkerboard;
    GpuScene g = packScene(r.scene);
    upload(g, f);
    setUniforms(r.scene, g, f, r.options.quality);
}

bool Renderer::setScene(const SceneRequest& request, std::string* error) {
    if (!fitsOrSays(request, error)) return false;
    Program* p = programFor(request.features, error);
    if (!p) return false;
    use(p, request.features, request);
    return true;
}

bool Renderer::requestScene(SceneRequest request, std::string* error) {
    if (!fitsOrSays(request, error)) return false;
    const ShaderFeatures& f = request.features;
    if (Cached* c = cached(f)) {
        pending_.reset();
        use(c->program.get(), f, request);
        return true;
    }
    if (failed_ && failed_->features == f) {  // a running simulation asks every frame
        *error = failed_->log;
        return false;
    }
    if (!pending_ || !(pending_->features == f)) {
        auto build = std::make_unique<Build>();
        if (!startBuild(f, build.get(), error)) return false;
        pending_ = std::move(build);
    }
    // Meanwhile the uber program, if it is built, draws the new scene; else the old program
    // keeps drawing the old one.
    if (request.fits(request.standIn))
        if (Cached* c = cached(request.standIn)) use(c->program.get(), request.standIn, request);
    pending_->request = std::move(request);
    return true;
}

bool Renderer::poll(std::string* error) {
    if (uberBuild_ && uberBuild_->program->linkDone()) {
        std::string ignored;  // a broken uber shader only means no stand-in
        finishBuild(uberBuild_.get(), &ignored);
        uberBuild_.reset();
    }
    if (!pending_ || !pending_->program->linkDone()) return true;
    std::unique_ptr<Build> b = std::move(pending_);
    Program* p = finishBuild(b.get(), error);
    if (!p) {
        failed_ = Failure{b->features, *error};
        return false;
    }
    use(p, b->features, b->request);
    return true;
}

bool Renderer::wouldCompile(const SceneRequest& request) const {
    if (!request.fits(request.features)) return false;
    auto same = [&](const auto& held) { return held.features == request.features; };
    return std::none_of(cache_.begin(), cache_.end(), same) && !(pending_ && same(*pending_)) &&
           !(failed_ && same(*failed_));
}

void Renderer::prepareUber(const SceneRequest& request) {
    const ShaderFeatures& u = request.standIn;
    // A scene the uber shader cannot draw stands in for itself: nothing to build but its own.
    if (!u.uber || uberBuild_ || !request.fits(u) || cached(u)) return;
    auto build = std::make_unique<Build>();
    std::string ignored;
    if (startBuild(u, build.get(), &ignored)) uberBuild_ = std::move(build);
}

const ShaderFeatures* Renderer::features() const {
    for (const Cached& c : cache_)
        if (c.program.get() == current_) return &c.features;
    return nullptr;
}

void Renderer::rebind() const {
    if (objectsInStorage_) {
        objectStore_.bindBase(kObjectsBinding);
        groupStore_.bindBase(kGroupsBinding);
    } else {
        objects_.bindBase(kObjectsBinding);
        groups_.bindBase(kGroupsBinding);
    }
    materials_.bindBase(kMaterialsBinding);
    lights_.bindBase(kLightsBinding);
    gridCells_.bind(kGridCellsUnit);
    gridItems_.bind(kGridItemsUnit);
    plainCells_.bind(kPlainCellsUnit);
    plainItems_.bind(kPlainItemsUnit);
    plainShapes_.bind(kPlainShapesUnit);
}

}  // namespace mb
