// reference_model.h — the pieces of the CPU reference (docs/shading-model.md), shared by
// reference_render.cpp (rays and the image), reference_trace.cpp (geometry: hits, normals,
// shadows, occlusion), reference_shade.cpp (light and mirrors) and reference_sky.cpp (sky, fog).
//
// Everything is in double: the SDF mirror is float, but the distances, hit points and colours
// between its calls need not lose more.
#pragma once

#include "marchbox/reference/reference_render.h"
#include "marchbox/scene/sdf.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace mb::reference {

using glm::dvec3;

struct LightSource {
    bool directional = false;
    dvec3 vec{0.0};     // point: position; directional: unit vector towards the light
    dvec3 radiance{0};  // colour × intensity
};

// The scene prepared once for many rays.
struct Model {
    const Scene* scene = nullptr;
    SceneSdf sdf;
    std::vector<LightSource> lights;
    dvec3 horizon{0.0};  // the horizon's colour, tinted by the brightest light
    double epsilon = 0.001;
    double softness = 8.0;
    double far = 100.0;         // a directional light's shadow rays end here (the GPU's uMaxDist)
    double sampleRadius = 0.0;  // half a sample's width per metre of path (§3); 0 point-samples
};

Model prepareModel(const Scene& scene, const ReferenceOptions& options);

// [reference_trace.cpp] geometry
struct Hit {
    bool hit = false;
    double t = 0.0;
    int object = kHitNone;
};

double field(const Model& m, dvec3 p);  // objects and ground: the scene's SDF
Hit firstHit(const Model& m, dvec3 origin, dvec3 dir);
struct SurfaceNormal {
    dvec3 n{0, 1, 0};
    bool crease = false;  // within a few difference steps of an edge: the normal is a blend
};
SurfaceNormal normalAt(const Model& m, dvec3 p, int object);
dvec3 liftOff(dvec3 p, dvec3 n, double epsilon);  // where secondary rays start
// 0 blocked .. 1 free, towards a light `reach` away; hard or soft as the scene says.
double visibility(const Model& m, dvec3 origin, dvec3 towards, double reach);
double occlusion(const Model& m, dvec3 p, dvec3 n);     // 1 open .. 0 buried
double beyondEverything(const Model& m, dvec3 origin);  // past every object's bounding sphere

// [reference_shade.cpp] light, mirrors
struct PathResult {
    dvec3 color{0.0};
    Hit first;
    uint64_t region = 0;    // see ReferenceImage::region
    bool penumbra = false;  // see ReferenceImage::penumbra
};
PathResult tracePath(const Model& m, dvec3 origin, dvec3 dir);

// [reference_sky.cpp] sky, suns, fog
dvec3 skyHorizon(const Scene& scene);
dvec3 skyColor(const Model& m, dvec3 dir);
dvec3 applyFog(const Model& m, dvec3 color, dvec3 dir, double t);

double smoothstep(double edge0, double edge1, double x);

}  // namespace mb::reference
