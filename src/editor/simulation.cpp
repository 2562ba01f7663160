// simulation.cpp — the physics world driven by frames, recorded as undo steps.
#include "marchbox/editor/simulation.h"

#include "marchbox/editor/timeline.h"

#include <cmath>

namespace mb {

void Simulation::play(Document& doc) {
    if (playing_) return;
    playing_ = true;
    accumulator_ = {};
    runStart_ = doc.scene();
    head_ = doc.time();
    bakedAtPlay_ = cache_.end();
    restedAt_ = -1;
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
    cache_.follow(doc.run());
    // An edit at t (or an undo to a time the cache lost) shows a frame of the run: the first
    // of what follows.
    if (doc.time() > cache_.end())
        cache_.record(doc.run(), doc.time(), doc.scene(),
                      doc.time() - cache_.end() > cache_.widest() + 1e-9);
    if (!worldAtBakeEnd()) world_.reset();
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
    const double loopAt = loop_ ? loopEnd(doc.scene().keyframes, bakedAtPlay_) : 0.0;
    head_ = playHead(head_, steps * settings_.dt, loopAt);
    // Frame times are sums of steps: one a rounding error past the head is still at it.
    const double baked = cache_.end();
    if (cache_.holds(head_)) {
        doc.show(cache_.at(head_ + 1e-9));
        return steps;
    }
    if (head_ > baked && worldAtBakeEnd() && doc.time() < baked) {  // on from the bake's end
        doc.show(cache_.last());
        simulate(doc, int(std::llround((head_ - baked) / settings_.dt)));
    } else {
        simulate(doc, steps);  // from the frame shown: a world built from its floats
    }
    head_ = doc.time();
    if (cameToRest(doc)) {
        pause(doc);
        restedAt_ = doc.time();
    }
    return steps;
}

bool Simulation::cameToRest(const Document& doc) const {
    return !loop_ && world_ && world_->stats().awake == 0 &&
           doc.time() + 1e-9 >= loopEnd(doc.scene().keyframes, 0.0);
}

void Simulation::simulate(Document& doc, int steps) {
    // The world goes on where it is the scene shown: at the last baked frame it made.
    if (!worldAtBakeEnd() || std::abs(doc.time() - worldTime_) > 1e-9) world_.reset();
    if (!world_) world_ = std::make_unique<PhysicsWorld>(doc.scene(), settings_);
    for (int i = 0; i < steps; ++i) world_->step();
    world_->writeBack(doc.moving(steps * settings_.dt));
    cache_.record(doc.run(), doc.time(), doc.scene());
    if (const BakedFrame* last = cache_.last()) {  // the frame just made
        worldTime_ = last->t;
        worldPiece_ = last->piece;
    }
}

bool Simulation::worldAtBakeEnd() const {
    const BakedFrame* last = cache_.last();
    return world_ && last && last->t == worldTime_ && last->piece == worldPiece_;
}

}  // namespace mb
