// test_near_parts.cpp — a union group probed part by part (near_parts.h): the parts near each
// part measure the group's distance wherever a probe of that part can reach it, and a table
// stood on another rests on its top as its shape puts it.
#include "near_parts.h"
#include "rigid_bodies.h"

#include "marchbox/physics/physics.h"
#include "physics_test_util.h"

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>
#include <random>
#include <string>

using namespace mb;
using glm::dvec3;

namespace {

// The report's table as group `name`: a box top on four cylinder legs, its legs' feet at its
// origin's height and its top 0.75 above them.
std::string table(const std::string& name, const std::string& pose) {
    const std::string in = "object in:" + name + " type:";
    return "group name:" + name + " " + pose + " mass:1\n" + in +
           "box pos:0,0.72,0 size:0.5,0.03,0.35\n" + in +
           "cylinder pos:0.42,0.345,0.27 radius:0.03 height:0.69\n" + in +
           "cylinder pos:-0.42,0.345,0.27 radius:0.03 height:0.69\n" + in +
           "cylinder pos:0.42,0.345,-0.27 radius:0.03 height:0.69\n" + in +
           "cylinder pos:-0.42,0.345,-0.27 radius:0.03 height:0.69\n";
}

// The body's whole shape at world point x: its group's distance, in the group's frame.
double groupDistance(const RigidBody& b, const dvec3& x) {
    const dvec3 local = glm::conjugate(b.orient) * (x - b.pos);
    return double(b.groupShape->distance(glm::vec3(b.centre + b.axes * local)));
}

}  // namespace

// For every part of the first table, points throughout its box (where its probes lie) that come
// within reach of the second: there, the least over that part's near parts is the group's
// distance, to the float SDF's rounding. The second table crossing the first, turned; and with
// its top 2 cm under the first's feet, where the sphere about a leg's box stops short of the top
// by less than the reach. Planted: the near test without the reach (a point 2.4 cm above the
// top finds no part); the members' frames without their offsets (a distance 0.48 m long).
TEST(NearParts, TheNearPartsMeasureTheGroupWhereAProbeCanReach) {
    for (const char* pose : {"pos:0.3,0.55,0.1 rot:40,20,0", "pos:0.1,-0.77,0.05"}) {
        SCOPED_TRACE(pose);
        const Scene s = sceneFromText("scene version:3\nworld ground:0\n" +
                                      table("a", "pos:0,0,0") + table("b", pose));
        const PhysicsSettings settings;
        const RigidBodies bodies(s, settings);
        ASSERT_EQ(bodies.count(), 2);
        const RigidBody &a = bodies.body(0), &b = bodies.body(1);
        ASSERT_EQ(a.parts.size(), 5u);
        const double reach = 0.05;
        std::vector<OrientedBox> boxesA, boxesB;
        appendPlacedBoxes(a, boxesA);
        appendPlacedBoxes(b, boxesB);
        NearParts near;
        near.meet(boxesA, boxesB, reach);
        near.find(true, b);
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        int within = 0;
        for (size_t p = 0; p < a.parts.size(); ++p) {
            const OrientedBox box = placed(a.parts[p], a.orient, a.pos);
            for (int i = 0; i < 20000; ++i) {
                const dvec3 x = box.centre + box.axes * (box.half * dvec3(u(rng), u(rng), u(rng)));
                const double d = groupDistance(b, x);
                if (d >= reach) continue;
                ++within;
                const NearParts::Sample found = near.nearest(near.of(int(p)), x);
                ASSERT_GE(found.part, 0)
                    << "part " << p << " at " << x.x << ", " << x.y << ", " << x.z;
                ASSERT_NEAR(found.distance, d, 1e-6) << "part " << p;
            }
        }
        std::printf("%s: %d points within reach\n", pose, within);
        EXPECT_GT(within, 200);
    }
}

// A part's list is empty where the other table is further than the reach by their boxes.
TEST(NearParts, NoPartIsNearATableAMetreAway) {
    const Scene s = sceneFromText("scene version:3\nworld ground:0\n" + table("a", "pos:0,0,0") +
                                  table("b", "pos:1.6,0,0 rot:0,90,0"));
    const PhysicsSettings settings;
    const RigidBodies bodies(s, settings);
    std::vector<OrientedBox> boxesA, boxesB;
    appendPlacedBoxes(bodies.body(0), boxesA);
    appendPlacedBoxes(bodies.body(1), boxesB);
    NearParts near;
    near.meet(boxesA, boxesB, 0.05);
    near.find(true, bodies.body(1));
    for (int p = 0; p < 5; ++p) EXPECT_TRUE(near.of(p).empty()) << "part " << p;
}

// A table set 1 cm above another's top, turned 5° about the vertical, its feet within the top's
// face: after 2 s both are at rest, the lower on the ground with its origin at 0 and the upper
// on the top's face, 0.75 up, each within the slop, level. Planted: rims left out of the part
// by part probes (the upper table's feet go through the top: it rests 8.4 cm low on its legs'
// higher probes); the members' frames without their offsets (it falls through, 0.72 m low).
TEST(NearParts, ATableStoodOnAnotherRestsOnItsTop) {
    const Scene s =
        sceneFromText("scene version:3\nworld ground:1 friction:0.6\n" + table("a", "pos:0,0,0") +
                      table("b", "pos:0.02,0.76,-0.01 rot:0,5,0"));
    PhysicsWorld w(s);
    ASSERT_EQ(w.rigidCount(), 2);
    for (int i = 0; i < stepsFor(2.0, w.settings()); ++i) w.step();
    const double slop = PhysicsSettings{}.linearSlop;
    const RigidState lower = w.rigid(0), upper = w.rigid(1);
    std::printf("lower origin %.5f, upper %.5f (0.75)\n", lower.pos.y, upper.pos.y);
    EXPECT_NEAR(lower.pos.y, 0.0, slop);
    EXPECT_NEAR(upper.pos.y, 0.75, slop);
    EXPECT_GT((upper.orient * dvec3(0, 1, 0)).y, 0.9999) << "the upper table tipped";
    EXPECT_LT(glm::length(upper.vel), 1e-3);
}
