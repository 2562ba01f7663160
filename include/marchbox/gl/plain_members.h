// marchbox/gl/plain_members.h — the part of a scene that rays meet exactly instead of marching.
//
// A plain member is a convex shape joined by a sharp union (op union, blend 0) that no later
// object's subtract, intersect or blend reaches: there the scene's surface is the shape's own,
// and the ray's nearest hit on it is the scene's (shaders/intersect.glsl). The rest is marched,
// bounded by its own box, and a ray takes the nearer answer. A member of a group that flattens
// (scene_tree.h) stands in the chain as a top-level object would; a group that does not
// flatten is one marched item of the chain, whole, whose members are never plain.
#pragma once

#include "marchbox/scene/object_grid.h"
#include "marchbox/scene/scene.h"
#include "marchbox/scene/sdf.h"

#include <vector>

namespace mb {

// Whether a ray can meet the object's shape in closed form: its type has a hit (shapes.h, in
// shaders/intersect.glsl) and it is neither rounded nor hollow; those are marched.
bool exactlyMet(const Object& o);
// Whether the object is a plain member unless a later item of the chain reaches it: exactly met
// and joined by a sharp union. Where it stands does not matter.
bool mayBePlain(const Object& o);

// Which of the scene's objects are plain members, in tree order. A later item of the chain
// reaches an earlier object when it is an intersection (which keeps only its overlap), or when
// its reach meets the object's bound; a body moves, so one always counts as reaching and
// reached (a member of a body too): play then changes no program.
std::vector<bool> plainMembers(const Scene& scene);

// The box of the plain members' reach (plainOnes) or the marched objects' (empty if none). An
// object in a group counts as its top-level group's whole bound: mirrors and copies reach as
// far as that.
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
