// marchbox/gl/plain_members.h — the part of a scene that rays meet exactly instead of marching.
//
// A plain member is a convex shape joined by a sharp union (op union, blend 0) that no later
// object's subtract, intersect or blend reaches: there the scene's surface is the shape's own,
// and the ray's nearest hit on it is the scene's (shaders/intersect.glsl). The rest is marched,
// bounded by its own box, and a ray takes the nearer answer.
#pragma once

#include "marchbox/scene/object_grid.h"
#include "marchbox/scene/scene.h"
#include "marchbox/scene/sdf.h"

#include <vector>

namespace mb {

// Which of the scene's objects are plain members, in file order. A later object reaches an
// earlier one when it is an intersection (which keeps only its overlap), or when its reach
// meets the earlier one's bound; a body moves, so one always counts as reaching and reached:
// play then changes no program.
std::vector<bool> plainMembers(const Scene& scene);

// The box of the plain members' reach (plainOnes) or the marched objects' (empty if none).
Box membersBounds(const SceneSdf& sdf, const std::vector<bool>& plain, bool plainOnes);

// What the shader's plain-member grid reads: the grid over the plain members alone (items are
// object indices) and three RGBA texels per object (intersect.glsl's uPlainShapes), whose
// second texel's w is -1 for an object that is not a plain member.
struct PlainGrid {
    ObjectGrid grid;
    std::vector<float> shapes;
};
PlainGrid buildPlainGrid(const SceneSdf& sdf, const std::vector<bool>& plain);

}  // namespace mb
