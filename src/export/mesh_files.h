// mesh_files.h — a mesh as the bytes of a binary STL, a Wavefront OBJ and its MTL, or a binary
// PLY with per-vertex colours. Each returns the whole file; the caller writes it atomically.
#pragma once

#include "mesh.h"

#include "marchbox/scene/scene.h"

#include <string>
#include <vector>

namespace mb {

// 80-byte header, the triangle count, then per triangle its unit normal, its three corners
// and a zero attribute word; little-endian floats.
std::string stlBytes(const TriangleMesh& m);

// The OBJ names `mtlFile` (a name beside it) and groups its faces by material, `usemtl NAME`;
// materials[t] is triangle t's index in scene.materials (-1: the first material).
std::string objBytes(const TriangleMesh& m, const std::vector<int>& materials, const Scene& scene,
                     const std::string& mtlFile);
// One `newmtl` per scene material: Kd its colour, Ka and Ks its Ka·colour and Ks, Ns its C.
std::string mtlBytes(const Scene& scene);
// The names objBytes and mtlBytes use: the material's own, made unique where two share one.
std::vector<std::string> materialNames(const Scene& scene);

// x, y, z as floats and red, green, blue as bytes per vertex (colours[i] each 0 to 1), then
// each face as a count and three uint indices.
std::string plyBytes(const TriangleMesh& m, const std::vector<glm::vec3>& colours);

// The colour a point of material m shows: the material's, clamped to 0..1; grey for none.
glm::vec3 materialColour(const Scene& scene, int m);

}  // namespace mb
