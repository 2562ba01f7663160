// gpu_scene.cpp — packing the scene model into the shader's std140 structs.
#include "marchbox/gl/gpu_scene.h"

#include "marchbox/scene/sdf.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace mb {

static void packMatrix(const glm::mat3& m, float (*out)[4]) {
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) out[c][r] = m[c][r];
}

static GpuObject packObject(const SdfObject& s) {
    GpuObject g{};
    g.posBound[0] = s.pos.x, g.posBound[1] = s.pos.y, g.posBound[2] = s.pos.z,
    g.posBound[3] = s.bound;
    g.sizeMinor[0] = s.size.x, g.sizeMinor[1] = s.size.y, g.sizeMinor[2] = s.size.z,
    g.sizeMinor[3] = s.minor;
    g.shape[0] = s.radius, g.shape[1] = s.height, g.shape[2] = s.blend;
    g.info[0] = int32_t(s.type), g.info[1] = int32_t(s.op), g.info[2] = s.material;
    g.detail[0] = s.top, g.detail[1] = s.round, g.detail[2] = s.shell;
    packMatrix(s.toLocal, g.toLocal);
    return g;
}

static GpuGroup packGroup(const SdfGroup& s) {
    GpuGroup g{};
    g.posBound[0] = s.pos.x, g.posBound[1] = s.pos.y, g.posBound[2] = s.pos.z,
    g.posBound[3] = s.bound;
    g.spacing[0] = s.spacing.x, g.spacing[1] = s.spacing.y, g.spacing[2] = s.spacing.z,
    g.spacing[3] = s.copyBound;
    g.blend[0] = s.blend;
    packMatrix(s.toLocal, g.toLocal);
    return g;
}

static GpuLight packLight(const Light& l) {
    glm::vec3 v = l.directional ? -glm::normalize(l.vec) : l.vec;
    glm::vec3 c = l.color * l.intensity;
    return GpuLight{{v.x, v.y, v.z, l.directional ? 1.0f : 0.0f}, {c.x, c.y, c.z, 0.0f}};
}

GpuScene packScene(const Scene& scene) {
    GpuScene g;
    const SceneSdf sdf = makeSceneSdf(scene);  // members in the world, groups' bounds
    g.objects.reserve(sdf.objects.size());
    for (const SdfObject& o : sdf.objects) g.objects.push_back(packObject(o));
    for (const SdfGroup& group : sdf.groups) g.groups.push_back(packGroup(group));
    for (const Material& m : scene.materials)
        g.materials.push_back({{m.color.r, m.color.g, m.color.b, m.Kr}, {m.Ka, m.Kd, m.Ks, m.C}});
    for (bool directional : {false, true})
        for (const Light& l : scene.lights)
            if (l.directional == directional) g.lights.push_back(packLight(l));
    g.dirLights = int(std::count_if(scene.lights.begin(), scene.lights.end(),
                                    [](const Light& l) { return l.directional; }));
    g.pointLights = int(scene.lights.size()) - g.dirLights;
    return g;
}

float maxRayDistance(const Scene& scene) {
    const SceneSdf sdf = makeSceneSdf(scene);
    float far = 100.0f;
    auto reach = [&](glm::vec3 centre, float bound) {
        far = std::max(far, 2.0f * (glm::length(centre - scene.camera.pos) + bound));
    };
    for (const SdfObject& o : sdf.objects) reach(o.pos, o.bound);
    for (const SdfGroup& g : sdf.groups)
        if (g.parent < 0) reach(g.pos, g.bound);
    return far;
}

}  // namespace mb
