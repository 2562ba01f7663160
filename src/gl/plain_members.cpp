// plain_members.cpp — which objects rays meet exactly, and the grid the shader walks over them.
#include "marchbox/gl/plain_members.h"

#include "marchbox/gl/scene_tree.h"
#include "marchbox/scene/shapes.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace mb {

namespace {

// One item of the top-level chain: an object, or a group that does not flatten, whole.
struct ChainItem {
    int object = -1;  // its index; -1 for a group, which is never plain
    CsgOp op = CsgOp::Union;
    float blend = 0.0f;
    glm::vec3 pos{0.0f};
    float bound = 0.0f;
    bool moves = false;
};

bool reaches(const ChainItem& later, const ChainItem& earlier) {
    if (later.op == CsgOp::Intersect || later.moves || earlier.moves) return true;
    return glm::length(later.pos - earlier.pos) < later.bound + later.blend + earlier.bound;
}

std::vector<ChainItem> chainItems(const Scene& scene, const SceneSdf& sdf) {
    std::vector<ChainItem> items;
    const std::vector<bool> flat = flatGroups(scene);
    for (size_t i = 0; i < scene.objects.size();) {
        const Object& o = scene.objects[i];
        const int top = topGroupOf(scene, o);
        if (top >= 0 && !flat[size_t(top)]) {
            const Group& g = scene.groups[size_t(top)];
            const SdfGroup& s = sdf.groups[size_t(top)];
            items.push_back({-1, g.op, g.blend, s.pos, s.bound, g.dynamic()});
            i = size_t(s.last);
            continue;
        }
        const SdfObject& s = sdf.objects[i];
        items.push_back({int(i), o.op, o.blend, s.pos, s.bound, moves(scene, o)});
        ++i;
    }
    return items;
}

// intersect.glsl's three texels: (centre, radius), (0, 0, 0, type), the world-to-object
// quaternion. A ball is met from the first alone; other shapes read their sizes from uObjects.
void packShape(const SdfObject& o, float* texels) {
    glm::quat q = glm::quat_cast(o.toLocal);
    const float values[12] = {o.pos.x, o.pos.y, o.pos.z, o.radius,
                              0.0f,    0.0f,    0.0f,    float(int(o.type)),
                              q.x,     q.y,     q.z,     q.w};
    std::copy(values, values + 12, texels);
}

}  // namespace

bool exactlyMet(const Object& o) {
    return shapeRow(o.type).hit != nullptr && o.round <= 0.0f && o.shell <= 0.0f;
}

bool mayBePlain(const Object& o) { return sharpUnion(o.op, o.blend) && exactlyMet(o); }

std::vector<bool> plainMembers(const Scene& scene) {
    std::vector<bool> plain(scene.objects.size());
    const std::vector<ChainItem> items = chainItems(scene, makeSceneSdf(scene));
    for (const ChainItem& item : items)
        if (item.object >= 0)
            plain[size_t(item.object)] = mayBePlain(scene.objects[size_t(item.object)]);
    for (size_t j = 0; j < items.size(); ++j) {
        if (sharpUnion(items[j].op, items[j].blend)) continue;
        for (size_t i = 0; i < j; ++i)
            if (items[i].object >= 0 && plain[size_t(items[i].object)] &&
                reaches(items[j], items[i]))
                plain[size_t(items[i].object)] = false;
    }
    return plain;
}

Box membersBounds(const SceneSdf& sdf, const std::vector<bool>& plain, bool plainOnes) {
    SceneSdf part;
    std::vector<bool> groupAdded(sdf.groups.size(), false);
    for (size_t i = 0; i < sdf.objects.size(); ++i) {
        if (plain[i] != plainOnes) continue;
        SdfObject o = sdf.objects[i];
        if (o.group >= 0) {  // its top-level group's reach, as one object
            int top = o.group;
            while (sdf.groups[size_t(top)].parent >= 0) top = sdf.groups[size_t(top)].parent;
            if (groupAdded[size_t(top)]) continue;
            groupAdded[size_t(top)] = true;
            const SdfGroup& g = sdf.groups[size_t(top)];
            o.pos = g.pos, o.bound = g.bound, o.blend = g.blend, o.group = -1;
        }
        part.objects.push_back(o);
    }
    return objectBounds(part);
}

PlainGrid buildPlainGrid(const SceneSdf& sdf, const std::vector<bool>& plain) {
    PlainGrid g;
    SceneSdf members;
    std::vector<uint32_t> index;
    g.shapes.assign(12 * std::max<size_t>(sdf.objects.size(), 1), 0.0f);
    for (size_t i = 0; i < sdf.objects.size(); ++i) {
        g.shapes[12 * i + 7] = -1.0f;  // not a member, until packed
        if (!plain[i]) continue;
        members.objects.push_back(sdf.objects[i]);
        members.objects.back().group = -1;  // a plain member is a world object of a flat chain
        index.push_back(uint32_t(i));
        packShape(sdf.objects[i], &g.shapes[12 * i]);
    }
    g.grid = buildObjectGrid(members);
    for (uint32_t& item : g.grid.items) item = index[item];
    return g;
}

}  // namespace mb
