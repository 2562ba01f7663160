// frame_cache.cpp — recording runs frame by frame and finding a frame by time.
#include "marchbox/editor/frame_cache.h"

#include <algorithm>

namespace mb {

void FrameCache::record(const std::shared_ptr<const Scene>& start, double t, const Scene& scene) {
    if (start != start_) frames_.clear();
    start_ = start;
    // A run going on from an earlier time (after a scrub or an undo) replaces what followed.
    while (!frames_.empty() && frames_.back().t >= t) frames_.pop_back();
    if (!start || frames_.size() >= kMaxFrames) return;
    BakedFrame f{t, {}};
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        if (o.dynamic()) f.bodies.push_back({int(i), o.pos, o.vel, o.spin, o.orient});
    }
    frames_.push_back(std::move(f));
}

const BakedFrame* FrameCache::at(const std::shared_ptr<const Scene>& start, double t) const {
    if (!start || start != start_) return nullptr;
    auto after = std::upper_bound(frames_.begin(), frames_.end(), t,
                                  [](double v, const BakedFrame& f) { return v < f.t; });
    return after == frames_.begin() ? nullptr : &*(after - 1);
}

double FrameCache::end(const std::shared_ptr<const Scene>& start) const {
    return start && start == start_ && !frames_.empty() ? frames_.back().t : 0.0;
}

void applyFrame(const BakedFrame& frame, Scene& scene) {
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
