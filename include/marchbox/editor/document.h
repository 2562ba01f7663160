// marchbox/editor/document.h — the open scene, its file, its undo history and whether it is saved.
//
// Unsaved means saving would change what the file says, the camera aside: the camera is written
// with the scene, but looking around is not an edit. Undoing back to the file, or a simulation
// Reset to it, leaves nothing unsaved.
//
// The scene as edited is the state at t = 0, its start. While the simulator has moved the
// bodies (time() > 0) the scene shows them where they got to and the start is kept aside:
// Save writes the start, and only keep() makes the shown poses the new start. The run is a
// chain of pieces (marchbox/editor/frame_cache.h), one more for each edit of the bodies or the
// world made at t > 0. Each undo state remembers its time, start and run, so undoing a run
// goes back to the time before it.
#pragma once

#include "marchbox/editor/frame_cache.h"
#include "marchbox/editor/history.h"
#include "marchbox/scene/scene.h"

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>

namespace mb {

using SceneChange = std::function<void(Scene&)>;

class Document {
public:
    const Scene& scene() const { return scene_; }
    const std::string& path() const { return path_; }  // empty for a scene never saved
    std::string name() const;  // the file's name without its folder, "untitled" without one
    bool dirty() const;        // the start differs from its file (from New's scene), camera aside
    const History& history() const { return history_; }

    // New or Open: a fresh history, clean.
    void replace(const Scene& scene, const std::string& path);
    void markSaved(const std::string& path);
    // The file changed on disk and `disk` is what it holds now: the start, as one undo step
    // (undo takes the edits back), with nothing unsaved. The run goes; the view stays where it
    // looks unless the file moved the camera.
    void reload(const Scene& disk);

    // The one door for edits: runs `change` on the scene and records the difference as one
    // undo step (see History::push for mergeKey). At t > 0 the change is made at that time and
    // the time stays: one that leaves the objects alone (camera, world, materials, lights) is
    // made to the start too, so Save keeps it; one of the objects is an event of the run, from
    // t on, and the start stays. A change of the objects or the world begins a run piece at t.
    void apply(const std::string& label, const SceneChange& change, uint64_t mergeKey = 0);
    void seal() { history_.seal(); }

    // Changes kept out of the history: the view moving, the simulator running. commit() later
    // records everything that changed since `before` as one step.
    Scene& live() {
        ++version_;
        return scene_;
    }
    void commit(const std::string& label, const Scene& before);

    // The simulator's door: the scene to write the bodies into after `seconds` more of motion.
    // The first motion from t = 0 sets the start aside; motion from a time before the run's
    // last edit drops that edit from the run: what follows is simulated anew.
    Scene& moving(double seconds);
    double time() const { return time_; }   // simulated seconds the scene shows; 0 at the start
    Scene start() const;                    // the scene at t = 0, with the current camera
    bool rewind(const std::string& label);  // back to the start, as an undo step; false at t = 0
    bool keep(const std::string& label);    // the shown poses become the start, as an undo step
    // The simulator's door for playing baked frames back: the scene at `frame` (null: t = 0,
    // the start), outside the history like moving(). The start and the run stay.
    void show(const BakedFrame* frame);
    // show() as an undo step, so that a scrub back can go forward again; one drag of the
    // timeline (one mergeKey) is one. False when nothing has run.
    bool seek(const std::string& label, const BakedFrame* frame, uint64_t mergeKey);
    // The run the shown scene is part of; null when nothing has run from this start.
    const std::shared_ptr<const RunPiece>& run() const { return run_; }
    // The run holds an edit of the objects made at t > 0 (not undone, not kept): Save does not
    // write it and only keep() makes it part of the start, so leaving the scene loses it.
    bool runEdits() const;

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
    bool restart(const std::string& label, const Scene& first);  // `first` is now t = 0
    void edited(double t, bool objects);  // the objects (or only the world) changed at time t
    void pushed(uint64_t before);         // after a history push: the new state's time and start
    void recall();                        // after undo or redo: the time and start of that state

    struct Moment {
        double time = 0;
        std::shared_ptr<const Scene> start;
        std::shared_ptr<const RunPiece> run;
    };

    Scene scene_;
    double time_ = 0;
    std::shared_ptr<const Scene> start_;   // null: t = 0 and the scene is its own start
    std::shared_ptr<const RunPiece> run_;  // null: nothing has run from this start
    std::map<uint64_t, Moment> moments_;   // the history states with a start or a run
    std::string path_;
    History history_;
    mutable Scene saved_;  // as the file holds it; its camera follows scene_'s
    Camera fileCamera_;    // the camera as the file holds it
    mutable uint64_t checkedVersion_ = ~uint64_t(0);
    mutable bool dirty_ = false;  // as of checkedVersion_
    uint64_t version_ = 0;
    uint64_t opened_ = 0;
};

bool sameCamera(const Camera& a, const Camera& b);
std::string timeLabel(double seconds);  // "t = 2.35 s", for the title and the menu bar

}  // namespace mb
