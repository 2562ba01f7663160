// test_object_grid.cpp — a grid cell's object list gives the scene's surface inside the cell.
#include "marchbox/scene/object_grid.h"

#include <gtest/gtest.h>
#include <random>

using namespace mb;
using glm::vec3;

namespace {

Scene randomScene(std::mt19937& rng, int count) {
    std::uniform_real_distribution<float> pos(-4, 4), size(0.1f, 0.8f), unit(0, 1);
    Scene s;
    s.materials.push_back({});
    for (int i = 0; i < count; ++i) {
        Object o;
        // The exact shapes: an ellipsoid's bound may read below what the cell's list gives,
        // though its surface is as far as the grid assumes.
        o.type = ShapeType(i % int(ShapeType::Cone));
        o.pos = {pos(rng), pos(rng) * 0.5f, pos(rng)};
        o.radius = size(rng);
        o.size = {size(rng), size(rng), size(rng)};
        o.minor = 0.5f * o.radius;
        o.height = size(rng);
        o.rot = {pos(rng) * 20, pos(rng) * 20, 0};
        float r = unit(rng);
        o.op = r < 0.7f ? CsgOp::Union : r < 0.92f ? CsgOp::Subtract : CsgOp::Intersect;
        o.blend = unit(rng) < 0.3f ? 0.2f * unit(rng) : 0.0f;
        s.objects.push_back(o);
    }
    return s;
}

}  // namespace

// Inside a cell the list's chain has the full chain's sign, and capped by the distance to the
// cell's boundary it never exceeds the full distance: sphere tracing with it is safe.
TEST(ObjectGrid, CellChainKeepsSignAndBoundsTheDistance) {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 20; ++trial) {
        SceneSdf sdf = makeSceneSdf(randomScene(rng, 40));
        ObjectGrid grid = buildObjectGrid(sdf, 1.0f);
        ASSERT_GT(grid.cellCount(), 1);
        std::uniform_real_distribution<float> u(0, 1);
        for (int i = 0; i < 2000; ++i) {
            vec3 p = grid.origin + vec3(u(rng), u(rng), u(rng)) * vec3(grid.dims) * grid.cellSize;
            glm::ivec3 cell = gridCellOf(grid, p);
            float full = mapObjects(sdf, p).d, part = mapCell(sdf, grid, cell, p).d;
            if (std::abs(full) > 1e-4f) {
                ASSERT_EQ(full > 0, part > 0) << "trial " << trial << " point " << i;
            }
            if (full > 0) {
                ASSERT_LE(std::min(part, cellBoundaryDistance(grid, cell, p)), full + 1e-4f);
            }
        }
    }
}

TEST(ObjectGrid, SpreadsManyObjectsThinly) {
    Scene s;
    s.materials.push_back({});
    for (int i = 0; i < 4096; ++i) {
        Object o;
        o.pos = {float(i % 64), 0.4f, float(i / 64)};
        o.radius = 0.4f;
        s.objects.push_back(o);
    }
    ObjectGrid grid = buildObjectGrid(makeSceneSdf(s), 1.0f);
    size_t most = 0;
    for (int c = 0; c < grid.cellCount(); ++c)
        most = std::max<size_t>(most, grid.cellStart[c + 1] - grid.cellStart[c]);
    EXPECT_LE(most, 16u) << "a step should visit a handful of spheres, not thousands";
    EXPECT_EQ(grid.cellStart.back(), grid.items.size());
}

TEST(ObjectGrid, EmptySceneHasNoCells) { EXPECT_EQ(buildObjectGrid(SceneSdf{}).cellCount(), 0); }
