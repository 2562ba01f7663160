// marchbox/gl/scene_compiler.h — the scene's structure written out as GLSL.
//
// A small scene's mapObjects() is one line per object in tree order: its SDF called directly,
// joined by its operator, turned only where it has a rotation. A group is a nested block
// (its name in a comment) that gathers its members' lines in a result of its own, skipped where
// the point lies beyond the group's bounding sphere, then joins its parent's chain by the
// group's operator; a mirrored group's members see the folded point, a repeated group's run in
// a loop over the copies that can come nearest (shaders/groups.glsl). The numbers (where, how
// big, which material; a group's place, turn and spacing) stay in the Objects and Groups
// blocks, so moving, resizing or recolouring compiles nothing; adding, deleting or retyping an
// object, or regrouping, changes the layout and compiles anew.
// Larger scenes keep the loop of shaders/scene_map.glsl, whose per-type SDF switch is written
// here too, from the same table, for the types present only. Every scene has that switch: the
// editor's selection outline (shaders/outline.glsl) measures one object by its index.
#pragma once

#include "marchbox/scene/scene.h"

#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace mb {

// What of an object the compiled code depends on; everything else is a uniform.
struct ObjectLayout {
    ShapeType type = ShapeType::Sphere;
    CsgOp op = CsgOp::Union;
    bool rotated = false;  // rot is not (0,0,0): the point is turned into the object's frame
    bool blended = false;  // blend > 0: the smooth operator
    bool plain = false;    // met by exact intersection, not marched (gl/plain_members.h)
    bool rounded = false;  // round > 0 on a box, cylinder or cone
    bool shelled = false;  // shell > 0: hollow
    int group = -1;        // index of its group in SceneLayout::groups; -1: the top level

    bool operator==(const ObjectLayout&) const = default;
};

// What of a group the compiled code depends on.
struct GroupLayout {
    std::string name;  // for the block's comment
    int parent = -1;
    int first = 0, end = 0;  // its objects, [first, end) of the tree order
    CsgOp op = CsgOp::Union;
    bool blended = false;
    bool turned = false;       // its frame is turned (scene_tree.h's frameTurned)
    glm::bvec3 mirror{false};  // axes whose positive half is kept, reflected
    glm::ivec3 repeat{1};      // copies along each axis

    bool operator==(const GroupLayout&) const = default;
};

struct SceneLayout {
    std::vector<ObjectLayout> objects;  // tree order (Scene::objects)
    std::vector<GroupLayout> groups;    // Scene::groups

    bool operator==(const SceneLayout&) const = default;
};

SceneLayout sceneLayout(const Scene& scene);

// loadObjects() and mapObjects(p) for a compiled scene; with plain members also mapRest(p), the
// chain of the others, and hitPlainMembers(ro, rd, far, anyHit), a line of exact intersection
// each (shaders/intersect.glsl); with soft shadows too plainClearance(ro, rd, far, k), a line of
// closed-form penumbra per plain ball (shaders/penumbra.glsl), and mapSoftRest(p), the chain of
// all the other objects, which soft shadows march.
std::string compileSceneMap(const SceneLayout& layout, bool softShadows);

// sdShape(o, q) and sdObjectLocal(i, q) for the loop, the outline and a plain member's normal: one
// case per type whose bit is set in `shapes`; `round` and `shell` add the rounded and the hollow
// forms, chosen by the object's numbers. Then hitShape(o, r, d), the exact hit of each of those
// types that has one, for the grid of plain members (intersect.glsl).
std::string compileShapeSwitch(unsigned shapes, bool round, bool shell);

}  // namespace mb
