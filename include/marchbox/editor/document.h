// marchbox/editor/document.h — the open scene, its file, its undo history and whether it is saved.
//
// Unsaved means saving would change what the file says, the camera aside: the camera is written
// with the scene, but looking around is not an edit. Undoing back to the file, or a simulation
// Reset to it, leaves nothing unsaved.
#pragma once

#include "marchbox/editor/history.h"
#include "marchbox/scene/scene.h"

#include <cstdint>
#include <functional>
#include <string>

namespace mb {

using SceneChange = std::function<void(Scene&)>;

class Document {
public:
    const Scene& scene() const { return scene_; }
    const std::string& path() const { return path_; }  // empty for a scene never saved
    std::string name() const;  // the file's name without its folder, "untitled" without one
    bool dirty() const;        // the scene differs from its file (from New's scene), camera aside
    const History& history() const { return history_; }

    // New or Open: a fresh history, clean.
    void replace(const Scene& scene, const std::string& path);
    void markSaved(const std::string& path);

    // The one door for edits: runs `change` on the scene and records the difference as one
    // undo step (see History::push for mergeKey).
    void apply(const std::string& label, const SceneChange& change, uint64_t mergeKey = 0);
    void seal() { history_.seal(); }

    // Changes kept out of the history: the view moving, the simulator running. commit() later
    // records everything that changed since `before` as one step.
    Scene& live() {
        ++version_;
        return scene_;
    }
    void commit(const std::string& label, const Scene& before);

    // Both keep the current camera unless the step itself changed the camera: looking around
    // is not an edit, and undoing an edit must not throw the view back.
    bool undo(std::string* label = nullptr);
    bool redo(std::string* label = nullptr);

    // Grows whenever the scene may have changed, for whoever mirrors it (the GPU upload).
    uint64_t version() const { return version_; }
    // Grows at each replace() (New, Open): what was said about the last scene goes with it.
    uint64_t opened() const { return opened_; }

private:
    void restore(const Scene& target, bool stepMovedCamera);

    Scene scene_;
    std::string path_;
    History history_;
    mutable Scene saved_;  // as the file holds it; its camera follows scene_'s
    mutable uint64_t checkedVersion_ = ~uint64_t(0);
    mutable bool dirty_ = false;  // as of checkedVersion_
    uint64_t version_ = 0;
    uint64_t opened_ = 0;
};

bool sameCamera(const Camera& a, const Camera& b);

}  // namespace mb
