// pair_cache.h — a pair's contact points kept while the two bodies lie as they lay, as Jolt's
// body pair cache keeps them. Finding the points (the closed forms, or probing each body's
// surface against the other's SDF) is most of a rigid step, and in a pile most pairs barely
// move against each other from one step to the next.
//
// Each point is kept on the surfaces that made it, each end in its own body's frame, with the
// normal in a's. While b stands within kMovedMost and kTurnedMost of where it stood against a
// when the points were found, the points are rebuilt from the bodies' poses now: both ends move
// with their bodies, so the separation follows the bodies' motion along the kept normal. Past
// either bound, or when the pair was not met in the last step, the points are found anew.
//
// A pair that had no point within its reach has none still while its reach now, plus how far
// any point of b can have come towards a (b's shift, and its turn times its bound), is within
// the reach it was searched to: no point was nearer than that. Kept points miss what came within
// reach since; so b must also have come less than half the reach (every reach is at least 4
// linear slops, 2 cm at the defaults), which the bounds above keep for bodies whose bound is under
// 1 m: larger ones are found anew.
#pragma once

#include "pair_contact.h"

#include <cstdint>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <unordered_map>
#include <vector>

namespace mb {

struct RigidBody;

class PairCache {
public:
    static constexpr double kMovedMost = 5e-4;  // m, b's origin in a's frame
    static constexpr double kTurnedMost = 0.5;  // degrees, b's turn in a's frame

    void nextStep();  // pairs not met in the step that ended are forgotten
    // The pair's points rebuilt for the poses now, into *out; false where they must be found.
    // `reach`: how far apart the bodies' points may be and still meet in this step.
    bool reuse(std::uint64_t pair, const RigidBody& a, const RigidBody& b, double reach,
               std::vector<PairCandidate>* out);
    void keep(std::uint64_t pair, const RigidBody& a, const RigidBody& b, double reach,
              const std::vector<PairCandidate>& found);

private:
    struct Pose {
        glm::dvec3 pos;
        glm::dquat orient;
    };
    // The points as found, and where both bodies stood: most pairs move on before they are
    // reused (a pile of tables reused one in six), so a point is taken into its bodies' frames
    // only when it is.
    struct Entry {
        Pose a, b;
        double reach;  // searched to
        std::vector<PairCandidate> points;
    };
    std::unordered_map<std::uint64_t, Entry> last_, now_;
};

}  // namespace mb
