// document.cpp — edits, live changes and undo over one scene.
#include "marchbox/editor/document.h"

#include "marchbox/scene/scene_io.h"

#include <filesystem>

namespace mb {

bool sameCamera(const Camera& a, const Camera& b) {
    return a.pos == b.pos && a.target == b.target && a.fov == b.fov;
}

std::string Document::name() const {
    return path_.empty() ? "untitled" : std::filesystem::path(path_).filename().string();
}

void Document::replace(const Scene& scene, const std::string& path) {
    scene_ = scene;
    path_ = path;
    history_.clear();
    saved_ = scene;
    ++version_;
    ++opened_;
}

void Document::markSaved(const std::string& path) {
    path_ = path;
    saved_ = scene_;
    ++version_;
    history_.seal();  // a later drag must not fold into the step that was saved
}

// Compared once per version: while the simulator runs that is once a frame, about 0.2 ms for
// 4096 objects.
bool Document::dirty() const {
    if (checkedVersion_ != version_) {
        saved_.camera = scene_.camera;
        dirty_ = !(saved_ == scene_);
        checkedVersion_ = version_;
    }
    return dirty_;
}

void Document::apply(const std::string& label, const SceneChange& change, uint64_t mergeKey) {
    Scene before = scene_;
    change(scene_);
    ++version_;
    history_.push(label, before, scene_, mergeKey);
}

void Document::commit(const std::string& label, const Scene& before) {
    Scene from = before;
    from.camera = scene_.camera;  // the view moving meanwhile is not part of the step
    history_.push(label, from, scene_);
}

void Document::restore(const Scene& target, bool stepMovedCamera) {
    Camera view = scene_.camera;
    scene_ = target;
    if (!stepMovedCamera) scene_.camera = view;
    ++version_;
}

bool Document::undo(std::string* label) {
    const HistoryStep* s = history_.undo();
    if (!s) return false;
    restore(s->before, !sameCamera(s->before.camera, s->after.camera));
    if (label) *label = s->label;
    return true;
}

bool Document::redo(std::string* label) {
    const HistoryStep* s = history_.redo();
    if (!s) return false;
    restore(s->after, !sameCamera(s->before.camera, s->after.camera));
    if (label) *label = s->label;
    return true;
}

}  // namespace mb
