// object_grid.cpp — building the uniform object grid and evaluating one of its cells.
#include "marchbox/scene/object_grid.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace mb {

namespace {

bool sphereTouchesCell(const ObjectGrid& g, glm::ivec3 c, glm::vec3 centre, float radius) {
    glm::vec3 lo = g.origin + glm::vec3(c) * g.cellSize, hi = lo + g.cellSize;
    glm::vec3 nearest = glm::clamp(centre, lo, hi);
    return glm::length(centre - nearest) <= radius;
}

int cellIndex(const ObjectGrid& g, glm::ivec3 c) { return (c.z * g.dims.y + c.y) * g.dims.x + c.x; }

void sizeGrid(ObjectGrid* g, const Box& b, size_t objects, float objectsPerCell) {
    glm::vec3 extent = glm::max(b.hi - b.lo, glm::vec3(1e-6f));
    float cells = std::max(1.0f, float(objects) / objectsPerCell);
    // Cubic cells whose count matches `cells` for this extent; flat scenes get one layer.
    float side = std::cbrt(extent.x * extent.y * extent.z / cells);
    for (int a = 0; a < 3; ++a)
        g->dims[a] =
            std::clamp(int(std::ceil(extent[a] / std::max(side, 1e-6f))), 1, kGridMaxCellsPerAxis);
    g->origin = b.lo;
    g->cellSize = extent / glm::vec3(g->dims);
}

// An intersection keeps only its overlap: in the cells it misses, nothing before it is left.
void addIntersection(const ObjectGrid& g, const SdfObject& o, uint32_t i,
                     std::vector<std::vector<uint32_t>>* lists) {
    for (int z = 0; z < g.dims.z; ++z)
        for (int y = 0; y < g.dims.y; ++y)
            for (int x = 0; x < g.dims.x; ++x) {
                auto& list = (*lists)[size_t(cellIndex(g, {x, y, z}))];
                if (sphereTouchesCell(g, {x, y, z}, o.pos, objectReach(o))) list.push_back(i);
                else list.clear();
            }
}

}  // namespace

ObjectGrid buildObjectGrid(const SceneSdf& sdf, float objectsPerCell) {
    ObjectGrid g;
    if (sdf.objects.empty()) return g;
    sizeGrid(&g, objectBounds(sdf), sdf.objects.size(), objectsPerCell);
    std::vector<std::vector<uint32_t>> lists(size_t(g.cellCount()));
    for (uint32_t i = 0; i < sdf.objects.size(); ++i) {
        const SdfObject& o = sdf.objects[i];
        if (o.op == CsgOp::Intersect) {
            addIntersection(g, o, i, &lists);
            continue;
        }
        glm::ivec3 lo = gridCellOf(g, o.pos - objectReach(o)),
                   hi = gridCellOf(g, o.pos + objectReach(o));
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x)
                    if (sphereTouchesCell(g, {x, y, z}, o.pos, objectReach(o)))
                        lists[size_t(cellIndex(g, {x, y, z}))].push_back(i);
    }
    g.cellStart.reserve(lists.size() + 1);
    for (const auto& l : lists) {
        g.cellStart.push_back(uint32_t(g.items.size()));
        g.items.insert(g.items.end(), l.begin(), l.end());
    }
    g.cellStart.push_back(uint32_t(g.items.size()));
    return g;
}

glm::ivec3 gridCellOf(const ObjectGrid& g, glm::vec3 p) {
    glm::ivec3 c(glm::floor((p - g.origin) / g.cellSize));
    return glm::clamp(c, glm::ivec3(0), g.dims - 1);
}

SceneSample mapCell(const SceneSdf& sdf, const ObjectGrid& g, glm::ivec3 cell, glm::vec3 p) {
    SceneSdf subset;
    int c = cellIndex(g, cell);
    std::vector<int> index;
    for (uint32_t k = g.cellStart[size_t(c)]; k < g.cellStart[size_t(c) + 1]; ++k) {
        subset.objects.push_back(sdf.objects[g.items[k]]);
        index.push_back(int(g.items[k]));
    }
    SceneSample s = mapObjects(subset, p);
    if (s.object >= 0) s.object = index[size_t(s.object)];
    return s;
}

float cellBoundaryDistance(const ObjectGrid& g, glm::ivec3 cell, glm::vec3 p) {
    glm::vec3 lo = g.origin + glm::vec3(cell) * g.cellSize, hi = lo + g.cellSize;
    glm::vec3 d = glm::min(p - lo, hi - p);
    return std::max(0.0f, std::min(d.x, std::min(d.y, d.z)));
}

}  // namespace mb
