// marchbox/editor/frame_cache.h — every dynamic body's state at each simulated frame, to scrub.
//
// A cache belongs to one start (the document's scene at t = 0, by identity): a run from another
// start, or a run going on from an earlier time, drops the frames that no longer follow. Only
// the bodies are kept (about 60 bytes each): a minute at 60 frames/s of 4096 bodies is under
// 1 GB, so the cache stops at kMaxFrames and the slider ends there.
#pragma once

#include "marchbox/scene/scene.h"

#include <glm/gtc/quaternion.hpp>
#include <memory>
#include <optional>
#include <vector>

namespace mb {

struct BodyState {
    int object = 0;
    glm::vec3 pos{0.0f}, vel{0.0f}, spin{0.0f};
    std::optional<glm::quat> orient;
};

struct BakedFrame {
    double t = 0;  // s since the start
    std::vector<BodyState> bodies;
};

class FrameCache {
public:
    static constexpr size_t kMaxFrames = 3600;

    // The scene's dynamic bodies at time t of the run from `start`.
    void record(const std::shared_ptr<const Scene>& start, double t, const Scene& scene);
    // The last frame at or before t of the run from `start`; null where none is (t = 0 is the
    // start itself).
    const BakedFrame* at(const std::shared_ptr<const Scene>& start, double t) const;
    double end(const std::shared_ptr<const Scene>& start) const;  // the last frame's t, or 0

private:
    std::shared_ptr<const Scene> start_;  // held, so that no other start takes its address
    std::vector<BakedFrame> frames_;      // in order of t
};

void applyFrame(const BakedFrame& frame, Scene& scene);  // the bodies back where they were

}  // namespace mb
