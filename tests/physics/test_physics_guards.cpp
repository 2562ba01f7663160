// test_physics_guards.cpp — behaviours of the sphere simulator that only the determinism hash
// used to see: each test names what broke, so the engine can grow with them in place.
#include "marchbox/physics/physics.h"
#include "marchbox/report/physics_scenes.h"
#include "physics_test_util.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace mb;
using glm::dvec3;

namespace {

void run(PhysicsWorld& w, double seconds) {
    for (int i = 0; i < stepsFor(seconds, w.settings()); ++i) w.step();
}

Object spinningSphere(glm::vec3 pos, float radius, glm::vec3 vel, glm::vec3 spin) {
    Object o = dynamicSphere(pos, radius, 1.0f, vel);
    o.spin = spin;
    return o;
}

}  // namespace

// A capsule lying along x (radius 0.3, y = 1, no ground): a sphere of 0.2 dropped on its middle
// comes to rest on top, its centre 0.3 + 0.2 above the axis. A contact normal pointing into
// the capsule would pull the sphere through it instead.
TEST(PhysicsGuards, SphereRestsOnAStaticCapsule) {
    Scene s = physicsWorld(9.81f, 0.3f, 0.5f, false);
    Object capsule = staticShape(ShapeType::Capsule, {0, 1, 0}, {0, 0, 90});
    capsule.radius = 0.3f;
    capsule.height = 1.0f;
    s.objects.push_back(capsule);
    s.objects.push_back(dynamicSphere({0, 1.8f, 0}, 0.2f, 1.0f));
    PhysicsWorld w(s);
    run(w, 2.0);
    EXPECT_NEAR(w.body(0).pos.y, 1.5, 0.01) << "not resting on the capsule's top";
    EXPECT_NEAR(w.body(0).pos.x, 0.0, 0.01);
}

// A frictionless sphere of 0.2 slides from rest down the outside of a torus tube (ring 1, tube
// 0.25, lying on the ground), 10° from the crest. In contact its centre keeps on the circle of
// ρ = 0.45 about the tube's core, so the energy it gains is m·g·ρ·(cos θ0 − cos θ), and it
// leaves the tube only at cos θ = ⅔·cos θ0 (49°). Up to 40° the energy must hold within 1 % of
// the drop and the centre within 0.1 slop of the circle, as in the bowl: a contact whose normal
// stayed as the step found it would gain energy where the tube bends away.
TEST(PhysicsGuards, FrictionlessSphereFollowsTheCurveOfATorus) {
    Scene s = physicsWorld(9.81f, 0.0f, 0.0f, true);
    s.world.rolling = 0.0f;
    Object torus = staticShape(ShapeType::Torus, {0, 0.25f, 0});
    torus.radius = 1.0f;
    torus.minor = 0.25f;
    s.objects.push_back(torus);
    const double rho = 0.45, theta0 = 10.0 * M_PI / 180.0;
    const glm::vec3 start(float(1.0 + rho * std::sin(theta0)), float(0.25 + rho * std::cos(theta0)),
                          0.0f);
    s.objects.push_back(dynamicSphere(start, 0.2f, 1.0f));
    PhysicsWorld w(s);
    const dvec3 core(1.0, 0.25, 0.0);
    const double e0 = w.kineticEnergy() + w.potentialEnergy();
    double drift = 0.0, off = 0.0, theta = theta0;
    for (int i = 0; i < stepsFor(2.0, w.settings()) && theta < 40.0 * M_PI / 180.0; ++i) {
        w.step();
        const dvec3 d = w.body(0).pos - core;
        theta = std::atan2(d.x, d.y);
        drift = std::max(drift, std::abs(w.kineticEnergy() + w.potentialEnergy() - e0));
        off = std::max(off, std::abs(glm::length(d) - rho));
    }
    ASSERT_GE(theta, 40.0 * M_PI / 180.0) << "the sphere never slid down to 40°";
    const double drop = 9.81 * rho * (std::cos(theta0) - std::cos(theta));
    EXPECT_LT(drift, 0.01 * drop) << "energy not kept along the torus";
    EXPECT_LT(off, 0.1 * w.settings().linearSlop) << "the centre left its circle about the tube";
}

