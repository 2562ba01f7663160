// marchbox/scene/object_grid.h — a uniform grid over the scene's objects, so that a ray step
// evaluates only the objects near it instead of all of them.
//
// Each cell lists, in file order, the objects whose bounding sphere (grown by the blend radius)
// reaches into it. Within a cell the CSG chain of that list equals the full chain: an object
// k beyond a point changes neither a union nor a subtraction there, and an intersection with
// an object that misses the cell empties everything before it, so the list restarts.
// Objects outside a cell are at least the distance to the cell's boundary away, which caps
// each step (see mapGridAlong in shaders/scene_map.glsl).
#pragma once

#include "marchbox/scene/sdf.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace mb {

struct ObjectGrid {
    glm::vec3 origin{0.0f};  // minimum corner
    glm::vec3 cellSize{1.0f};
    glm::ivec3 dims{0};               // cells per axis; 0 when there are no objects
    std::vector<uint32_t> cellStart;  // cells + 1 prefix sums into items
    std::vector<uint32_t> items;      // object indices

    int cellCount() const { return dims.x * dims.y * dims.z; }
};

constexpr int kGridMaxCellsPerAxis = 64;

// About `objectsPerCell` objects per cell on average, at most kGridMaxCellsPerAxis per axis.
ObjectGrid buildObjectGrid(const SceneSdf& sdf, float objectsPerCell = 1.0f);

// The CSG chain of one cell's objects at p: the twin of mapCell in the shader.
SceneSample mapCell(const SceneSdf& sdf, const ObjectGrid& grid, glm::ivec3 cell, glm::vec3 p);

// Distance from p to the boundary of its cell, the lower bound for every object not listed.
float cellBoundaryDistance(const ObjectGrid& grid, glm::ivec3 cell, glm::vec3 p);

glm::ivec3 gridCellOf(const ObjectGrid& grid, glm::vec3 p);  // clamped into the grid

}  // namespace mb
