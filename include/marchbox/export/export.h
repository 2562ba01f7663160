// marchbox/export/export.h — `marchbox export`: a scene's solids as one closed mesh file, or an
// animated glTF of its run.
//
// [SECTION] Formats
// [SECTION] Settings and result
// [SECTION] Exporting
//
// The solids are every object and group, not the ground plane: the SDF of mapObjects
// (marchbox/scene/sdf.h), meshed on a sparse grid of voxels S wide (default: the solids'
// bounding box's longest side / 256). Every vertex lies within S/2 of the surface; every mesh
// is closed (each edge shared by two triangles) and wound counter-clockwise seen from outside.
// Files are written whole, beside OUT and renamed over it (marchbox/scene/atomic_file.h).
#pragma once

#include "marchbox/physics/physics.h"
#include "marchbox/scene/scene.h"

#include <cstddef>
#include <functional>
#include <string>

namespace mb {

//-----------------------------------------------------------------------------
// [SECTION] Formats
//-----------------------------------------------------------------------------
enum class MeshFormat {
    Stl,  // binary STL
    Obj,  // Wavefront OBJ, its materials in an MTL file beside it
    Ply,  // binary PLY, a colour per vertex
    Glb,  // binary glTF 2.0: a primitive per material, the lights, the camera
};

// OUT's format from its extension, in any case: .stl, .obj, .ply, .glb; false for another.
bool meshFormatOf(const std::string& path, MeshFormat* out);
// The MTL file an OBJ export writes too: OUT with .mtl in place of its extension.
std::string mtlPathFor(const std::string& objPath);

//-----------------------------------------------------------------------------
// [SECTION] Settings and result
//-----------------------------------------------------------------------------
struct ExportSettings {
    double voxel = 0.0;    // m; 0: the default above
    double seconds = 0.0;  // exportScene: simulated first, at the fixed step
    PhysicsSettings physics;
    size_t memoryBudget = 0;     // bytes the grids and meshes may take; 0: half the memory
    std::function<bool()> stop;  // polled between steps and blocks: true ends the run unwritten
    // What the run is doing ("simulating", "meshing") and how far, 0 to 1 (1 once, at its end).
    std::function<void(const char* doing, double done)> progress;
};

// Frames first to last at fps, as `render --frames` plays them: frame k at t = k / fps.
struct ExportFrames {
    int first = 0, last = 0;
    double fps = 30.0;
};

struct ExportResult {
    enum Status { Written, Stopped, Failed };
    Status status = Failed;
    std::string error;     // one line, where Failed: an unwritable file, no solids, too fine
    double voxel = 0.0;    // the voxel used, m
    size_t triangles = 0;  // in all the file's meshes
};

// What an export at `voxel` (0: the default) makes, told before it runs: the voxel, and about
// how many triangles and bytes. The surface is taken as the solids' bounding spheres' (more
// than it is), crossing 3/2 voxel faces a voxel's area on average over its directions, two
// triangles to a face; the grid holds the band about it.
struct ExportEstimate {
    double voxel = 0.0;
    double triangles = 0.0;
    double bytes = 0.0;
};
ExportEstimate estimateExport(const Scene& scene, double voxel);

//-----------------------------------------------------------------------------
// [SECTION] Exporting
//-----------------------------------------------------------------------------
// The scene's solids after `seconds` of simulation, as one mesh in `path`'s format.
ExportResult exportScene(const Scene& scene, const std::string& path, const ExportSettings& s);

// The largest |mapObjects| over the vertices of the mesh exportScene makes of `scene` at `voxel`
// (0: the default) with no simulation, in m: the contract's S/2, measured. Negative where it
// makes none (no solids, too fine for the memory, every solid thinner than a voxel).
double exportVertexError(const Scene& scene, double voxel);

// An animated .glb: the static solids as one node; each dynamic body (object or top-level
// group) meshed once in its own frame (origin at its pos, unturned) as a node moved by its
// simulated pos and turn at every frame; the camera path as an animated camera where the scene
// has keyframes (else the camera, still); the lights. Bodies are meshed as their own solids:
// their op and blend against the rest, which change with every frame, are not kept.
ExportResult exportAnimation(const Scene& scene, const std::string& path,
                             const ExportFrames& frames, const ExportSettings& s);

}  // namespace mb
