// mesh.h — a closed triangle mesh of a scene's solids, and the materials on it.
//
// [SECTION] The mesh
// [SECTION] Meshing an SDF: a narrow band on a sparse grid, meshed by OpenVDB
// [SECTION] Materials on the surface
//
// The SDF (mapObjects: every object and group, not the ground plane) is sampled only where the
// surface may be. A block of voxels whose centre is at least its half-diagonal (plus the band)
// from the surface holds no surface and no band voxel, whether the SDF is exact or a bound, so
// the sampler skips it whole and recurses, top-down, only into the rest. The band's voxels go
// into an OpenVDB level set (sparse: only 8³ leaves near the surface are stored), which
// openvdb::tools::volumeToMesh turns into quads at adaptivity 0: one vertex in each voxel
// cell the surface crosses, at the mean of its edge crossings.
#pragma once

#include "marchbox/scene/sdf.h"

#include <cstddef>
#include <functional>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace mb {

//-----------------------------------------------------------------------------
// [SECTION] The mesh
//-----------------------------------------------------------------------------
struct TriangleMesh {
    std::vector<glm::vec3> points;
    std::vector<glm::uvec3> triangles;  // counter-clockwise seen from outside: normals outward
    bool empty() const { return triangles.empty(); }
};

glm::vec3 faceNormal(const TriangleMesh& m, size_t t);  // unit, outward; 0 for a sliver
// Unit, area-weighted over the triangles around each point (0,1,0 where they cancel).
std::vector<glm::vec3> pointNormals(const TriangleMesh& m);
double meshVolume(const TriangleMesh& m);  // divergence theorem: > 0 when normals point out
// The farthest any vertex lies from the surface: the largest |distance(p)| over m.points, m.
float largestVertexError(const TriangleMesh& m, const std::function<float(glm::vec3)>& distance);
// The same by the scene's SDF, mapObjects(sdf, p).d: the error itself where that is exact, and
// where it is a bound (blends, subtractions), no more than the error.
float largestVertexError(const SceneSdf& sdf, const TriangleMesh& m);

//-----------------------------------------------------------------------------
// [SECTION] Meshing an SDF
//-----------------------------------------------------------------------------
struct MeshSettings {
    double voxel = 0.0;          // edge of a voxel, m; 0: defaultVoxel
    size_t memoryBudget = 0;     // bytes the grid and mesh may take; 0: half the physical memory
    std::function<bool()> stop;  // polled between blocks: true ends the run
    std::function<void(double done)> progress;  // the band sampled so far, 0 to 1
};

// The solids' bounding box's longest side / 256 (objectBounds); 0 when there are no solids.
float defaultVoxel(const SceneSdf& sdf);

enum class MeshStatus {
    Ok,        // *out holds the mesh (empty where every solid is thinner than a voxel)
    Stopped,   // stop() said so; *out is empty
    TooLarge,  // the grid would not fit in the memory budget; *why says how much it needs
};

MeshStatus meshSdf(const SceneSdf& sdf, const MeshSettings& settings, TriangleMesh* out,
                   std::string* why);

// The band half-width in voxels: each corner of a cell the surface crosses lies within √3 voxels
// of it, and the mesher reads those corners; 3 is OpenVDB's own level-set default.
constexpr float kBandVoxels = 3.0f;

//-----------------------------------------------------------------------------
// [SECTION] Materials on the surface
//-----------------------------------------------------------------------------
// The material the renderer shades at p: mapObjects(...).object → its material; -1 for none.
int materialAt(const Scene& scene, const SceneSdf& sdf, glm::vec3 p);
std::vector<int> pointMaterials(const Scene& scene, const SceneSdf& sdf, const TriangleMesh& m);
// Each triangle's, at its centroid (a triangle that straddles two objects takes the one there).
std::vector<int> triangleMaterials(const Scene& scene, const SceneSdf& sdf, const TriangleMesh& m);

}  // namespace mb
