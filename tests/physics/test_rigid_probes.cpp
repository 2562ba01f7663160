// test_rigid_probes.cpp — the sides of cylinders and cones, and the search along them.
#include "rigid_probes.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

using namespace mb;
using glm::dvec3;

// A cylinder's side runs between its rims' centres with its radius; one rounded to half its
// height has rims that meet, and no side between them (a side of length 0 would divide by it).
// Planted: the guard taken out, the disc has a side from (0, 0, 0) to itself.
TEST(RigidProbes, ACylinderHasASideUnlessItsRimsMeet) {
    SdfObject o{};
    o.type = ShapeType::Cylinder;
    o.radius = 0.2f, o.height = 1.0f, o.round = 0.1f;
    const std::optional<Side> side = sideOf(o);
    ASSERT_TRUE(side);
    EXPECT_NEAR(side->from.y, -0.4, 1e-6);
    EXPECT_NEAR(side->to.y, 0.4, 1e-6);
    EXPECT_NEAR(side->radius[0], 0.2, 1e-6);
    o.height = 0.2f;
    EXPECT_FALSE(sideOf(o));
}

// Along a unit side of radius 0.1 (x from 0 to 1), a sphere of radius 0.2 whose centre lies
// 0.35 above x = 0.3 comes nearest at t = 0.3, where F = 0.35 − 0.2 − 0.1 = 0.05: the search
// finds it to kSideStep. The same sphere above x = −0.3 is nearest at the end, the rim's, and
// the search finds nothing; with that end open, the end itself. Planted: the ends' screening
// taken out, the search returns t = kSideStep for the sphere beyond the end.
TEST(RigidProbes, TheSearchFindsWhereASurfaceComesNearestTheSide) {
    Side side{dvec3(0.0), dvec3(1, 0, 0), {0.1, 0.1}};
    auto ball = [](dvec3 centre) {
        return [centre](const dvec3& p) { return glm::length(p - centre) - 0.2; };
    };
    const SideTouch inside = nearestOnSide(ball({0.3, 0.35, 0}), side, 1.0, 1e-9, 1e-6, 0);
    ASSERT_EQ(inside.count, 1);
    EXPECT_NEAR(inside.t[0], 0.3, kSideStep);
    EXPECT_NEAR(inside.least, 0.05, 1e-6);
    EXPECT_EQ(nearestOnSide(ball({-0.3, 0.35, 0}), side, 1.0, 1e-9, 1e-6, 0).count, 0);
    side.open[0] = true;
    const SideTouch end = nearestOnSide(ball({-0.3, 0.35, 0}), side, 1.0, 1e-9, 1e-6, 0);
    ASSERT_EQ(end.count, 1);
    EXPECT_EQ(end.t[0], 0.0);
    // A metre above, F's least is 0.7; the ends' values alone allow 0.33, the ends' secants
    // crossed 0.61: out of a reach of 0.5, searched no further. Planted: no secant bound, and
    // the search goes on to t = 0.3.
    EXPECT_EQ(nearestOnSide(ball({0.3, 1.0, 0}), side, 0.5, 1e-9, 1e-6, 0).count, 0);
}
