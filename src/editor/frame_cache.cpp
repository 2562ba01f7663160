// frame_cache.cpp — recording runs frame by frame and finding a frame by time.
#include "marchbox/editor/frame_cache.h"

#include <algorithm>

namespace mb {

const std::shared_ptr<const RunPiece>& pieceAt(const std::shared_ptr<const RunPiece>& run,
                                               double t) {
    const std::shared_ptr<const RunPiece>* p = &run;
    while (*p && (*p)->from > t && (*p)->before) p = &(*p)->before;
    return *p;
}

void FrameCache::record(const std::shared_ptr<const RunPiece>& run, double t, const Scene& scene) {
    // A run going on from an earlier time (after a scrub or an undo) replaces what followed.
    while (!frames_.empty() && frames_.back().t >= t) frames_.pop_back();
    if (!run || frames_.size() >= kMaxFrames) return;
    BakedFrame f{t, pieceAt(run, t), {}};
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        if (o.dynamic()) f.bodies.push_back({int(i), o.pos, o.vel, o.spin, o.orient});
    }
    frames_.push_back(std::move(f));
}

void FrameCache::follow(const std::shared_ptr<const RunPiece>& run) {
    auto stray = std::find_if(frames_.begin(), frames_.end(), [&](const BakedFrame& f) {
        return !run || f.piece != pieceAt(run, f.t);
    });
    frames_.erase(stray, frames_.end());
}

const BakedFrame* FrameCache::at(double t) const {
    auto after = std::upper_bound(frames_.begin(), frames_.end(), t,
                                  [](double v, const BakedFrame& f) { return v < f.t; });
    return after == frames_.begin() ? nullptr : &*(after - 1);
}

double FrameCache::end() const { return frames_.empty() ? 0.0 : frames_.back().t; }

void applyFrame(const BakedFrame& frame, Scene& scene) {
    if (frame.piece && frame.piece->objects) scene.objects = *frame.piece->objects;
    for (const BodyState& b : frame.bodies) {
        if (b.object >= int(scene.objects.size())) continue;
        Object& o = scene.objects[size_t(b.object)];
        o.pos = b.pos;
        o.vel = b.vel;
        o.spin = b.spin;
        o.orient = b.orient;
    }
}

}  // namespace mb
