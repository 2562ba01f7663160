// test_carved_statics.cpp — spheres against statics carved by CSG, whose SDF is a bound.
//
// A carved or blended chain (max(a, −b), a smooth minimum) is 1-Lipschitz and zero on the drawn
// surface, but over an opening it reads the gap to the subtractor's cap, which is not drawn. The
// collider must meet only what is drawn: a ball falls into a cup whose subtractor pokes above the
// rim, and into a square hole through a slab, and still rests on the rim's top.
#include "marchbox/physics/physics.h"
#include "marchbox/report/physics_scenes.h"
#include "physics_test_util.h"
#include "static_collider.h"

#include <gtest/gtest.h>
#include <cmath>
#include <cstring>

using namespace mb;
using glm::dvec3;

namespace {

// A cup: a static cylinder of radius 0.5 and height 0.8 standing on the ground, less a cylinder
// of radius 0.44 raised 0.06, so its floor is 0.06 thick at y = 0.06, its wall 0.06 thick and its
// rim at y = 0.8; the subtractor's cap stands 0.06 above the rim, over the opening.
constexpr double kFloor = 0.06, kRim = 0.8, kInner = 0.44, kOuter = 0.5;

Scene cupScene() {
    Scene s = physicsWorld(9.81f, 0.3f, 0.5f, true);
    s.world.rolling = 0.05f;  // so a ball rolling on the floor comes to rest
    Object cup = staticShape(ShapeType::Cylinder, {0, 0.4f, 0});
    cup.radius = 0.5f;
    cup.height = 0.8f;
    Object hole = staticShape(ShapeType::Cylinder, {0, 0.46f, 0});
    hole.radius = 0.44f;
    hole.height = 0.8f;
    hole.op = CsgOp::Subtract;
    s.objects.push_back(cup);
    s.objects.push_back(hole);
    return s;
}

// What a contact at rest keeps: the overlap that the solver leaves alone (slopFor in
// physics_world.cpp), which the ball may sink into its support.
double restSlop(const PhysicsSettings& s, double radius) {
    return std::min(s.linearSlop, 0.05 * radius);
}

// FNV-1a over the bytes of every body's position, velocity and spin.
std::uint64_t stateHash(const PhysicsWorld& w) {
    std::uint64_t h = 1469598103934665603ull;
    for (int i = 0; i < w.bodyCount(); ++i) {
        const PhysicsBody& b = w.body(i);
        const double values[9] = {b.pos.x, b.pos.y,  b.pos.z,  b.vel.x, b.vel.y,
                                  b.vel.z, b.spin.x, b.spin.y, b.spin.z};
        unsigned char bytes[sizeof values];
        std::memcpy(bytes, values, sizeof values);
        for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
    }
    return h;
}

}  // namespace

// Dropped over the opening, off its axis, the ball falls through where the bound reads a lid at
// the rim and comes to rest on the inner floor: its centre r above the floor, less at most the
// slop that a resting contact keeps (the floor is flat and exact there: no other error).
TEST(CarvedStatics, BallDroppedIntoACupRestsOnItsFloor) {
    Scene s = cupScene();
    const double r = 0.15;
    s.objects.push_back(dynamicSphere({0.1f, 1.5f, 0.05f}, float(r), 1.0f));
    PhysicsWorld w(s);
    bool belowRim = false;
    for (int i = 0; i < stepsFor(4.0, w.settings()); ++i) {
        w.step();
        belowRim = belowRim || w.body(0).pos.y < kRim;
    }
    const PhysicsBody& b = w.body(0);
    EXPECT_TRUE(belowRim) << "held above the rim, at y = " << b.pos.y;
    const double slop = restSlop(w.settings(), r);
    EXPECT_LE(b.pos.y, kFloor + r + 1e-6) << "resting on the inner floor";
    EXPECT_GE(b.pos.y, kFloor + r - slop - 1e-6) << "resting on the inner floor";
    EXPECT_LT(std::hypot(b.pos.x, b.pos.z), kInner - r + slop) << "inside the wall";
}

// A ball rolled across a slab, 0.2 thick on the ground, towards a square hole 0.6 wide through
// it (the subtracted box pokes 0.1 out of both faces): it drops into the hole and stays in it, on
// the ground, where the bound's lid over the hole would carry it across and on along the slab.
TEST(CarvedStatics, BallRolledAcrossASquareHoleFallsIn) {
    Scene s = physicsWorld(9.81f, 0.3f, 0.5f, true);
    Object slab = staticShape(ShapeType::Box, {0, 0.1f, 0});
    slab.size = {2.0f, 0.1f, 1.0f};
    Object hole = staticShape(ShapeType::Box, {0, 0.1f, 0});
    hole.size = {0.3f, 0.2f, 0.3f};
    hole.op = CsgOp::Subtract;
    s.objects.push_back(slab);
    s.objects.push_back(hole);
    const float r = 0.15f, v = 1.0f;
    Object ball = dynamicSphere({-1.0f, 0.2f + r, 0.0f}, r, 1.0f, {v, 0, 0});
    ball.spin = {0, 0, -v / r};  // rolling without slipping along +x
    s.objects.push_back(ball);
    PhysicsWorld w(s);
    for (int i = 0; i < stepsFor(3.0, w.settings()); ++i) w.step();
    const PhysicsBody& b = w.body(0);
    EXPECT_LT(b.pos.y, 0.2) << "below the slab's top";
    EXPECT_LT(std::abs(b.pos.x), 0.3) << "in the hole, at x = " << b.pos.x;
    EXPECT_LT(std::abs(b.pos.z), 0.3) << "in the hole, at z = " << b.pos.z;
}

