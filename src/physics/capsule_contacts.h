// capsule_contacts.h — capsules against capsules and boxes, in closed form: a capsule holds the
// points within its radius of a segment, so it touches where its segment comes closest.
//
// Capsule–capsule: the closest points of the two segments (Ericson, "Real-Time Collision
// Detection", 5.1.9), the normal along their difference, separation = distance − r₁ − r₂.
// Capsule–box: the closest points of the segment and the box (an end of the segment against
// the box, or the segment against one of its twelve edges); where the segment reaches into the
// box, the face it lies least deep behind.
//
// A segment lying along the other shape touches along a line. The line's two ends, the segment
// clipped to the other's extent, are its points, so a capsule lying on either rests on two
// points and does not rock on one. Where the closest point lies deeper than both ends
// (segments crossing at an angle, a segment dipping past a face's edge), it is kept as well.
// - Along a box face: within kAligned of parallel to it.
// - Along another segment: wherever one's projection onto the other covers more than a
//   quarter of the shorter one, whatever the angle. The ends are then points of speculative
//   contact that a single closest point would miss: two capsules crossing at 10° to 45° and
//   turning as they land slid through each other on one point (5.8 cm deep in the mixed pile
//   of 1000, 1.8 cm with the ends).
// Features: 0 the closest point, 1 and 2 the line's ends.
#pragma once

#include "box_box.h"
#include "pair_contact.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace mb {

constexpr double kAligned = 0.05;  // a segment lies along a face within this sine: 2.9°

struct CapsulePose {
    glm::dvec3 centre;
    glm::dquat orient;  // the segment lies along the capsule's local y axis
    double half;        // half the segment's length
    double radius;
};

// The contacts of a and b closer than `reach`, normals from a to b; none where further apart.
std::vector<PairContact> collideCapsules(const CapsulePose& a, const CapsulePose& b, double reach);
std::vector<PairContact> collideCapsuleBox(const CapsulePose& a, const BoxPose& b, double reach);

}  // namespace mb
