// test_physics_surfaces.cpp — each body's and static surface's own friction and restitution,
// combined per touching pair as √(f₁·f₂) and max(e₁, e₂), against the closed forms.
#include "marchbox/physics/physics.h"
#include "marchbox/report/physics_scenes.h"
#include "physics_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>

using namespace mb;

namespace {

constexpr double kG = double(9.81f);

// The first apex after dropping the ball from 1 m: e²·h to within the step's sampling,
// g·(dt/2)²/2 (as BounceApexesFallAsEToTheTwoN).
double firstApex(const Scene& scene) {
    PhysicsWorld w(scene);
    const double r = w.body(0).radius;
    double apex = 0.0, previousVy = 0.0;
    bool bounced = false;
    for (int i = 0; i < stepsFor(3.0, w.settings()); ++i) {
        w.step();
        const PhysicsBody& b = w.body(0);
        if (previousVy < 0.0 && b.vel.y > 0.0) bounced = true;
        if (bounced) apex = std::max(apex, b.pos.y - r);
        if (bounced && previousVy > 0.0 && b.vel.y <= 0.0) break;
        previousVy = b.vel.y;
    }
    return apex;
}

// Where a ball sent sliding at v0 is after 2 s: it slides for t_s = 2·v0/(7·μ·g), then rolls at
// 5/7·v0 (SlideTurnsIntoRollingAtFiveSevenths), so x = v0·t_s − μ·g·t_s²/2 + 5/7·v0·(2 − t_s).
double slideDistance(double v0, double mu) {
    const double slide = 2.0 * v0 / (7.0 * mu * kG);
    return v0 * slide - 0.5 * mu * kG * slide * slide + 5.0 / 7.0 * v0 * (2.0 - slide);
}

double slidAfter2s(const Scene& scene) {
    PhysicsWorld w(scene);
    for (int i = 0; i < stepsFor(2.0, w.settings()); ++i) w.step();
    return w.body(0).pos.x;
}

// The scene with its ground replaced by a static slab, top at y = 0, of its own values.
Scene onSlab(Scene s, std::optional<float> friction, std::optional<float> restitution) {
    s.world.ground = false;
    Object slab = staticShape(ShapeType::Box, {0.0f, -0.5f, 0.0f});
    slab.size = {20.0f, 0.5f, 2.0f};
    slab.friction = friction;
    slab.restitution = restitution;
    s.objects.push_back(slab);
    return s;
}

}  // namespace

// The world says e = 0.2; a ball of its own e = 0.8 bounces to 0.64 m, one without to 0.04 m;
// on a static slab of e = 0.8 (the ground off) a ball without its own value takes the slab's.
TEST(PhysicsSurfaces, TheLargerRestitutionOfAPairSetsTheBounce) {
    const double sampling = kG * (1.0 / 120) * (1.0 / 120) / 8.0 + 1e-9;
    Scene plain = bounceScene(1.0f, 0.2f);
    EXPECT_NEAR(firstApex(plain), 0.04, sampling);
    Scene own = plain;
    own.objects[0].restitution = 0.8f;
    const double e = double(0.8f);
    EXPECT_NEAR(firstApex(own), e * e, sampling) << "the ball's own restitution";
    EXPECT_NEAR(firstApex(onSlab(plain, std::nullopt, 0.8f)), e * e, sampling)
        << "the static slab's own restitution";
}

// The world (and so the ground) says μ = 0.3 and the ball μ = 0.6: on the ground it slides
// with √(0.3·0.6); on a static slab of μ = 0.6 (the ground off) with 0.6, half as long as at
// 0.3. Within the Euler lag of the existing slide test, μ·g·h/2 per second of sliding, h the
// substep.
TEST(PhysicsSurfaces, ThePairsFrictionIsTheGeometricMean) {
    const double v0 = 5.0, world = double(0.3f), own = double(0.6f);
    const double lag = own * kG * (1.0 / 480) * 1.0 + 1e-9;
    Scene ground = slideScene(float(v0), 0.3f);
    ground.world.rolling = 0.0f;
    ground.objects[0].friction = 0.6f;
    EXPECT_NEAR(slidAfter2s(ground), slideDistance(v0, std::sqrt(world * own)), lag)
        << "the ball's μ against the ground's (the world's)";
    EXPECT_NEAR(slidAfter2s(onSlab(ground, 0.6f, std::nullopt)), slideDistance(v0, own), lag)
        << "the ball's μ against the slab's own";
}
