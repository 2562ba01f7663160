// marchbox/gl/scene_tree.h — a scene's groups as the renderer sees them: which flatten into a
// plain chain of objects, and which need the compiled shader's nested blocks.
//
// A group whose members all join by a sharp union, itself joined by a sharp union, with no
// mirror and one copy, adds its members to its parent's chain exactly as if they stood there
// one by one: min is associative, and the first of equal distances keeps the surface either
// way. Such groups flatten. Any other group (a member's subtract or intersect, a blend, a
// mirror, copies) carves, blends or copies only inside itself: only the compiled shader, which
// writes the tree as nested blocks, draws it. The uber shader and the object grid walk flat
// chains, so a scene with such a group is always compiled (shader_source.cpp).
#pragma once

#include "marchbox/scene/scene.h"

#include <vector>

namespace mb {

// A union with no blend: what joins a plain chain, and what leaves its objects' surfaces whole.
bool sharpUnion(CsgOp op, float blend);

// For every group, whether its members may join its parent's chain directly (a group with no
// members adds nothing: it flattens). A group flattens only where its member groups do.
std::vector<bool> flatGroups(const Scene& scene);
bool flatChain(const Scene& scene);  // every group flattens: one chain of objects
// For every group, one past its last object in the tree order (groupEnd, in one pass).
std::vector<int> groupEnds(const Scene& scene);

// Whether group g's frame is turned in the world (its own turn or a parent's), or may turn: a
// body (a dynamic top-level group) turns as it moves, so its shader has the turn from the start
// and play compiles nothing.
bool frameTurned(const Scene& scene, int g);
// Whether object o moves with the simulator: a body of its own, or a member of one.
bool moves(const Scene& scene, const Object& o);

}  // namespace mb
