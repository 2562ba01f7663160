// marchbox/reference/reference_render.h — the CPU reference: a scene shaded on the CPU, with no GL,
// from docs/shading-model.md. It is written from that model and the SDF mirror, not from the GLSL,
// so a bug the shaders share cannot also hide here. One thread, double precision: 5 to 230 ms
// for a 96x54 image of an example scene. For tests and checks, not for the editor.
//
// [SECTION] Options
// [SECTION] Images
// [SECTION] Single rays, for closed-form tests
#pragma once

#include "marchbox/scene/scene.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace mb {

//-----------------------------------------------------------------------------
// [SECTION] Options
//-----------------------------------------------------------------------------
// Renderer knobs the scene file does not hold. The defaults are the GPU renderer's.
struct ReferenceOptions {
    float softness = 8.0f;  // soft-shadow k, as RenderQuality::softness: penumbra ~ distance / k
    int aa = 0;             // samples per pixel per axis; 0 takes the scene's `aa`
};

//-----------------------------------------------------------------------------
// [SECTION] Images
//-----------------------------------------------------------------------------
struct ReferenceImage {
    int width = 0, height = 0;
    std::vector<glm::vec3> rgb;  // linear colour, each channel clamped to [0, 1]; row 0 at the top
    std::vector<int> object;  // primary ray at the pixel centre: object index, kHitGround, kHitNone
    // Pixels with equal keys see the same surfaces, checker squares, lit sides and hard-shadow
    // states along the whole path, reflections included, and none of them on a crease (where
    // the normal is an edge's blend): the colour is smooth between them. A 3x3 block of one key
    // holds no edge, so a comparison there need not allow for a pixel's shift.
    std::vector<uint64_t> region;
    // 1 where a soft shadow along the path is partly lit. The GPU estimates the penumbra from
    // its march samples (Quilez's improved estimate); the reference takes the converged minimum.
    std::vector<uint8_t> penumbra;

    size_t index(int x, int row) const { return size_t(row) * size_t(width) + size_t(x); }
    glm::vec3 color(int x, int row) const { return rgb[index(x, row)]; }
    int objectAt(int x, int row) const { return object[index(x, row)]; }
    uint64_t regionAt(int x, int row) const { return region[index(x, row)]; }
    bool penumbraAt(int x, int row) const { return penumbra[index(x, row)] != 0; }
};

// Pixels count from the bottom-left like gl_FragCoord; a sample of pixel (i, j) sits at
// (i + (a + 0.5) / aa, j + (b + 0.5) / aa), as the GPU's supersampling passes place theirs.
// Each sample is clamped before the samples are averaged, as the GPU's blended passes are.
ReferenceImage renderReference(const Scene& scene, int width, int height,
                               const ReferenceOptions& options = {});

//-----------------------------------------------------------------------------
// [SECTION] Single rays
//-----------------------------------------------------------------------------
struct ReferenceSample {
    glm::dvec3 color{0.0};  // before the clamp to [0, 1]
    int object = -2;        // what the ray hit first: object index, kHitGround, kHitNone (sdf.h)
    double t = 0.0;         // distance to that hit along the unit direction
};

// One ray through the scene, reflections, shadows and fog included. Prepares the scene on each
// call: for tests of single pixels, not for images.
ReferenceSample traceReference(const Scene& scene, glm::dvec3 origin, glm::dvec3 dir,
                               const ReferenceOptions& options = {});

}  // namespace mb
