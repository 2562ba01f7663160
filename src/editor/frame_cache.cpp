// frame_cache.cpp — recording runs frame by frame and finding a frame by time.
#include "marchbox/editor/frame_cache.h"

#include "marchbox/scene/sdf.h"

#include <algorithm>

namespace mb {

const std::shared_ptr<const RunPiece>& pieceAt(const std::shared_ptr<const RunPiece>& run,
                                               double t) {
    const std::shared_ptr<const RunPiece>* p = &run;
    while (*p && (*p)->from > t && (*p)->before) p = &(*p)->before;
    return *p;
}

void FrameCache::record(const std::shared_ptr<const RunPiece>& run, double t, const Scene& scene,
                        bool afterHole) {
    // A run going on from an earlier time (after a scrub or an undo) replaces what followed.
    while (!frames_.empty() && frames_.back().t >= t) frames_.pop_back();
    if (!run) return;
    BakedFrame f{t, pieceAt(run, t), {}, afterHole};
    // A thinned cache keeps frames a gap apart, the newest standing in until the next is a gap
    // on; the first after an edit always stays, to show the edit.
    const size_t n = frames_.size();
    if (n >= 2 && frames_[n - 1].piece == f.piece && frames_[n - 2].piece == f.piece &&
        t - frames_[n - 2].t < gap_) {
        f.afterHole = f.afterHole || frames_.back().afterHole;  // the hole stays before it
        frames_.pop_back();
    }
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        if (o.dynamic()) f.bodies.push_back({int(i), o.pos, o.vel, o.spin, o.orient});
    }
    for (size_t g = 0; g < scene.groups.size(); ++g) {
        const Group& b = scene.groups[g];
        if (b.dynamic()) f.bodies.push_back({int(g), b.pos, b.vel, b.spin, b.orient, true});
    }
    if (!afterHole && !frames_.empty()) widest_ = std::max(widest_, t - frames_.back().t);
    frames_.push_back(std::move(f));
    if (bytes() > budget_) thin();
}

size_t FrameCache::bytes() const {
    size_t n = frames_.size() * sizeof(BakedFrame);
    for (const BakedFrame& f : frames_) n += f.bodies.capacity() * sizeof(BodyState);
    return n;
}

void FrameCache::thin() {
    std::vector<BakedFrame> kept;
    for (size_t i = (frames_.size() - 1) % 2; i < frames_.size(); i += 2) {
        kept.push_back(std::move(frames_[i]));
        if (i > 0 && frames_[i - 1].afterHole) kept.back().afterHole = true;  // a frame it drops
    }
    frames_ = std::move(kept);
    if (frames_.size() > 1)
        gap_ = (frames_.back().t - frames_.front().t) / double(frames_.size() - 1);
    for (size_t i = 1; i < frames_.size(); ++i)
        if (!frames_[i].afterHole) widest_ = std::max(widest_, frames_[i].t - frames_[i - 1].t);
}

void FrameCache::follow(const std::shared_ptr<const RunPiece>& run) {
    auto stray = std::find_if(frames_.begin(), frames_.end(), [&](const BakedFrame& f) {
        return !run || f.piece != pieceAt(run, f.t);
    });
    frames_.erase(stray, frames_.end());
    if (frames_.empty()) widest_ = 0;  // a first frame past t = 0 follows a hole
}

const BakedFrame* FrameCache::at(double t) const {
    auto after = std::upper_bound(frames_.begin(), frames_.end(), t,
                                  [](double v, const BakedFrame& f) { return v < f.t; });
    return after == frames_.begin() ? nullptr : &*(after - 1);
}

bool FrameCache::holds(double t) const {
    constexpr double kSame = 1e-9;  // s: a play head a rounding past a frame is at it
    if (frames_.empty() || t > end() + kSame) return false;
    const BakedFrame* before = at(t + kSame);
    if (before && t - before->t <= kSame) return true;  // at a frame
    const BakedFrame* next = before ? before + 1 : frames_.data();
    return next == frames_.data() + frames_.size() || !next->afterHole;
}

double FrameCache::end() const { return frames_.empty() ? 0.0 : frames_.back().t; }

template <class R>
static void putBody(const BodyState& b, std::vector<R>& bodies) {
    if (b.object >= int(bodies.size())) return;
    R& r = bodies[size_t(b.object)];
    r.pos = b.pos;
    r.vel = b.vel;
    r.spin = b.spin;
    r.orient = b.orient;
    if (b.orient) r.rot = anglesShowing(*b.orient, r.rot);  // the fields show the frame's turn
}

void copyLooks(const std::vector<Object>& from, std::vector<Object>& to) {
    if (from.size() != to.size()) return;
    for (size_t i = 0; i < to.size(); ++i) {
        to[i].name = from[i].name;
        to[i].material = from[i].material;
        to[i].comment = from[i].comment;
    }
}

void copyLooks(const std::vector<Group>& from, std::vector<Group>& to) {
    if (from.size() != to.size()) return;
    for (size_t i = 0; i < to.size(); ++i) {
        to[i].name = from[i].name;
        to[i].comment = from[i].comment;
    }
}

// The piece's list where an edit made one, wearing the looks of the list it replaces.
template <class T>
static void takeEdited(const std::shared_ptr<const std::vector<T>>& edited, std::vector<T>& list) {
    if (!edited) return;
    std::vector<T> next = *edited;
    copyLooks(list, next);
    list = std::move(next);
}

void applyFrame(const BakedFrame& frame, Scene& scene) {
    if (frame.piece) takeEdited(frame.piece->objects, scene.objects);
    if (frame.piece) takeEdited(frame.piece->groups, scene.groups);
    for (const BodyState& b : frame.bodies) {
        if (b.group) putBody(b, scene.groups);
        else putBody(b, scene.objects);
    }
}

}  // namespace mb
