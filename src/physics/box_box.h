// box_box.h — two boxes by separating axes and clipping, where probing their SDFs fails: boxes
// stacked face to face touch only at corners and edges, where an SDF's gradient is diagonal.
//
// Of the 15 axes (each box's three face normals and the nine cross products of their edges),
// the one of least overlap separates them best. A face axis clips the other box's face that
// looks most against it to the reference face's sides (Sutherland–Hodgman), giving up to eight
// points; an edge axis gives the closest points of the two edges. Face axes are preferred unless
// an edge axis separates clearly more, so a resting stack keeps its face contacts.
#pragma once

#include "pair_contact.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace mb {

struct BoxPose {
    glm::dvec3 centre;
    glm::dquat orient;
    glm::dvec3 half;  // half extents along the box's local axes
};

// The contacts of a and b closer than `reach`; none where they are further apart.
std::vector<PairContact> collideBoxes(const BoxPose& a, const BoxPose& b, double reach);

}  // namespace mb
