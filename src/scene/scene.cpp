// scene.cpp — names of the scene model's enumerations, as the file format spells them.
#include "marchbox/scene/scene.h"

#include "marchbox/scene/sdf.h"
#include "marchbox/scene/shapes.h"

#include <algorithm>
#include <glm/gtc/quaternion.hpp>

namespace mb {

const char* shapeTypeName(ShapeType t) { return shapeRow(t).name; }

const char* csgOpName(CsgOp op) {
    static const char* names[kCsgOpCount] = {"union", "subtract", "intersect"};
    return names[int(op)];
}

bool hasEdges(ShapeType t) { return shapeRow(t).edges; }

float halfThinnest(const Object& o) {
    switch (o.type) {
        case ShapeType::Sphere:
        case ShapeType::Capsule:
            return o.radius;
        case ShapeType::Box:
        case ShapeType::Ellipsoid:
            return std::min(o.size.x, std::min(o.size.y, o.size.z));
        case ShapeType::Torus:
            return o.minor;
        case ShapeType::Cylinder:
        case ShapeType::Cone:
            return std::min(o.radius, 0.5f * o.height);
    }
    return 0.0f;
}

glm::quat Object::orientation() const {
    return orient ? *orient : glm::quat_cast(rotationFromEuler(rot));
}

glm::quat Group::orientation() const {
    return orient ? *orient : glm::quat_cast(rotationFromEuler(rot));
}

namespace {

bool within(const Scene& scene, int group, int g) {
    for (; group >= 0; group = scene.groups[size_t(group)].parent)
        if (group == g) return true;
    return false;
}

// A member's frame in the world: the parent's frame applied to the member's own.
Placement compose(const Placement& parent, glm::vec3 pos, glm::quat turn) {
    return {parent.pos + parent.turn * pos, parent.turn * turn};
}

}  // namespace

int groupEnd(const Scene& scene, int g) {
    int end = scene.groups[size_t(g)].first;
    while (end < int(scene.objects.size()) && within(scene, scene.objects[size_t(end)].group, g))
        ++end;
    return end;
}

int groupDepth(const Scene& scene, int g) {
    int depth = 0;
    for (; g >= 0; g = scene.groups[size_t(g)].parent) ++depth;
    return depth;
}

int topGroupOf(const Scene& scene, const Object& o) {
    int g = o.group;
    while (g >= 0 && scene.groups[size_t(g)].parent >= 0) g = scene.groups[size_t(g)].parent;
    return g;
}

Placement groupPose(const Scene& scene, int g) {
    if (g < 0) return {};
    const Group& group = scene.groups[size_t(g)];
    return compose(groupPose(scene, group.parent), group.pos, group.orientation());
}

Placement worldPose(const Scene& scene, const Object& o) {
    return compose(groupPose(scene, o.group), o.pos, o.orientation());
}

}  // namespace mb
