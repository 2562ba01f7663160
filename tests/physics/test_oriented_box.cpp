// test_oriented_box.cpp — the boxes that cull contact probes (oriented_box.h), and the parts of
// a group that bound its distance from below (unionParts), against closed forms.
#include "group_body.h"
#include "oriented_box.h"

#include "marchbox/scene/scene_io.h"
#include "marchbox/scene/sdf.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

using namespace mb;
using glm::dquat;
using glm::dvec3;

namespace {

// Half extents (1, 2, 3) about (1, 0, 0), turned by `degrees` about z.
OrientedBox turnedBox(double degrees) {
    const dquat turn = glm::angleAxis(glm::radians(degrees), dvec3(0, 0, 1));
    return placed({dvec3(0.0), glm::dmat3(1.0), dvec3(1, 2, 3)}, turn, dvec3(1, 0, 0));
}

GroupShape shapeOf(const std::string& members) {
    Scene s;
    std::vector<SceneError> errors;
    EXPECT_TRUE(
        parseScene("scene version:3\nmaterial r:0.8 g:0.8 b:0.8\n"
                   "group name:g pos:0,0,0 mass:1\n" +
                       members,
                   &s, &errors));
    return groupShapeOf(s, 0);
}

// The report's table: a box top on four cylinder legs.
const char* kTable =
    "object in:g type:box material:0 pos:0,0.72,0 size:0.5,0.03,0.35\n"
    "object in:g type:cylinder material:0 pos:0.42,0.345,0.27 radius:0.03 height:0.69\n"
    "object in:g type:cylinder material:0 pos:-0.42,0.345,0.27 radius:0.03 height:0.69\n"
    "object in:g type:cylinder material:0 pos:0.42,0.345,-0.27 radius:0.03 height:0.69\n"
    "object in:g type:cylinder material:0 pos:-0.42,0.345,-0.27 radius:0.03 height:0.69\n";

}  // namespace

// Turned 30° about z: a point 3 out along the box's x axis is 3 − 1 from its face; one beyond
// a corner by (1, 2, 2) in the box's axes is 3 from it; the centre is inside.
TEST(OrientedBox, DistanceInTheBoxsOwnAxes) {
    const OrientedBox b = turnedBox(30.0);
    EXPECT_NEAR(distanceToBox(b, b.centre + 3.0 * b.axes[0]), 2.0, 1e-12);
    const dvec3 corner = b.centre + b.axes * dvec3(2, 4, 5);
    EXPECT_NEAR(distanceToBox(b, corner), 3.0, 1e-12);
    EXPECT_EQ(distanceToBox(b, b.centre), 0.0);
}

// Turned 90° about z, the box spans x ± 2 (its y half) and y ± 1: with a cube of half 0.5 at (−3,
// 0, 0) the world box around both runs from −3.5 to 3 in x.
TEST(OrientedBox, BoxAroundHoldsTurnedBoxes) {
    const OrientedBox around =
        boxAround({turnedBox(90.0), {dvec3(-3, 0, 0), glm::dmat3(1.0), dvec3(0.5)}});
    EXPECT_NEAR(around.centre.x, -0.25, 1e-12);
    EXPECT_NEAR(around.half.x, 3.25, 1e-12);
    EXPECT_NEAR(around.half.y, 1.0, 1e-12);
    EXPECT_NEAR(around.half.z, 3.0, 1e-12);
}

// A cube (half 0.5) turned 45° about z points a corner at an unturned one 1.5 away: the gap
// between them is 1.5 − 0.5 − √2/2 (0.2929), so they are apart for any slack above −0.2929.
TEST(OrientedBox, OverlapWithNegativeSlackAsksForAGap) {
    const OrientedBox a{dvec3(0.0), glm::dmat3(1.0), dvec3(0.5)};
    const OrientedBox b = placed(a, glm::angleAxis(M_PI / 4.0, dvec3(0, 0, 1)), dvec3(1.5, 0, 0));
    const double gap = 1.0 - std::sqrt(0.5);
    EXPECT_FALSE(boxesOverlap(a, b, -(gap - 1e-9)));
    EXPECT_TRUE(boxesOverlap(a, b, -(gap + 1e-9)));
    EXPECT_TRUE(boxesOverlap(a, placed(a, dquat(1, 0, 0, 0), dvec3(0.9, 0, 0)), 0.0));
}

