// scene_parts.cpp — copying a scene's top-level items, and their members, into a new scene.
#include "scene_parts.h"

#include <functional>

namespace mb {

namespace {

int topOf(const Scene& scene, int g) {
    while (scene.groups[size_t(g)].parent >= 0) g = scene.groups[size_t(g)].parent;
    return g;
}

// The scene with only the top-level items `keep` says yes to, with their members: objects
// and groups keep their tree order, and the group indices are renumbered.
Scene keepTopLevel(const Scene& scene, const std::function<bool(BodyRef)>& keep) {
    Scene out = scene;
    out.objects.clear();
    out.groups.clear();
    std::vector<int> newGroup(scene.groups.size(), -1);
    for (size_t g = 0; g < scene.groups.size(); ++g)
        if (keep({true, topOf(scene, int(g))})) {
            newGroup[g] = int(out.groups.size());
            out.groups.push_back(scene.groups[g]);
        }
    // kept[i]: how many kept objects come before object i, the new index of a group's `first`.
    std::vector<int> before(scene.objects.size() + 1, 0);
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        const bool kept = o.group < 0 ? keep({false, int(i)}) : newGroup[size_t(o.group)] >= 0;
        before[i + 1] = before[i] + (kept ? 1 : 0);
        if (!kept) continue;
        out.objects.push_back(o);
        out.objects.back().group = o.group < 0 ? -1 : newGroup[size_t(o.group)];
    }
    for (size_t g = 0; g < scene.groups.size(); ++g) {
        if (newGroup[g] < 0) continue;
        Group& group = out.groups[size_t(newGroup[g])];
        group.first = before[size_t(scene.groups[g].first)];
        group.parent = group.parent < 0 ? -1 : newGroup[size_t(group.parent)];
    }
    return out;
}

bool isBody(const Scene& scene, BodyRef b) {
    return b.group ? scene.groups[size_t(b.index)].dynamic()
                   : scene.objects[size_t(b.index)].dynamic();
}

}  // namespace

std::vector<BodyRef> dynamicBodies(const Scene& scene) {
    // Tree order: a top-level group stands just before objects[first].
    std::vector<BodyRef> bodies;
    size_t g = 0;
    for (size_t i = 0; i <= scene.objects.size(); ++i) {
        for (; g < scene.groups.size() && scene.groups[g].first <= int(i); ++g)
            if (scene.groups[g].dynamic()) bodies.push_back({true, int(g)});
        if (i < scene.objects.size() && scene.objects[i].dynamic())
            bodies.push_back({false, int(i)});
    }
    return bodies;
}

std::string bodyName(const Scene& scene, BodyRef body) {
    if (body.group) return scene.groups[size_t(body.index)].name;
    const Object& o = scene.objects[size_t(body.index)];
    return o.name.empty() ? std::string(shapeTypeName(o.type)) + " " + std::to_string(body.index)
                          : o.name;
}

Placement bodyPose(const Scene& scene, BodyRef body) {
    if (body.group) {
        const Group& g = scene.groups[size_t(body.index)];
        return {g.pos, g.orientation()};
    }
    const Object& o = scene.objects[size_t(body.index)];
    return {o.pos, o.orientation()};
}

Scene staticPart(const Scene& scene) {
    return keepTopLevel(scene, [&](BodyRef b) { return !isBody(scene, b); });
}

Scene bodyAtOrigin(const Scene& scene, BodyRef body) {
    Scene out = keepTopLevel(
        scene, [&](BodyRef b) { return b.group == body.group && b.index == body.index; });
    auto place = [](auto& item) {
        item.pos = glm::vec3(0.0f);
        item.rot = glm::vec3(0.0f);
        item.orient.reset();
        item.op = CsgOp::Union;
        item.blend = 0.0f;
    };
    if (body.group) place(out.groups.front());
    else place(out.objects.front());
    return out;
}

}  // namespace mb
