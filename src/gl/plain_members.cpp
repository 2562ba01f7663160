// plain_members.cpp — which objects rays meet exactly, and the grid the shader walks over them.
#include "marchbox/gl/plain_members.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace mb {

namespace {

bool sharpUnion(const Object& o) { return o.op == CsgOp::Union && o.blend <= 0.0f; }

bool reaches(const Object& later, const SdfObject& l, const Object& earlier, const SdfObject& e) {
    if (later.op == CsgOp::Intersect || later.dynamic() || earlier.dynamic()) return true;
    return glm::length(l.pos - e.pos) < objectReach(l) + e.bound;
}

// intersect.glsl's three texels: (centre, radius or major radius), (half-extents, or height and
// tube radius; type), the world-to-object quaternion.
void packShape(const SdfObject& o, float* texels) {
    bool box = o.type == ShapeType::Box;
    glm::vec3 b = box ? o.size : glm::vec3(o.height, o.minor, 0.0f);
    glm::quat q = glm::quat_cast(o.toLocal);
    const float values[12] = {
        o.pos.x, o.pos.y, o.pos.z, o.radius, b.x, b.y, b.z, float(int(o.type)), q.x, q.y, q.z, q.w};
    std::copy(values, values + 12, texels);
}

}  // namespace

std::vector<bool> plainMembers(const Scene& scene) {
    size_t n = scene.objects.size();
    std::vector<bool> plain(n);
    std::vector<SdfObject> sdf;
    sdf.reserve(n);
    for (size_t i = 0; i < n; ++i) {
        plain[i] = sharpUnion(scene.objects[i]);
        sdf.push_back(makeSdfObject(scene.objects[i]));
    }
    for (size_t j = 0; j < n; ++j) {
        if (sharpUnion(scene.objects[j])) continue;
        for (size_t i = 0; i < j; ++i)
            if (plain[i] && reaches(scene.objects[j], sdf[j], scene.objects[i], sdf[i]))
                plain[i] = false;
    }
    return plain;
}

Box membersBounds(const SceneSdf& sdf, const std::vector<bool>& plain, bool plainOnes) {
    SceneSdf part;
    for (size_t i = 0; i < sdf.objects.size(); ++i)
        if (plain[i] == plainOnes) part.objects.push_back(sdf.objects[i]);
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
        index.push_back(uint32_t(i));
        packShape(sdf.objects[i], &g.shapes[12 * i]);
    }
    g.grid = buildObjectGrid(members);
    for (uint32_t& item : g.grid.items) item = index[item];
    return g;
}

}  // namespace mb
