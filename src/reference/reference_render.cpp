// reference_render.cpp — the CPU reference's image: the scene prepared once, a ray per sample
// (docs/shading-model.md §1), each sample clamped, then averaged into its pixel (§10).
#include "marchbox/reference/reference_render.h"

#include "marchbox/scene/camera.h"
#include "reference_model.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace mb {

namespace reference {

// The farthest a camera ray looks: twice the farthest reach of an object or of a top-level
// group's bound (which holds its mirrors and copies), and never under 100 m. Only directional
// shadow rays use it; what lies past the objects is ground, handled in closed form. It is the
// GPU's uMaxDist, since a low sun's soft penumbra depends on it (the ground's k·h/t term keeps
// falling along the ray).
static double farDistance(const Scene& scene, const SceneSdf& sdf) {
    double far = 100.0;
    auto reach = [&](glm::vec3 centre, float bound) {
        far = std::max(
            far, 2.0 * (glm::length(dvec3(centre) - dvec3(scene.camera.pos)) + double(bound)));
    };
    for (const SdfObject& o : sdf.objects) reach(o.pos, o.bound);
    for (const SdfGroup& g : sdf.groups)
        if (g.parent < 0) reach(g.pos, g.bound);
    return far;
}

Model prepareModel(const Scene& scene, const ReferenceOptions& options) {
    Model m;
    m.scene = &scene;
    m.sdf = makeSceneSdf(scene);  // members in the world, groups evaluated as a tree
    for (const Light& l : scene.lights) {
        dvec3 v = l.directional ? -glm::normalize(dvec3(l.vec)) : dvec3(l.vec);
        m.lights.push_back({l.directional, v, dvec3(l.color) * double(l.intensity)});
    }
    m.horizon = skyHorizon(scene);
    m.epsilon = scene.render.epsilon;
    m.softness = options.softness;
    m.far = farDistance(scene, m.sdf);
    return m;
}

}  // namespace reference

using reference::dvec3;

namespace {

// The direction through `sample` (pixels from the bottom-left), as camera.h defines it: the
// image's height spans [-1, 1] of the basis's scaled up vector, its width the same per pixel.
dvec3 sampleRay(const CameraBasis& b, double sx, double sy, int width, int height) {
    double u = (2.0 * sx - width) / height, v = (2.0 * sy - height) / height;
    return glm::normalize(dvec3(b.forward) + u * dvec3(b.right) + v * dvec3(b.up));
}

dvec3 clamp01(dvec3 c) { return glm::clamp(c, dvec3(0.0), dvec3(1.0)); }

}  // namespace

ReferenceImage renderReference(const Scene& scene, int width, int height,
                               const ReferenceOptions& options) {
    reference::Model m = reference::prepareModel(scene, options);
    CameraBasis basis = cameraBasis(scene.camera);
    dvec3 eye(basis.pos);
    int aa = std::clamp(options.aa > 0 ? options.aa : scene.render.aa, 1, 4);
    m.sampleRadius = double(glm::length(basis.up)) / (double(height) * aa);  // up: tan(fov/2)
    ReferenceImage img;
    img.width = width, img.height = height;
    img.rgb.resize(size_t(width) * size_t(height));
    img.object.resize(img.rgb.size());
    img.region.resize(img.rgb.size());
    img.penumbra.resize(img.rgb.size());
    for (int row = 0; row < height; ++row)
        for (int x = 0; x < width; ++x) {
            int y = height - 1 - row;  // from the bottom, as gl_FragCoord counts
            dvec3 sum(0.0);
            reference::PathResult centre;
            for (int b = 0; b < aa; ++b)
                for (int a = 0; a < aa; ++a) {
                    dvec3 dir =
                        sampleRay(basis, x + (a + 0.5) / aa, y + (b + 0.5) / aa, width, height);
                    reference::PathResult r = reference::tracePath(m, eye, dir);
                    sum += clamp01(r.color);
                    if (2 * a + 1 == aa && 2 * b + 1 == aa) centre = r;
                }
            // Ids and regions belong to the pixel centre, where the GPU's id view looks; an even
            // aa has no sample there.
            if (aa % 2 == 0)
                centre =
                    reference::tracePath(m, eye, sampleRay(basis, x + 0.5, y + 0.5, width, height));
            size_t i = img.index(x, row);
            img.rgb[i] = glm::vec3(sum / double(aa * aa));
            img.object[i] = centre.first.object;
            img.region[i] = centre.region;
            img.penumbra[i] = centre.penumbra;
        }
    return img;
}

ReferenceSample traceReference(const Scene& scene, dvec3 origin, dvec3 dir,
                               const ReferenceOptions& options) {
    reference::Model m = reference::prepareModel(scene, options);
    reference::PathResult r = reference::tracePath(m, origin, glm::normalize(dir));
    return {r.color, r.first.object, r.first.t};
}

}  // namespace mb