// The same two cubes are parted along a's x axis, a face's normal, so facesOverlap sees the gap
// as boxesOverlap does, from either box. A cube turned 45° about x has an edge along x on top;
// one turned 45° about z, 1 cm over it, an edge along z below: the edges cross, and only their
// cross (y) parts the cubes, which facesOverlap leaves out.
TEST(OrientedBox, FacesOverlapSeesTheGapAlongAFaceNormal) {
    const OrientedBox a{dvec3(0.0), glm::dmat3(1.0), dvec3(0.5)};
    const OrientedBox b = placed(a, glm::angleAxis(M_PI / 4.0, dvec3(0, 0, 1)), dvec3(1.5, 0, 0));
    const double gap = 1.0 - std::sqrt(0.5);
    for (const bool flip : {false, true}) {
        const OrientedBox &first = flip ? b : a, &second = flip ? a : b;
        EXPECT_FALSE(facesOverlap(first, second, gap - 1e-9));
        EXPECT_TRUE(facesOverlap(first, second, gap + 1e-9));
    }
    const OrientedBox under = placed(a, glm::angleAxis(M_PI / 4.0, dvec3(1, 0, 0)), dvec3(0.0));
    const OrientedBox over = placed(a, glm::angleAxis(M_PI / 4.0, dvec3(0, 0, 1)),
                                    dvec3(0.0, std::sqrt(2.0) + 0.01, 0.0));
    EXPECT_FALSE(boxesOverlap(under, over, 0.0));
    EXPECT_TRUE(facesOverlap(under, over, 0.0));
}

// Boxes of three unequal halves whose edges cross at 50°: one (0.8, 0.4, 0.6) turned 30° about x
// and then 40° about y has a level top edge 0.4·cos 30° + 0.6·sin 30° over its centre; one (0.3,
// 0.7, 0.9) turned 60° about z, a bottom edge along z 0.3·sin 60° + 0.7·cos 60° under its own,
// which is set over the first's so that the edges cross 2 cm apart. Only the edges' cross (y)
// parts them, and boxesOverlap sees exactly that gap: each box's reach along the cross comes from
// its two other axes, which differ, and the cross is shorter than a unit.
TEST(OrientedBox, CrossedEdgesOfUnequalBoxesPartThemByTheirGap) {
    const double gap = 0.02, lowTop = 0.4 * std::cos(M_PI / 6) + 0.6 * std::sin(M_PI / 6);
    const double highBottom = 0.3 * std::sin(M_PI / 3) + 0.7 * std::cos(M_PI / 3);
    const double edgeX = 0.7 * std::sin(M_PI / 3) - 0.3 * std::cos(M_PI / 3);  // of its centre
    const dquat lowTurn = glm::angleAxis(glm::radians(40.0), dvec3(0, 1, 0)) *
                          glm::angleAxis(M_PI / 6, dvec3(1, 0, 0));
    const OrientedBox low =
        placed({dvec3(0.0), glm::dmat3(1.0), dvec3(0.8, 0.4, 0.6)}, lowTurn, dvec3(0.0));
    const OrientedBox high = placed({dvec3(0.0), glm::dmat3(1.0), dvec3(0.3, 0.7, 0.9)},
                                    glm::angleAxis(M_PI / 3, dvec3(0, 0, 1)),
                                    dvec3(-edgeX, lowTop + highBottom + gap, 0.0));
    ASSERT_TRUE(facesOverlap(low, high, gap + 1e-9));
    for (const bool flip : {false, true}) {
        const OrientedBox &first = flip ? high : low, &second = flip ? low : high;
        EXPECT_FALSE(boxesOverlap(first, second, -(gap - 1e-9)));
        EXPECT_TRUE(boxesOverlap(first, second, -(gap + 1e-9)));
    }
}

