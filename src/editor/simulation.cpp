// simulation.cpp — the physics world driven by frames, recorded as undo steps.
#include "marchbox/editor/simulation.h"

#include "marchbox/editor/timeline.h"

namespace mb {

void Simulation::ensureWorld(const Scene& scene) {
    if (!world_) world_ = std::make_unique<PhysicsWorld>(scene, settings_);
}

void Simulation::play(Document& doc) {
    if (playing_) return;
    playing_ = true;
    accumulator_ = {};
    runStart_ = doc.scene();
    head_ = doc.time();
    bakedAtPlay_ = cache_.end();
}

void Simulation::pause(Document& doc) {
    if (!playing_) return;
    commitRun(doc);
    playing_ = false;
}

void Simulation::commitRun(Document& doc) {
    if (!playing_) return;
    doc.commit("Simulation run", runStart_);
    runStart_ = doc.scene();
}

void Simulation::sceneChanged(Document& doc) {
    world_.reset();
    cache_.follow(doc.run());
    // An edit at t (or an undo to a time the cache lost) shows a frame of the run: the first
    // of what follows.
    if (doc.time() > cache_.end()) cache_.record(doc.run(), doc.time(), doc.scene());
    if (playing_) runStart_ = doc.scene();
    head_ = doc.time();
}

void Simulation::step(Document& doc) {
    pause(doc);
    Scene before = doc.scene();
    simulate(doc, 1);
    doc.commit("Simulation step", before);
}

void Simulation::reset(Document& doc) {
    pause(doc);
    if (doc.rewind("Reset simulation")) sceneChanged(doc);
}

int Simulation::advance(Document& doc, double frameSeconds) {
    if (!playing_) return 0;
    const int steps = accumulator_.advance(frameSeconds, settings_);
    if (steps == 0) return 0;
    const double end = loop_ ? loopEnd(doc.scene().keyframes, bakedAtPlay_) : 0.0;
    head_ = playHead(head_, steps * settings_.dt, end);
    // Frame times are sums of steps: one a rounding error past the head is still at it.
    if (head_ <= cache_.end() + 1e-9) {
        show(doc, cache_.at(head_ + 1e-9));
        return steps;
    }
    simulate(doc, steps);  // past the baked frames (from before the last: the same again)
    head_ = doc.time();
    return steps;
}

void Simulation::show(Document& doc, const BakedFrame* frame) {
    doc.show(frame);
    world_.reset();  // built again from the frame where the run is simulated on
}

void Simulation::simulate(Document& doc, int steps) {
    ensureWorld(doc.scene());
    for (int i = 0; i < steps; ++i) world_->step();
    world_->writeBack(doc.moving(steps * settings_.dt));
    cache_.record(doc.run(), doc.time(), doc.scene());
}

}  // namespace mb
