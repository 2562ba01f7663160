// marchbox/editor/frame_cache.h — every dynamic body's state at each simulated frame, to scrub.
//
// A run is a chain of pieces: the first goes on from the start (t = 0); an edit at a later time
// t begins another, which goes on from the scene as edited at t. Each frame names the piece it
// was simulated in. The cache holds one timeline, that of the document's run: after an edit,
// an undo or a replay from an earlier time, follow() drops the frames that no longer belong to
// it, which are all those after the time that changed. Only the bodies are kept (about 60
// bytes each): a minute at 60 frames/s of 4096 bodies is about 1 GB, so past a budget the
// cache drops every other frame and keeps frames half as often from then on.
#pragma once

#include "marchbox/scene/scene.h"

#include <glm/gtc/quaternion.hpp>
#include <memory>
#include <optional>
#include <vector>

namespace mb {

// One stretch of a run, immutable and shared: the pieces before it stay the run's past.
struct RunPiece {
    double from = 0;                                     // s: where it begins
    std::shared_ptr<const std::vector<Object>> objects;  // as edited at `from`; null: the start's
    std::shared_ptr<const RunPiece> before;              // the piece it goes on from; null: none
    bool objectsEdited = false;  // the edit at `from` changed the objects, which the start lacks
    std::shared_ptr<const std::vector<Group>> groups{};  // with `objects`: the groups as edited
};

// The piece of `run` that holds time t: the last to begin at or before it (an edit at t
// belongs to the time it was made at). Null for a null run.
const std::shared_ptr<const RunPiece>& pieceAt(const std::shared_ptr<const RunPiece>& run,
                                               double t);

struct BodyState {
    int object = 0;  // its index in Scene::objects, or in Scene::groups for a group
    glm::vec3 pos{0.0f}, vel{0.0f}, spin{0.0f};
    std::optional<glm::quat> orient;
    bool group = false;  // a dynamic group, moved as one body
};

struct BakedFrame {
    double t = 0;                           // s since the start
    std::shared_ptr<const RunPiece> piece;  // the piece it was simulated in
    std::vector<BodyState> bodies;
    bool afterHole = false;  // the frames before it, back to the one before, are lost
};

class FrameCache {
public:
    static constexpr size_t kDefaultBudget = size_t(512) << 20;  // bytes: 36 s of 4096 bodies

    explicit FrameCache(size_t budget = kDefaultBudget) : budget_(budget) {}

    // The scene's dynamic bodies at time t of `run` (its last piece), after the frames before t.
    // `afterHole`: the frames between the last one and t are lost (a run undone and redone
    // brings back its last pose alone).
    void record(const std::shared_ptr<const RunPiece>& run, double t, const Scene& scene,
                bool afterHole = false);
    // Keeps the frames up to the first that is not of `run` (all of them go for a null run).
    void follow(const std::shared_ptr<const RunPiece>& run);

    // The last frame at or before t; null where none is (t = 0 is the start itself).
    const BakedFrame* at(double t) const;
    // Whether t is in the bake: at or before its end and not in a hole. In a hole, as past the
    // end, the run is simulated anew.
    bool holds(double t) const;
    // The widest time between two frames that follow each other with no hole between: a frame
    // further on from the last than this comes after a hole.
    double widest() const { return widest_; }
    const BakedFrame* last() const { return frames_.empty() ? nullptr : &frames_.back(); }
    double end() const;  // the last frame's t, or 0
    bool empty() const { return frames_.empty(); }
    size_t frames() const { return frames_.size(); }
    size_t bytes() const;  // held by the frames, about

private:
    void thin();  // every other frame goes, the last stays

    size_t budget_;
    double gap_ = 0;                  // s: the least time between frames kept, 0 at first
    double widest_ = 0;               // s: see widest()
    std::vector<BakedFrame> frames_;  // in order of t
};

// The bodies back where they were: the frame's piece's objects and groups where an edit made
// them, then each dynamic body's state. `scene` holds the start's objects before, and keeps
// their looks (copyLooks): a name or material edited at any time is the start's.
void applyFrame(const BakedFrame& frame, Scene& scene);

// What the simulator never reads: an object's name, material and comment, a group's name and
// comment. `to` takes those of `from` where the two lists are as long.
void copyLooks(const std::vector<Object>& from, std::vector<Object>& to);
void copyLooks(const std::vector<Group>& from, std::vector<Group>& to);

}  // namespace mb
