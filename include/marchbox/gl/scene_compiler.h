// marchbox/gl/scene_compiler.h — the scene's structure written out as GLSL.
//
// A small scene's mapObjects() is one line per object in file order: its SDF called directly,
// joined by its operator, turned only where it has a rotation. The numbers (where, how big,
// which material) stay in the Objects block, so moving, resizing or recolouring compiles
// nothing; adding, deleting or retyping an object changes the layout and compiles anew.
// Larger scenes keep the loop of shaders/scene_map.glsl, whose per-type SDF switch is written
// here too, from the same table, for the types present only. Every scene has that switch: the
// editor's selection outline (shaders/outline.glsl) measures one object by its index.
#pragma once

#include "marchbox/scene/scene.h"

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

    bool operator==(const ObjectLayout&) const = default;
};

std::vector<ObjectLayout> objectLayout(const Scene& scene);

// loadObjects() and mapObjects(p) for a compiled scene; with plain members also mapRest(p), the
// chain of the others, and hitPlainMembers(ro, rd, far, anyHit), a line of exact intersection
// each (shaders/intersect.glsl); with soft shadows too plainClearance(ro, rd, far, k), a line of
// closed-form penumbra per plain ball (shaders/penumbra.glsl), and mapSoftRest(p), the chain of
// all the other objects, which soft shadows march.
std::string compileSceneMap(const std::vector<ObjectLayout>& layout, bool softShadows);

// sdShape(o, q) and sdObjectLocal(i, q) for the loop, the outline and a plain member's normal: one
// case per type whose bit is set in
// `shapes`.
std::string compileShapeSwitch(unsigned shapes);

}  // namespace mb