// A group's members have float turns, whose axes are out of square by about 6e-8. Two boxes of
// one turn, given as (10°, 20°, 30°) and as (10°, 20°, 390°), have nearly parallel edges: they
// lie along the same axes and overlap wherever their centres are nearer along each than the sum
// of their halves. Within 99 % of that, none may come out apart with the slack the group's mass
// takes (1e-6). Planted: the edges' reaches taken from the turn between the boxes: 488 of the
// 20,000 placements called apart.
TEST(OrientedBox, BoxesOfFloatTurnsThatOverlapAreNotApart) {
    const dvec3 halfA(0.5, 0.1, 0.3), halfB(0.2, 0.4, 0.25);
    const OrientedBox a{dvec3(0.0), glm::dmat3(rotationFromEuler(glm::vec3(10, 20, 30))), halfA};
    const glm::dmat3 turn(rotationFromEuler(glm::vec3(10, 20, 390)));
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-0.99, 0.99);
    int apart = 0;
    for (int i = 0; i < 20000; ++i) {
        const dvec3 offset = a.axes * ((halfA + halfB) * dvec3(u(rng), u(rng), u(rng)));
        apart += !boxesOverlap(a, {offset, turn, halfB}, 1e-6);
    }
    EXPECT_EQ(apart, 0);
}

// A cone that widens upwards is as wide as its top: radius 0.2, top 0.5, height 1.
TEST(OrientedBox, WideningConeIsBoundByItsTop) {
    Object cone;
    cone.type = ShapeType::Cone;
    cone.radius = 0.2f;
    cone.top = 0.5f;
    cone.height = 1.0f;
    const OrientedBox b = boxAbout(makeSdfObject(cone));
    EXPECT_NEAR(b.half.x, 0.5, 1e-7);
    EXPECT_NEAR(b.half.y, 0.5, 1e-7);
    EXPECT_NEAR(b.half.z, 0.5, 1e-7);
}

// What the culls rest on: no point outside the table is nearer it than the nearest of its parts'
// boxes (to the float SDF's rounding, 1e-6 of its size; the culls allow 1e-4), and a box holds
// every point inside. Points in a cube twice the
// table's size, most near its surface, where the culls decide.
TEST(UnionParts, NoPointIsNearerTheGroupThanItsNearestPart) {
    const GroupShape table = shapeOf(kTable);
    const std::vector<OrientedBox> parts = unionParts(table);
    ASSERT_EQ(parts.size(), 5u);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 20000; ++i) {
        const dvec3 p = table.bound * dvec3(u(rng), u(rng), u(rng)) + dvec3(0, 0.4, 0);
        double nearest = 1e300;
        for (const OrientedBox& b : parts) nearest = std::min(nearest, distanceToBox(b, p));
        const double outside = std::max(0.0, double(table.distance(glm::vec3(p))));
        ASSERT_LE(nearest, outside + 1e-6 * table.bound)
            << "at " << p.x << ", " << p.y << ", " << p.z;
    }
}

// Where a member carves, blends or is a bound, the group's distance is not the least of its
// members': no parts.
TEST(UnionParts, NoneWhereTheDistanceIsNotALeastOfExactMembers) {
    const std::string top = "object in:g type:box material:0 pos:0,0,0 size:0.5,0.1,0.5\n";
    EXPECT_EQ(unionParts(shapeOf(top)).size(), 1u);
    EXPECT_TRUE(unionParts(shapeOf(top + "object in:g type:sphere material:0 pos:0,0.1,0 "
                                         "radius:0.2 op:subtract\n"))
                    .empty());
    EXPECT_TRUE(unionParts(shapeOf(top + "object in:g type:sphere material:0 pos:0,0.1,0 "
                                         "radius:0.2 blend:0.05\n"))
                    .empty());
    EXPECT_TRUE(unionParts(shapeOf(top + "object in:g type:ellipsoid material:0 pos:0,0.3,0 "
                                         "size:0.3,0.2,0.1\n"))
                    .empty());
}
