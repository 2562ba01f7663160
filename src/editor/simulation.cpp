// simulation.cpp — the physics world driven by frames, recorded as undo steps.
#include "marchbox/editor/simulation.h"

namespace mb {

void Simulation::ensureWorld(const Scene& scene) {
    if (!world_) world_ = std::make_unique<PhysicsWorld>(scene, settings_);
}

void Simulation::play(Document& doc) {
    if (playing_) return;
    playing_ = true;
    accumulator_ = {};
    runStart_ = doc.scene();
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
}

void Simulation::step(Document& doc) {
    pause(doc);
    Scene before = doc.scene();
    ensureWorld(before);
    world_->step();
    world_->writeBack(doc.moving(settings_.dt));
    cache_.record(doc.run(), doc.time(), doc.scene());
    doc.commit("Simulation step", before);
}

void Simulation::reset(Document& doc) {
    pause(doc);
    if (doc.rewind("Reset simulation")) sceneChanged(doc);
}

int Simulation::advance(Document& doc, double frameSeconds) {
    if (!playing_) return 0;
    int steps = accumulator_.advance(frameSeconds, settings_);
    if (steps == 0) return 0;
    ensureWorld(doc.scene());
    for (int i = 0; i < steps; ++i) world_->step();
    world_->writeBack(doc.moving(steps * settings_.dt));
    cache_.record(doc.run(), doc.time(), doc.scene());
    return steps;
}

}  // namespace mb
