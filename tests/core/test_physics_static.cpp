// test_physics_static.cpp — spheres against static objects through the SDF mirror.
#include "marchbox/physics.h"
#include "marchbox/physics_scenes.h"
#include "marchbox/static_collider.h"
#include "physics_test_util.h"

#include <gtest/gtest.h>

using namespace mb;
using glm::dvec3;

namespace {

Object staticObject(ShapeType type, glm::vec3 pos) {
    Object o;
    o.type = type;
    o.pos = pos;
    o.isStatic = true;
    return o;
}

// A torus of ring 1 and tube 0.25 lying on the ground, and a sphere of 0.2 set on top of the
// tube, just off its crest towards `side` (+1 outward, −1 into the hole).
Scene torusScene(float side) {
    Scene s = physicsWorld(9.81f, 0.3f, 0.5f, true);
    Object torus = staticObject(ShapeType::Torus, {0, 0.25f, 0});
    torus.radius = 1.0f;
    torus.minor = 0.25f;
    s.objects.push_back(torus);
    s.objects.push_back(dynamicSphere({1.0f + side * 0.02f, 0.25f + 0.25f + 0.2f, 0}, 0.2f, 1.0f));
    return s;
}

double radial(const PhysicsBody& b) { return std::hypot(b.pos.x, b.pos.z); }

}  // namespace

TEST(PhysicsStatic, SphereRollsOffTheTorusOutward) {
    PhysicsWorld w(torusScene(+1.0f));
    for (int i = 0; i < stepsFor(4.0, w.settings()); ++i) w.step();
    const PhysicsBody& b = w.body(0);
    EXPECT_NEAR(b.pos.y, 0.2, 0.01) << "on the ground";
    EXPECT_GT(radial(b), 1.25 + 0.2 - 0.01) << "outside the tube";
}

TEST(PhysicsStatic, SphereRollsOffTheTorusIntoTheHole) {
    PhysicsWorld w(torusScene(-1.0f));
    for (int i = 0; i < stepsFor(4.0, w.settings()); ++i) w.step();
    const PhysicsBody& b = w.body(0);
    EXPECT_NEAR(b.pos.y, 0.2, 0.01) << "on the ground";
    EXPECT_LT(radial(b), 0.75 - 0.2 + 0.01) << "inside the hole";
}

// A box with a hemispherical dimple carved by a subtracted sphere of radius 0.5 centred on its
// top face: a sphere of 0.2 dropped off-centre rolls to and fro in the bowl (it rolls without
// slipping, so only rolling resistance c takes its energy: 0.2 here, to settle in seconds) and
// settles on the bowl, its centre 0.5 − 0.2 from the carving sphere's. Rolling resistance holds
// it wherever the slope has tan θ <= c, so it stops within 0.3·sin(atan c) of the bottom.
TEST(PhysicsStatic, SphereSettlesIntoASubtractedHole) {
    Scene s = physicsWorld(9.81f, 0.3f, 0.5f, true);
    Object box = staticObject(ShapeType::Box, {0, 0.5f, 0});
    box.size = {2.0f, 0.5f, 2.0f};
    Object hole = staticObject(ShapeType::Sphere, {0, 1.0f, 0});
    hole.radius = 0.5f;
    hole.op = CsgOp::Subtract;
    s.objects.push_back(box);
    s.objects.push_back(hole);
    s.objects.push_back(dynamicSphere({0.15f, 2.0f, 0.05f}, 0.2f, 1.0f));
    s.world.rolling = 0.2f;
    PhysicsWorld w(s);
    const PhysicsSettings& settings = w.settings();
    for (int i = 0; i < stepsFor(10.0, w.settings()); ++i) {
        w.step();
        // Landed by 1 s. A contact's normal is fixed for a step, in which the ball crosses up
        // to 4 cm of a bowl of radius 0.5: allow 2 cm of overlap on the curve.
        if (i > stepsFor(1.0, w.settings())) {
            ASSERT_LT(glm::length(w.body(0).pos - dvec3(0, 1, 0)), 0.3 + 0.02) << "step " << i;
        }
    }
    const dvec3 p = w.body(0).pos;
    const double slop = std::min(settings.linearSlop, 0.05 * 0.2);  // overlap a rest may keep
    EXPECT_NEAR(glm::length(p - dvec3(0, 1, 0)), 0.3, slop + 1e-3) << "resting on the bowl";
    EXPECT_LT(std::hypot(p.x, p.z), 0.3 * std::sin(std::atan(double(s.world.rolling))));
    EXPECT_FALSE(w.body(0).awake);
}

// Far from the origin the collider works in local coordinates: a box 1e5 m out still gives
// distances to a micrometre.
TEST(PhysicsStatic, DistancesKeepPrecisionFarFromTheOrigin) {
    Scene s = physicsWorld(9.81f, 0.3f, 0.5f, false);
    s.objects.push_back(staticObject(ShapeType::Box, {1e5f, 0, 0}));  // half-extent 0.5
    StaticCollider c(s);
    EXPECT_NEAR(c.distance(dvec3(1e5 + 0.5 + 0.123456, 0, 0)), 0.123456, 1e-6);
    std::vector<StaticHit> hits;
    c.query(dvec3(1e5, 0.9, 0), 0.3, 0.2, hits);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_NEAR(hits[0].separation, 0.1, 1e-6);
    EXPECT_NEAR(hits[0].normal.y, 1.0, 1e-6);
}

TEST(PhysicsStatic, CastStopsBeforeAThinPlate) {
    StaticCollider c(tunnelScene(1.0f, 0.0f));  // plate |z| <= 0.01
    const double t = c.cast(dvec3(0, 0, -3), dvec3(0, 0, 1), 10.0, 0.05);
    EXPECT_GT(t, 3.0 - 0.01 - 0.05 - 1e-4);
    EXPECT_LE(t, 3.0 - 0.01 - 0.05 + 1e-6);  // the plate's 0.01 is a float
}
