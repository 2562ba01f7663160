// oriented_box.h — boxes turned to any axes about a shape: cheap lower bounds on its distance,
// for culls that must leave every contact as it was.
//
// An exact SDF is no less than the distance to any solid that holds the shape, so a point at
// least d from a member's box is at least d from the member (to the float SDF's rounding, which
// callers allow for with a slack far above it). Distances and gaps here are in double.
#pragma once

#include "marchbox/scene/sdf.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace mb {

struct OrientedBox {
    glm::dvec3 centre{0.0};
    glm::dmat3 axes{1.0};  // columns: the box's axes in its parent frame
    glm::dvec3 half{0.0};
};

// The box about the object's shape, in the frame that holds it (o.pos and o.toLocal's).
OrientedBox boxAbout(const SdfObject& o);
// The box moved as a point x goes to shift + turn·x.
OrientedBox placed(const OrientedBox& b, const glm::dquat& turn, const glm::dvec3& shift);
// The box with the parent frame's axes that holds every box in `boxes` (none: an empty one).
OrientedBox boxAround(const std::vector<OrientedBox>& boxes);
// How far p is from the box; 0 inside it.
double distanceToBox(const OrientedBox& b, const glm::dvec3& p);
// False where the boxes lie at least -slack apart along one of the separating axes (their own
// and their edges' crosses): a positive slack lets faces that touch count as apart, a negative
// one asks for a gap of at least |slack|, which bounds the distance between them from below.
bool boxesOverlap(const OrientedBox& a, const OrientedBox& b, double slack);
// False where one of the six axes of the boxes' own faces parts them by `gap` or more: the
// face half of boxesOverlap(a, b, −gap), without the nine crosses of their edges or a root.
bool facesOverlap(const OrientedBox& a, const OrientedBox& b, double gap);

}  // namespace mb
