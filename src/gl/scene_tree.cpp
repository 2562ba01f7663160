// scene_tree.cpp — which groups flatten into a plain chain (see scene_tree.h).
#include "marchbox/gl/scene_tree.h"

#include <algorithm>
#include <glm/gtc/quaternion.hpp>

namespace mb {

namespace {

bool sharpUnion(CsgOp op, float blend) { return op == CsgOp::Union && blend <= 0.0f; }

bool ownTurn(const std::optional<glm::quat>& orient, glm::vec3 rot) {
    return orient ? *orient != glm::quat(1.0f, 0.0f, 0.0f, 0.0f) : rot != glm::vec3(0.0f);
}

}  // namespace

bool flatGroup(const Scene& scene, int g) {
    const Group& group = scene.groups[size_t(g)];
    const int end = groupEnd(scene, g);
    if (end == group.first) return true;  // no members: it adds nothing, wherever it stands
    if (!sharpUnion(group.op, group.blend) || glm::any(group.mirror) ||
        group.repeat != glm::ivec3(1))
        return false;
    for (int i = group.first; i < end; ++i) {
        const Object& o = scene.objects[size_t(i)];
        if (o.group == g && !sharpUnion(o.op, o.blend)) return false;
    }
    for (size_t child = size_t(g) + 1; child < scene.groups.size(); ++child)
        if (scene.groups[child].parent == g && !flatGroup(scene, int(child))) return false;
    return true;
}

bool flatChain(const Scene& scene) {
    for (size_t g = 0; g < scene.groups.size(); ++g)
        if (scene.groups[g].parent < 0 && !flatGroup(scene, int(g))) return false;
    return true;
}

bool frameTurned(const Scene& scene, int g) {
    for (; g >= 0; g = scene.groups[size_t(g)].parent) {
        const Group& group = scene.groups[size_t(g)];
        if (group.dynamic() || ownTurn(group.orient, group.rot)) return true;
    }
    return false;
}

bool moves(const Scene& scene, const Object& o) {
    const int top = topGroupOf(scene, o);
    return o.dynamic() || (top >= 0 && scene.groups[size_t(top)].dynamic());
}

}  // namespace mb
