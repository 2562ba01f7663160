// scene_view.cpp — renderer upkeep for the window: uploads, the picture, hot reload, screenshots.
#include "scene_view.h"

#include "marchbox/editor/events.h"
#include "marchbox/gl/shader.h"
#include "marchbox/gl/image.h"

#include <cstdio>
#include <filesystem>

namespace mb {

SceneView::SceneView() : shaders_(shaderDir()) {}

namespace {

std::unique_ptr<Renderer> newRenderer(std::string* error) {
    auto r = std::make_unique<Renderer>();
    return r->init(error) ? std::move(r) : nullptr;
}

// The scene and options at a quality preset, as `renderer` would draw them.
SceneRequest requestAt(const Renderer& renderer, Scene scene, RenderOptions options,
                       QualityPreset quality) {
    applyQualityPreset(quality, &scene.render, &options);
    return renderer.requestFor(std::move(scene), options);
}

}  // namespace

std::optional<SceneRequest> SceneView::draftRequest(const Scene& scene,
                                                    const RenderOptions& options,
                                                    QualityPreset quality) const {
    // Previews come from draft_ unless the view is at draft quality already.
    if (!draft_ || quality == QualityPreset::Draft) return std::nullopt;
    return requestAt(*draft_, scene, options, QualityPreset::Draft);
}

SceneView::Change SceneView::change(const Scene& scene, const RenderOptions& options,
                                    QualityPreset quality) const {
    return {requestAt(*renderer_, scene, options, quality), draftRequest(scene, options, quality)};
}

bool SceneView::init(const Scene& scene, std::string* error) {
    renderer_ = newRenderer(error);
    if (!renderer_) return false;
    std::string ignored;
    draft_ = newRenderer(&ignored);
    Change c = change(scene, options_, quality_);
    // A scene whose shader fails still opens: the log window says why.
    if (!renderer_->setScene(c.full, &log_)) emitEvent("shader-error");
    renderer_->prepareUber(c.full);  // the stand-in while later edits compile
    aa_ = c.full.scene.render.aa;
    requestDraft(std::move(c.draft));
    return true;
}

// Compiles on the driver's threads like the scene's own program; until it is built, or where
// it fails, renderer_ draws the previews.
void SceneView::requestDraft(std::optional<SceneRequest> draft) {
    if (!draft) return;
    std::string ignored;
    draftCurrent_ = draft_->requestScene(std::move(*draft), &ignored);
}

bool SceneView::wouldCompile(const Change& c) const {
    return renderer_->wouldCompile(c.full) || (c.draft && draft_->wouldCompile(*c.draft));
}

Renderer* SceneView::draftRenderer() const {
    bool ready = draft_ && draftCurrent_ && !draft_->compiling() && draft_->program();
    return ready && quality_ != QualityPreset::Draft ? draft_.get() : nullptr;
}

void SceneView::sync(const Scene& scene, uint64_t version, const RenderOptions& options,
                     QualityPreset quality, double now) {
    const bool sameView = options == options_ && quality == quality_;
    if (version == version_ && sameView) return;
    // After a failure, a scene that changes every frame (a running simulation) would recompile
    // the broken shader every frame: try again at most once a second.
    if (now < retryAt_ && sameView) return;
    Change c = change(scene, options, quality);
    // A driver without background compiles blocks while it builds, the draft program too: the
    // UI draws its note first.
    if (!announced_ && wouldCompile(c)) {
        announced_ = true;
        return;
    }
    announced_ = false;
    options_ = options;
    quality_ = quality;
    version_ = version;
    requestDraft(std::move(c.draft));
    const int aa = c.full.scene.render.aa;
    std::string error;
    if (renderer_->requestScene(std::move(c.full), &error)) {
        aa_ = aa;
        ++content_;
        return;
    }
    log_ = error;
    retryAt_ = now + 1.0;
    emitEvent("shader-error");
}

bool SceneView::update(int width, int height, int selectedObject, StepKind only) {
    std::string error;
    const Program* before = renderer_->program();
    if (!renderer_->poll(&error)) {
        log_ = error;
        emitEvent("shader-error");
    }
    if (renderer_->program() != before) ++content_;  // the scene's own program took over
    if (draft_ && !draft_->poll(&error)) draftCurrent_ = false;
    PictureKey key{
        content_, selectedObject, width, height, aa_, options_.mode != RenderMode::ObjectId};
    return image_.update(*renderer_, draftRenderer(), key, only);
}

void SceneView::pollShaders(const Scene& scene, double now) {
    if (now < nextPoll_) return;
    nextPoll_ = now + 0.5;
    if (shaders_.changed()) reload(scene);
}

bool SceneView::reload(const Scene& scene) {
    auto fresh = std::make_unique<Renderer>();
    std::string error;
    if (fresh->init(&error) &&
        fresh->setScene(requestAt(*fresh, scene, options_, quality_), &error)) {
        renderer_ = std::move(fresh);
        std::string ignored;
        draft_ = newRenderer(&ignored);  // the old one's program has the old shaders
        requestDraft(draftRequest(scene, options_, quality_));
        ++content_;
        log_.clear();
        retryAt_ = 0.0;
        emitEvent("shaders reloaded");
        return true;
    }
    log_ = error;
    version_ = ~0ull;  // the fresh renderer may have rebound buffers: upload the old one again
    emitEvent("shader-error");
    return false;
}

static std::string freeScreenshotName(const std::string& folder) {
    namespace fs = std::filesystem;
    for (int i = 1;; ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "marchbox-%04d.png", i);
        fs::path p = fs::path(folder) / name;
        std::error_code ec;
        if (!fs::exists(p, ec)) return p.string();
    }
}

bool saveScreenshot(int width, int height, const std::string& folder, std::string* path,
                    std::string* error) {
    if (width <= 0 || height <= 0) {
        *error = "nothing to capture: the window has no area";
        return false;
    }
    Image img = readFramebuffer(width, height);
    for (size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;  // the window is opaque
    *path = freeScreenshotName(folder);
    return savePng(*path, img, error);
}

}  // namespace mb
