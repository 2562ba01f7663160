// marchbox/gl/gpu_scene.h — the scene as the shader reads it: std140 blocks, packed on the CPU.
//
// Each struct mirrors one in shaders/scene_data.glsl field for field. std140 puts vec4s at
// 16-byte offsets and a mat3 as three vec4 columns, so plain float[4] rows reproduce it;
// tests/gl/test_std140.cpp checks every offset against what the driver reports.
#pragma once

#include "marchbox/scene/scene.h"

#include <cstdint>
#include <vector>

namespace mb {

struct GpuObject {
    float posBound[4];    // centre xyz, bounding-sphere radius
    float sizeMinor[4];   // box half-extents xyz, torus tube radius
    float shape[4];       // radius, height, blend, unused
    int32_t info[4];      // type, op, material, unused
    float detail[4];      // cone's top radius, edge radius (round), wall thickness (shell), unused
    float toLocal[3][4];  // mat3 world→local, column-major, each column padded to a vec4
};
static_assert(sizeof(GpuObject) == 128, "std140 Object is 128 bytes");

// A group of the compiled tree (gl/scene_compiler.h), from makeSceneSdf's SdfGroup.
struct GpuGroup {
    float posBound[4];    // origin xyz in the world, bound of its whole shape (every copy)
    float spacing[4];     // between copies xyz; w: bound of one copy's shape
    float blend[4];       // smooth-blend radius of its join, unused
    float toLocal[3][4];  // mat3 world→group frame, column-major, each column padded to a vec4
};
static_assert(sizeof(GpuGroup) == 96, "std140 Group is 96 bytes");

struct GpuMaterial {
    float color[4];   // r g b, Kr
    float coeffs[4];  // Ka Kd Ks C
};
static_assert(sizeof(GpuMaterial) == 32, "std140 Material is 32 bytes");

struct GpuLight {
    float vec[4];    // point: position; directional: unit vector towards the light
    float color[4];  // rgb × intensity, unused
};
static_assert(sizeof(GpuLight) == 32, "std140 Light is 32 bytes");

struct GpuScene {
    std::vector<GpuObject> objects;  // in the world: a member's place composed with its groups'
    std::vector<GpuGroup> groups;
    std::vector<GpuMaterial> materials;
    std::vector<GpuLight> lights;  // point lights first, then directional ones
    int pointLights = 0, dirLights = 0;
};

GpuScene packScene(const Scene& scene);

// Far end of every ray: twice the farthest reach from the camera (of an object, or of a
// top-level group's bound, which holds its mirrors and copies), and never under 100 m.
float maxRayDistance(const Scene& scene);

}  // namespace mb
