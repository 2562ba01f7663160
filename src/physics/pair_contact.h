// pair_contact.h — one contact point of two bodies, as each pair's analytic routine gives it,
// and as the rigid bodies' collision keeps it.
#pragma once

#include <glm/vec3.hpp>

namespace mb {

struct PairContact {
    glm::dvec3 point;   // midway between the two surfaces
    glm::dvec3 normal;  // unit, from a to b
    double separation;  // < 0 overlaps
    int feature;        // stable from step to step while the same features touch (0..254)
};

// A point of a pair as the collision finds it, before it becomes a contact row: the closed
// forms' PairContact, or a probe's, with where each side turns from.
struct PairCandidate {
    glm::dvec3 point, normal;  // midway between the surfaces; normal from a to b
    double separation;
    int probe;  // key within the pair
    // Where each side's anchor turns from (sideOf's `centre`): a probe's centre, a capsule's
    // segment point, or the point itself where it turns with the body (a corner).
    glm::dvec3 centreA, centreB;
};

}  // namespace mb
