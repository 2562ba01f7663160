// scene_tree.cpp — which groups flatten into a plain chain (see scene_tree.h).
#include "marchbox/gl/scene_tree.h"

#include <glm/gtc/quaternion.hpp>

namespace mb {

bool sharpUnion(CsgOp op, float blend) { return op == CsgOp::Union && blend <= 0.0f; }

namespace {

bool ownTurn(const std::optional<glm::quat>& orient, glm::vec3 rot) {
    return orient ? *orient != glm::quat(1.0f, 0.0f, 0.0f, 0.0f) : rot != glm::vec3(0.0f);
}

}  // namespace

std::vector<int> groupEnds(const Scene& scene) {
    std::vector<int> end(scene.groups.size());
    for (size_t g = 0; g < scene.groups.size(); ++g) end[g] = scene.groups[g].first;
    for (size_t i = 0; i < scene.objects.size(); ++i)
        for (int g = scene.objects[i].group; g >= 0; g = scene.groups[size_t(g)].parent)
            end[size_t(g)] = int(i) + 1;
    return end;
}

// Children stand after their parents in tree order, so one pass from the last group up sees
// every child before its parent.
std::vector<bool> flatGroups(const Scene& scene) {
    const size_t n = scene.groups.size();
    const std::vector<int> end = groupEnds(scene);
    std::vector<bool> flat(n, true), blocked(n, false);
    for (const Object& o : scene.objects)
        if (o.group >= 0 && !sharpUnion(o.op, o.blend)) blocked[size_t(o.group)] = true;
    for (size_t g = n; g-- > 0;) {
        const Group& group = scene.groups[g];
        if (end[g] == group.first) continue;  // no members: it adds nothing, wherever it stands
        flat[g] = !blocked[g] && sharpUnion(group.op, group.blend) && !glm::any(group.mirror) &&
                  group.repeat == glm::ivec3(1);
        if (!flat[g] && group.parent >= 0) blocked[size_t(group.parent)] = true;
    }
    return flat;
}

bool flatChain(const Scene& scene) {
    for (bool flat : flatGroups(scene))
        if (!flat) return false;
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