// Dropped on the middle of the rim's top (0.06 wide), the ball lands on it and stays there: the
// contact under it is the drawn top face, not something the search for real surfaces loses.
TEST(CarvedStatics, BallDroppedOnTheRimRestsOnIt) {
    Scene s = cupScene();
    const double r = 0.15, ring = 0.5 * (kInner + kOuter);
    s.objects.push_back(dynamicSphere({float(ring), 1.3f, 0.0f}, float(r), 1.0f));
    PhysicsWorld w(s);
    for (int i = 0; i < stepsFor(3.0, w.settings()); ++i) w.step();
    const PhysicsBody& b = w.body(0);
    const double slop = restSlop(w.settings(), r);
    EXPECT_LE(b.pos.y, kRim + r + 1e-6) << "resting on the rim";
    EXPECT_GE(b.pos.y, kRim + r - slop - 1e-6) << "resting on the rim";
    EXPECT_NEAR(b.pos.x, ring, 1e-3) << "still over the rim's top";
}

// A ball wider than the opening (r 0.5 on the rim's inner edge of radius 0.44), dropped a little
// off its axis, rests on the edge all round, its centre sqrt(r² − 0.44²) above the rim, and
// sleeps. A single contact with the nearest point of the edge would flip from side to side: the
// ball sank into the rim, or rocked on it and gained energy. The contacts may overlap by the
// slop along their normals, which lean cos θ = 0.475 from the vertical: slop / 0.475 lower at most.
TEST(CarvedStatics, BallWiderThanTheCupRestsOnItsRim) {
    Scene s = cupScene();
    const double r = 0.5, rest = kRim + std::sqrt(r * r - kInner * kInner);
    s.objects.push_back(dynamicSphere({0.03f, 1.5f, 0.01f}, float(r), 1.0f));
    PhysicsWorld w(s);
    for (int i = 0; i < stepsFor(4.0, w.settings()); ++i) w.step();
    const PhysicsBody& b = w.body(0);
    const double lean = (rest - kRim) / r;
    EXPECT_LE(b.pos.y, rest + 1e-4) << "on the rim";
    EXPECT_GE(b.pos.y, rest - restSlop(w.settings(), r) / lean) << "on the rim";
    EXPECT_LT(std::hypot(b.pos.x, b.pos.z), 1e-3) << "centred on the opening";
    EXPECT_FALSE(b.awake) << "still rocking, at " << glm::length(b.vel) << " m/s";
}

// The collider itself, against closed forms for the cup (a ring wall and a floor disc, so the
// nearest drawn point to a point over the opening is on the rim's inner edge).
TEST(CarvedStatics, ColliderMeetsOnlyTheDrawnSurface) {
    StaticCollider c(cupScene());
    // Over the axis, 0.2 above the rim: the rim's inner edge is sqrt(0.2² + 0.44²) away; the
    // bound reads 0.2, the lid's. Float scene, double queries: 1e-5.
    EXPECT_NEAR(c.distance(dvec3(0, kRim + 0.2, 0)), std::hypot(0.2, kInner), 1e-5);
    // A falling ball of 0.15 swept down the axis stops on the inner floor, not on the lid.
    const double t = c.cast(dvec3(0, 1.5, 0), dvec3(0, -1, 0), 2.0, 0.15);
    EXPECT_NEAR(t, 1.5 - kFloor - 0.15, 1e-3 * 0.15) << "the sweep's tolerance, 1e-3·radius";
    // A ball over the opening 0.03 in from the rim and 0.12 above it touches the edge only.
    std::vector<StaticHit> hits;
    const double s = 0.03, h = 0.12, r = 0.15;
    c.query(0, dvec3(kInner - s, kRim + h, 0), r, 0.02, hits);
    ASSERT_EQ(hits.size(), 1u) << "the cup alone: the ground is out of reach";
    EXPECT_GE(hits[0].feature, 1) << "the cup's";
    EXPECT_NEAR(hits[0].separation, std::hypot(s, h) - r, 1e-5);
    EXPECT_NEAR(hits[0].normal.x, -s / std::hypot(s, h), 1e-3);
    EXPECT_NEAR(hits[0].normal.y, h / std::hypot(s, h), 1e-3);
    // Over the middle of the opening, 0.1 above the rim, nothing is in reach.
    c.query(1, dvec3(0, kRim + 0.1, 0), r, 0.02, hits);
    EXPECT_TRUE(hits.empty()) << "separation " << (hits.empty() ? 0.0 : hits[0].separation);
}

// A ball dropped into the cup gives the same bytes on one thread and on two.
TEST(CarvedStatics, SameBytesOnOneAndTwoThreads) {
    Scene s = cupScene();
    s.objects.push_back(dynamicSphere({0.3f, 1.2f, 0.0f}, 0.15f, 1.0f));
    s.objects.push_back(dynamicSphere({-0.38f, 1.0f, 0.1f}, 0.2f, 1.0f));
    PhysicsSettings two;
    two.threads = 2;
    PhysicsWorld a(s), b(s, two);
    for (int i = 0; i < stepsFor(2.0, a.settings()); ++i) {
        a.step();
        b.step();
    }
    EXPECT_EQ(stateHash(a), stateHash(b));
}
