// test_physics_static.cpp — spheres against static objects through the SDF mirror.
#include "marchbox/physics/physics.h"
#include "marchbox/report/physics_scenes.h"
#include "static_collider.h"
#include "physics_test_util.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

using namespace mb;
using glm::dvec3;

namespace {

// A torus of ring 1 and tube 0.25 lying on the ground, and a sphere of 0.2 set on top of the
// tube, just off its crest towards `side` (+1 outward, −1 into the hole).
Scene torusScene(float side) {
    Scene s = physicsWorld(9.81f, 0.3f, 0.5f, true);
    Object torus = staticShape(ShapeType::Torus, {0, 0.25f, 0});
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
    Object box = staticShape(ShapeType::Box, {0, 0.5f, 0});
    box.size = {2.0f, 0.5f, 2.0f};
    Object hole = staticShape(ShapeType::Sphere, {0, 1.0f, 0});
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

// A frictionless ball sliding to and fro in a spherical bowl (a box minus a sphere): its centre
// keeps on a circle of ρ = R − r, where a contact's normal turns as the ball moves. A contact
// whose surface bends is followed every substep, RATTLE's way: the solve pass aims the end of
// the substep's straight path at the surface (StaticCollider::bend), the relax pass works along
// the normal found there. For a circle that keeps the speed exactly; with gravity the method is
// a symplectic kick-drift, whose energy error stays bounded instead of drifting. Bounds: 2 % of
// the swing energy (the energy above the bowl's bottom) over 10 periods
// (measured 0.2 %, was a 49 % gain with the step's first normal), and the centre within
// 0.1 slop of its circle (measured 0.2 mm).
class PhysicsBowl : public ::testing::TestWithParam<std::tuple<float, float, float>> {};

TEST_P(PhysicsBowl, FrictionlessBallKeepsItsSwingEnergy) {
    const auto [bowlRadius, ballRadius, degrees] = GetParam();
    PhysicsWorld w(bowlScene(bowlRadius, ballRadius, degrees, 0.0f));
    const dvec3 centre(bowlCentre(bowlRadius));
    const double rho = double(bowlRadius) - double(ballRadius), g = double(9.81f);
    const double e0 = w.kineticEnergy() + w.potentialEnergy();
    const double swing = e0 - g * (centre.y - rho) / w.body(0).invMass;  // above the bottom
    const double period = 2.0 * M_PI * std::sqrt(rho / g);
    double drift = 0.0, off = 0.0;
    for (int i = 0; i < stepsFor(10.0 * period, w.settings()); ++i) {
        w.step();
        drift = std::max(drift, std::abs(w.kineticEnergy() + w.potentialEnergy() - e0));
        off = std::max(off, std::abs(glm::length(w.body(0).pos - centre) - rho));
    }
    EXPECT_LT(drift, 0.02 * swing);
    EXPECT_LT(off, 0.1 * w.settings().linearSlop);
    EXPECT_GT(std::abs(w.body(0).vel.x) + std::abs(w.body(0).pos.x), 0.1) << "still swinging";
    std::printf(
        "bowl R %g, r %g, %g°: energy drift %.3g of the swing over 10 periods, %.3g m off "
        "the circle\n",
        double(bowlRadius), double(ballRadius), double(degrees), drift / swing, off);
}

INSTANTIATE_TEST_SUITE_P(PhysicsBowls, PhysicsBowl,
                         ::testing::Values(std::make_tuple(1.5f, 0.2f, 20.0f),
                                           std::make_tuple(1.5f, 0.2f, 40.0f),
                                           std::make_tuple(0.5f, 0.2f, 30.0f)));

// A sphere set on a tilted plank (a rotated box: its top face is flat, so its contact keeps its
// normal). Rolling without slipping with rolling resistance c, m·a = m·g·sin θ − F and
// I·a/r = F·r − c·r·N, N = m·g·cos θ, I = 2/5·m·r², give a = 5/7·g·(sin θ − c·cos θ); sliding
// (μ below 2/7·tan θ + 5/7·c), a = g·(sin θ − μ·cos θ). The velocity is exact but for the
// friction row trailing by a substep (bound 2·a·h); the position of a body a contact pushes moves
// by v·h each substep, the symplectic Euler lag a·T·h/2, plus that velocity lag over T. Both well
// inside 1 %.
class PhysicsRamp : public ::testing::TestWithParam<std::tuple<float, float, float, bool>> {};

TEST_P(PhysicsRamp, AccelerationDownTheSlope) {
    const auto [degrees, mu, c, rolls] = GetParam();
    PhysicsWorld w(rampScene(degrees, mu, c));
    const PhysicsSettings& s = w.settings();
    const double theta = double(degrees) * M_PI / 180.0, g = double(9.81f), h = s.dt / s.substeps,
                 T = 1.0;
    const dvec3 down(-std::cos(theta), -std::sin(theta), 0.0), start = w.body(0).pos;
    const double a = rolls ? 5.0 / 7.0 * g * (std::sin(theta) - double(c) * std::cos(theta))
                           : g * (std::sin(theta) - double(mu) * std::cos(theta));
    for (int i = 0; i < stepsFor(T, s); ++i) w.step();
    const PhysicsBody& b = w.body(0);
    const double v = glm::dot(b.vel, down), d = glm::dot(b.pos - start, down);
    EXPECT_NEAR(v, a * T, 2.0 * a * h);
    EXPECT_NEAR(d, 0.5 * a * T * T, 0.5 * a * T * h + 2.0 * a * h * T);
    EXPECT_NEAR(2.0 * d / (T * T), a, 0.01 * a);
    const double slip = glm::length(
        b.vel + glm::cross(b.spin, dvec3(std::sin(theta), -std::cos(theta), 0) * b.radius));
    if (rolls) {
        // Within a substep the rolling row, solved after friction, turns the spin back by
        // c·r·N·h / I: a slip of 5/2·c·g·cos θ·h that the next substep's friction row takes out.
        EXPECT_LT(slip, 2.5 * double(c) * g * std::cos(theta) * h + 1e-9)
            << "rolls without slipping";
    } else {
        EXPECT_GT(slip, 0.1) << "slides";
    }
    std::printf(
        "ramp %g°, μ %g, c %g: a from v %.6f, from distance %.6f, exact %.6f; slip %.3g m/s\n",
        double(degrees), double(mu), double(c), v / T, 2.0 * d / (T * T), a, slip);
}

INSTANTIATE_TEST_SUITE_P(PhysicsRamps, PhysicsRamp,
                         ::testing::Values(std::make_tuple(20.0f, 0.5f, 0.02f, true),
                                           std::make_tuple(30.0f, 0.5f, 0.1f, true),
                                           std::make_tuple(30.0f, 0.1f, 0.02f, false),
                                           std::make_tuple(45.0f, 0.2f, 0.0f, false)));

// Far from the origin the collider works in local coordinates: a box 1e5 m out still gives
// distances to a micrometre.
TEST(PhysicsStatic, DistancesKeepPrecisionFarFromTheOrigin) {
    Scene s = physicsWorld(9.81f, 0.3f, 0.5f, false);
    s.objects.push_back(staticShape(ShapeType::Box, {1e5f, 0, 0}));  // half-extent 0.5
    StaticCollider c(s);
    EXPECT_NEAR(c.distance(dvec3(1e5 + 0.5 + 0.123456, 0, 0)), 0.123456, 1e-6);
    std::vector<StaticHit> hits;
    c.query(0, dvec3(1e5, 0.9, 0), 0.3, 0.2, hits);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_NEAR(hits[0].separation, 0.1, 1e-6);
    EXPECT_NEAR(hits[0].normal.y, 1.0, 1e-6);
}

// A sphere's query skips measuring groups while its last clearance, less how far it moved, keeps
// them out of reach: walking into a box and back in steps of 7.5 mm, it must see the box at the
// same steps as a query that measures afresh (a new body each time).
TEST(PhysicsStatic, KeptClearanceFindsWhatMeasuringFinds) {
    Scene s = physicsWorld(9.81f, 0.3f, 0.5f, false);
    s.objects.push_back(staticShape(ShapeType::Box, {0, 0, 0}));  // half-extent 0.5
    StaticCollider kept(s), fresh(s);
    std::vector<StaticHit> a, b;
    int seen = 0;
    for (int i = 0; i < 400; ++i) {
        const double x =
            2.0 - 0.0075 * (i < 200 ? i : 400 - i);  // into the box (its face at 0.5) and back
        kept.query(0, dvec3(x, 0.1, 0), 0.05, 0.02, a);
        fresh.query(i, dvec3(x, 0.1, 0), 0.05, 0.02, b);
        ASSERT_EQ(a.size(), b.size()) << "at x = " << x;
        for (size_t k = 0; k < a.size(); ++k)
            EXPECT_EQ(a[k].separation, b[k].separation) << "at x = " << x;
        seen += a.empty() ? 0 : 1;
    }
    EXPECT_GT(seen, 0) << "the walk never reached the box: the test would see nothing";
}

TEST(PhysicsStatic, CastStopsBeforeAThinPlate) {
    StaticCollider c(tunnelScene(1.0f, 0.0f));  // plate |z| <= 0.01
    const double t = c.cast(dvec3(0, 0, -3), dvec3(0, 0, 1), 10.0, 0.05);
    EXPECT_GT(t, 3.0 - 0.01 - 0.05 - 1e-4);
    EXPECT_LE(t, 3.0 - 0.01 - 0.05 + 1e-6);  // the plate's 0.01 is a float
}

// A floor of 10 × 10 static tiles: each tile's surface is a manifold of its own, whose points
// (its corners and edges' midpoints) need keys apart within the 127 the probe byte holds, or
// two share a warm start. Planted: each probe keyed by its place among the whole floor's,
// sorted by x with ten tiles to each column: 123 of the 2,000 share a key with another of
// their tile's.
TEST(PhysicsStatic, EachStaticSurfacesProbesHaveKeysApart) {
    Scene s = physicsWorld(9.81f, 0.0f, 0.5f, true);
    for (int i = 0; i < 10; ++i)
        for (int k = 0; k < 10; ++k)
            s.objects.push_back(staticBox({float(i), 0.1f, float(k)}, {0.5f, 0.1f, 0.5f}));
    const StaticCollider statics(s);
    std::map<int, std::set<int>> keys;  // per feature, its probes' keys as the byte holds them
    int probes = 0;
    for (const StaticProbe& p : statics.probes()) {
        keys[p.feature].insert(p.key % 127);
        ++probes;
    }
    int held = 0;
    for (const auto& [feature, own] : keys) held += int(own.size());
    EXPECT_GT(probes, 100);
    EXPECT_EQ(held, probes) << "two probes of one surface share a key";
}
