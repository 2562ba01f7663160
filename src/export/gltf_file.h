// gltf_file.h — meshes, their materials, the lights and a camera as one binary glTF 2.0 file
// (.glb), still or animated, through TinyGLTF.
//
// Each part is a node with one mesh, one primitive per material (POSITION, NORMAL, indices);
// each scene material used becomes a pbrMetallicRoughness material: base colour the material's
// colour taken from display values to linear ones (the renderer writes its shading to the
// picture as it is, a glTF viewer encodes linear light as sRGB), roughness from the shininess C
// (a Blinn-Phong exponent n ≈ 2/α² − 2 with α = roughness², so roughness = (2/(C+2))^¼),
// not metallic. Lights are KHR_lights_punctual. Animation keys are LINEAR at the given times.
#pragma once

#include "mesh.h"

#include "marchbox/scene/scene.h"
#include "marchbox/scene/sdf.h"

#include <string>
#include <vector>

namespace mb {

struct GltfPart {
    std::string name;
    TriangleMesh mesh;             // in the part's own frame
    std::vector<int> materials;    // per triangle, index in Scene::materials (-1: the first)
    std::vector<Placement> poses;  // the part's frame at each time; empty: the world's
};

struct GltfDocument {
    const Scene* scene = nullptr;  // its materials and lights
    std::vector<GltfPart> parts;
    std::vector<double> times;    // s, one per animation key; empty: no animation
    std::vector<Camera> cameras;  // one per key, or one for a still view; none: no camera
    Box solids;                   // where the solids are: lights aim at, the far plane past
};

std::string glbBytes(const GltfDocument& doc);

// The quaternion (w, x, y, z) that turns a glTF camera (looking down −z, +y up) to look from
// pos at target with +y up, as the renderer's camera does.
glm::quat cameraTurn(const Camera& camera);

}  // namespace mb
