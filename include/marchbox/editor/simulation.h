// marchbox/editor/simulation.h — Play, Pause, Step and Reset over a Document.
//
// While playing, the simulator changes the live scene every frame through the fixed-step
// accumulator, outside the undo history; pausing records the whole run as one undo step.
// Frames already baked after the time shown are played back, not simulated again; past the
// last one the run is simulated on. With Loop on, playing goes back to t = 0 at loopEnd().
// Without it, playing stops by itself once every body sleeps and the camera keys are played:
// nothing more would change.
// The document keeps the time and the start (t = 0); Reset goes back to that start.
#pragma once

#include "marchbox/editor/document.h"
#include "marchbox/editor/frame_cache.h"
#include "marchbox/physics/physics.h"

#include <memory>

namespace mb {

class Simulation {
public:
    explicit Simulation(const PhysicsSettings& settings = {}) : settings_(settings) {}

    bool playing() const { return playing_; }
    const PhysicsSettings& settings() const { return settings_; }

    void play(Document& doc);
    bool loop() const { return loop_; }
    void setLoop(bool on) { loop_ = on; }
    void pause(Document& doc);  // records the run since play() as "Simulation run"
    // The time playing last stopped by itself, every body at rest; -1 once played again.
    double restedAt() const { return restedAt_; }
    void step(Document& doc);   // one fixed step, as its own undo step; pauses first
    void reset(Document& doc);  // back to t = 0, as an undo step

    // Each frame: the steps the accumulator owes for frameSeconds, taken and written back.
    // Returns the number of steps; 0 while paused.
    int advance(Document& doc, double frameSeconds);

    // The scene was edited, undone or replaced: the physics world is rebuilt before the next
    // step, and the cache keeps only the frames of the document's run. While playing, the run so
    // far must be committed first (commitRun) so that the edit is its own undo step; the run then
    // continues from the edited scene.
    void commitRun(Document& doc);
    void sceneChanged(Document& doc);

    const PhysicsWorld* world() const { return world_.get(); }
    const FrameCache& cache() const { return cache_; }  // each frame of the runs so far

private:
    void simulate(Document& doc, int steps);  // on from the scene shown, baking each frame
    bool worldAtBakeEnd() const;
    bool cameToRest(const Document& doc) const;

    PhysicsSettings settings_;
    // The world as it simulated the last baked frame, to go on from: a run played on after a
    // scrub back is the run never interrupted, not one begun again from a frame's floats. Null
    // until the first step, and once the bake's last frame is no longer the one it made.
    std::unique_ptr<PhysicsWorld> world_;
    double worldTime_ = 0;                        // s: the frame it made
    std::shared_ptr<const RunPiece> worldPiece_;  // and that frame's piece
    StepAccumulator accumulator_;
    FrameCache cache_;
    Scene runStart_;  // the scene when this run (or its last committed part) began
    bool playing_ = false;
    bool loop_ = false;
    double head_ = 0;         // s: the time playing has got to
    double bakedAtPlay_ = 0;  // s: the baked frames' end when Play was pressed, where a loop ends
    double restedAt_ = -1;    // s: see restedAt()
};

}  // namespace mb
