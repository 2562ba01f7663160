// scene_view.h — the scene as the window shows it: the raymarching renderer kept in step with
// the editor, its picture refined a step a frame (scene_image.h), the selection highlighted,
// shaders reloaded when they change on disk. A second renderer draws the previews after a
// change at draft quality; the refinement ends at the View menu's quality (normal: the scene's
// own settings).
#pragma once

#include "marchbox/editor/files.h"
#include "marchbox/gl/quality_preset.h"
#include "marchbox/gl/renderer.h"
#include "scene_image.h"

#include <memory>
#include <optional>
#include <string>

namespace mb {

class SceneView {
public:
    SceneView();
    bool init(const Scene& scene, std::string* error);  // needs the window's context current

    // Uploads the scene when its version, the options or the quality changed since the last call.
    void sync(const Scene& scene, uint64_t version, const RenderOptions& options,
              QualityPreset quality, double now);
    // The scene's share of a frame: swaps in a program that finished compiling, then draws the
    // picture's next step if it is of kind `only` (see SceneImage::update); true if it drew.
    bool update(int width, int height, int selectedObject, StepKind only);
    void otherWork(double ms) { image_.otherWork(ms); }  // the rest of the frame took ms
    void show(int width, int height) const { image_.show(width, height); }  // the last picture
    bool done() const { return image_.done() && !renderer_->compiling(); }  // nothing to draw
    const PictureStatus& status() const { return image_.status(); }

    // Twice a second, looks at shaders/; on a change builds a fresh renderer and swaps it in
    // only when the new program compiles and links, so a broken edit keeps the last good one.
    void pollShaders(const Scene& scene, double now);
    const std::string& shaderLog() const { return log_; }  // the last failure, empty when fine
    bool compiling() const {
        return announced_ || renderer_->compilingScene();
    }  // the scene's program is not ready
    const ShaderFeatures* features() const { return renderer_->features(); }  // of the one drawing

private:
    // One change as the two renderers draw it, each request looked at once.
    struct Change {
        SceneRequest full;                  // renderer_'s, at the view's quality
        std::optional<SceneRequest> draft;  // draft_'s previews; none at draft quality
    };
    Change change(const Scene& scene, const RenderOptions& options, QualityPreset quality) const;
    std::optional<SceneRequest> draftRequest(const Scene& scene, const RenderOptions& options,
                                             QualityPreset quality) const;
    bool wouldCompile(const Change& c) const;  // either program would have to be built
    bool reload(const Scene& scene);
    void requestDraft(std::optional<SceneRequest> draft);
    Renderer* draftRenderer() const;  // null when previews draw with renderer_

    std::unique_ptr<Renderer> renderer_;  // at quality_
    std::unique_ptr<Renderer> draft_;     // previews; its failures only leave them to renderer_
    bool draftCurrent_ = false;           // draft_ took the newest scene
    SceneImage image_;
    FolderWatch shaders_;
    RenderOptions options_;
    QualityPreset quality_ = QualityPreset::Normal;
    uint64_t version_ = ~0ull;
    uint64_t content_ = 0;    // grows with each change to what the renderer draws
    int aa_ = 1;              // the scene's samples per axis, as last uploaded
    bool announced_ = false;  // a compile is due: the UI says so for a frame before it starts
    double nextPoll_ = 0.0, retryAt_ = 0.0;
    std::string log_;
};

// Reads the back buffer (after the UI is drawn, before the swap) and writes it as a PNG in
// `folder` under the first free name marchbox-NNNN.png.
bool saveScreenshot(int width, int height, const std::string& folder, std::string* path,
                    std::string* error);

}  // namespace mb