// A sphere asleep on the ground is hit by one rolling at 2 m/s: it must wake and move on,
// whichever of the two comes first in the scene.
class PhysicsWaking : public ::testing::TestWithParam<bool> {};

TEST_P(PhysicsWaking, ARollingSphereWakesTheSleeperItHits) {
    const bool sleeperFirst = GetParam();
    Scene s = physicsWorld(9.81f, 0.5f, 0.5f, true);
    s.world.rolling = 0.0f;
    const Object sleeper = dynamicSphere({0, 0.2f, 0}, 0.2f, 1.0f);
    const Object roller = spinningSphere({-4, 0.2f, 0}, 0.2f, {2, 0, 0}, {0, 0, -10});
    s.objects =
        sleeperFirst ? std::vector<Object>{sleeper, roller} : std::vector<Object>{roller, sleeper};
    const int index = sleeperFirst ? 0 : 1;
    PhysicsWorld w(s);
    run(w, 1.2);
    ASSERT_FALSE(w.body(index).awake) << "the resting sphere should be asleep before the hit";
    run(w, 1.3);
    EXPECT_GT(w.body(index).pos.x, 0.2) << "the sleeper was hit but did not move";
}

INSTANTIATE_TEST_SUITE_P(EitherOrder, PhysicsWaking, ::testing::Bool());

// Three columns of six spheres dropped onto the ground, and the same scene 10 m lower: the
// solver orders contacts bottom-up by height, and below zero that order must still be
// bottom-up. Both end within 1e-5 m of each other (rounding of the shifted heights is about
// 1e-6 m; solving a column top-down instead leaves it sagging by millimetres).
TEST(PhysicsGuards, ASceneMovedDownTenMetresGivesTheSameResult) {
    auto columns = [](float floor) {
        Scene s = physicsWorld(9.81f, 0.3f, 0.5f, true);
        s.world.floor = floor;
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 6; ++k)
                s.objects.push_back(dynamicSphere(
                    {0.5f * float(c), floor + 0.1f + 0.205f * float(k), 0}, 0.1f, 1.0f + float(k)));
        return s;
    };
    PhysicsWorld high(columns(0.0f)), low(columns(-10.0f));
    run(high, 1.0);
    run(low, 1.0);
    double worst = 0.0;
    for (int i = 0; i < high.bodyCount(); ++i)
        worst =
            std::max(worst, glm::length(high.body(i).pos - (low.body(i).pos + dvec3(0, 10, 0))));
    EXPECT_LT(worst, 1e-5) << "the same columns 10 m lower end elsewhere";
}

// A sphere of 0.1 sliding at 1 m/s without spin over the top of a giant dynamic sphere (radius
// 1000, 1e9 kg, resting on the ground: flat here to 5e-5 over the slide) decelerates at μ·g
// until it rolls at t = 2·v0/(7·μ·g) = 0.097 s. At 0.05 s its speed is v0 − μ·g·t within 2 %
// of the change μ·g·t; the friction between two dynamic spheres is the world's μ, as on the
// ground.
TEST(PhysicsGuards, SphereOnSphereFrictionIsTheWorldsCoefficient) {
    const float mu = 0.3f;
    Scene s = physicsWorld(9.81f, 0.0f, mu, true);
    s.world.rolling = 0.0f;
    s.objects.push_back(dynamicSphere({0, 1000, 0}, 1000.0f, 1e9f));
    s.objects.push_back(dynamicSphere({0, 2000.1f, 0}, 0.1f, 1.0f, {1, 0, 0}));
    PhysicsWorld w(s);
    run(w, 0.05);
    const double change = 1.0 - w.body(1).vel.x, expected = double(mu) * 9.81 * 0.05;
    EXPECT_NEAR(change, expected, 0.02 * expected)
        << "sliding on a sphere decelerates at " << change / 0.05
        << " m/s², not μ·g = " << expected / 0.05;
}
