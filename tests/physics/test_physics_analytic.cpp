// test_physics_analytic.cpp — the simulator against closed-form motion. Each bound is derived
// from the method in the comment beside it; h = dt / substeps is the substep.
#include "marchbox/physics/physics.h"
#include "marchbox/report/physics_scenes.h"
#include "physics_test_util.h"

#include <gtest/gtest.h>

using namespace mb;
using glm::dvec3;

namespace {

constexpr double kG = double(9.81f);  // the scene stores gravity as a float

}  // namespace

// ExactGravity moves by v·h + ½·a·h² in free flight: exact for constant acceleration, so only
// rounding is left, about 1e-16 relative per substep over 960 substeps.
TEST(PhysicsAnalytic, FreeFallIsExactAtTheDefaultStep) {
    PhysicsWorld w(freeFallScene(100.0f));
    const PhysicsSettings& s = w.settings();
    for (int i = 0; i < stepsFor(2.0, s); ++i) w.step();
    EXPECT_NEAR(w.body(0).pos.y, 100.0 - 0.5 * kG * 4.0, 1e-9);
    EXPECT_NEAR(w.body(0).vel.y, -kG * 2.0, 1e-9);
}

// Symplectic Euler: y_n = y0 − g·h²·n(n+1)/2, which lags the exact −g·t²/2 by exactly g·t·h/2.
TEST(PhysicsAnalytic, FreeFallSymplecticEulerLagsByHalfGTH) {
    PhysicsSettings s;
    s.integrator = Integrator::SymplecticEuler;
    PhysicsWorld w(freeFallScene(100.0f), s);
    for (int i = 0; i < stepsFor(2.0, s); ++i) w.step();
    const double h = s.dt / s.substeps;
    EXPECT_NEAR(w.body(0).pos.y, 100.0 - 0.5 * kG * 4.0 - 0.5 * kG * 2.0 * h, 1e-9);
}

TEST(PhysicsAnalytic, ProjectileFollowsTheParabola) {
    const glm::vec3 v0(3.0f, 10.0f, -2.0f);
    PhysicsWorld w(projectileScene(v0));
    const double t = 1.5;
    for (int i = 0; i < stepsFor(t, w.settings()); ++i) w.step();
    const dvec3 expected = dvec3(v0) * t + dvec3(0, -0.5 * kG * t * t, 0);
    EXPECT_LT(glm::length(w.body(0).pos - expected), 1e-9);  // rounding only, as in free fall
    EXPECT_LT(glm::length(w.body(0).spin), 1e-12);
}

// Impacts are resolved at their time of impact (impacts.h): the flight to the ground
// is a parabola, the bounce turns the impact speed v into e·v, the flight after is a parabola
// again, and the step ends where that flight is. So a bounce keeps exactly e² of the height and
// the apexes are e^(2k)·h to rounding. What is left is how they are seen: the highest step end
// is at most g·(dt/2)²/2 = 8.5e-5 m below the true apex. Bound: that, plus 1e-9 of rounding
// (it is about 1e-15 per step), for the first five apexes, far inside 1 mm.
TEST(PhysicsAnalytic, BounceApexesFallAsEToTheTwoN) {
    const double e = double(0.8f);
    PhysicsWorld w(bounceScene(1.0f, float(e)));
    const double r = w.body(0).radius, h0 = w.body(0).pos.y - r, dt = w.settings().dt;
    double apex = 0.0, expected = h0, previousVy = 0.0;
    int bounce = 0;
    for (int i = 0; i < stepsFor(6.0, w.settings()) && bounce < 5; ++i) {
        w.step();
        const PhysicsBody& b = w.body(0);
        apex = std::max(apex, b.pos.y - r);
        if (previousVy < 0.0 && b.vel.y > 0.0) apex = 0.0;  // bounced: a new flight
        if (previousVy > 0.0 && b.vel.y <= 0.0) {
            ++bounce;
            expected *= e * e;
            EXPECT_LE(apex, expected + 1e-9) << "apex " << bounce;
            EXPECT_GE(apex, expected - kG * dt * dt / 8.0 - 1e-9) << "apex " << bounce;
            if (bounce == 3) {
                EXPECT_NEAR(apex, std::pow(e, 6.0) * h0, 1e-3);
            }
            std::printf("apex %d: %.9f m, e^%d·h = %.9f m\n", bounce, apex, 2 * bounce, expected);
        }
        previousVy = b.vel.y;
    }
    EXPECT_EQ(bounce, 5);
}

// A bounce loses (1 − e²) of the normal energy and nothing else: its velocity just after the
// impact step is the exact flight's, −e·v_impact + g·(time since the impact), to rounding.
TEST(PhysicsAnalytic, BounceVelocityIsExactAfterTheImpactStep) {
    const double e = double(0.8f);
    PhysicsWorld w(bounceScene(1.0f, float(e)));
    const double r = w.body(0).radius, h0 = w.body(0).pos.y - r, dt = w.settings().dt;
    const double fall = std::sqrt(2.0 * h0 / kG), impact = kG * fall;  // time and speed of impact
    const int step = int(std::ceil(fall / dt));  // the step that holds the impact
    for (int i = 0; i < step; ++i) w.step();
    const double after = step * dt - fall;
    EXPECT_NEAR(w.body(0).vel.y, e * impact - kG * after, 1e-9);
    EXPECT_NEAR(w.body(0).pos.y - r, e * impact * after - 0.5 * kG * after * after, 1e-9);
}

// One contact between two spheres is solved exactly: the normal row zeroes the approach and the
// restitution pass sets it to −e times the approach before the step. Rounding only.
class PhysicsHeadOn : public ::testing::TestWithParam<double> {};

TEST_P(PhysicsHeadOn, VelocitiesMatchAndMomentumIsConserved) {
    const double e = GetParam(), m1 = 1.0, m2 = 3.0, v1 = 2.0, v2 = -1.0;
    PhysicsWorld w(headOnScene(float(e), float(m1), float(m2), float(v1), float(v2)));
    const dvec3 p0 = momentum(w);
    for (int i = 0; i < stepsFor(1.0, w.settings()); ++i) w.step();
    const double u = (m1 * v1 + m2 * v2) / (m1 + m2);  // centre-of-mass velocity
    EXPECT_NEAR(w.body(0).vel.x, u - e * m2 * (v1 - v2) / (m1 + m2), 1e-9);
    EXPECT_NEAR(w.body(1).vel.x, u + e * m1 * (v1 - v2) / (m1 + m2), 1e-9);
    EXPECT_LT(glm::length(momentum(w) - p0), 1e-6 * glm::length(p0));
}

INSTANTIATE_TEST_SUITE_P(PhysicsRestitution, PhysicsHeadOn, ::testing::Values(0.0, 0.5, 1.0));

// Friction acts at the contact point, so angular momentum about it is conserved:
// m·v0·r = m·v·r + (2/5)·m·r²·ω with ω = v/r once rolling → v = 5/7·v0, spin = −v/r about z for
// motion along +x. The friction row reaches zero slip within one substep once the clamp
// releases, so only rounding remains. Position: Euler on x lags μ·g·h/2 per second of sliding.
TEST(PhysicsAnalytic, SlideTurnsIntoRollingAtFiveSevenths) {
    const double v0 = 5.0, mu = double(0.3f);
    Scene scene = slideScene(float(v0), float(mu));
    scene.world.rolling = 0.0f;  // pure Coulomb friction: rolling would otherwise slow down
    PhysicsWorld w(scene);
    const PhysicsSettings& s = w.settings();
    const double T = 2.0;
    for (int i = 0; i < stepsFor(T, s); ++i) w.step();
    const PhysicsBody& b = w.body(0);
    const double v = 5.0 / 7.0 * v0, slideTime = 2.0 * v0 / (7.0 * mu * kG);
    EXPECT_NEAR(b.vel.x, v, 1e-9 * v0);
    EXPECT_NEAR(b.spin.z, -v / b.radius, 1e-9 * v0 / b.radius);
    EXPECT_NEAR(b.spin.x, 0.0, 1e-12);
    const double x = v0 * slideTime - 0.5 * mu * kG * slideTime * slideTime + v * (T - slideTime);
    EXPECT_NEAR(b.pos.x, x, mu * kG * (s.dt / s.substeps) * slideTime + 1e-9);
    EXPECT_NEAR(b.pos.y, b.radius, 1e-9);
}

// A ball spinning in place at ω0 on the ground: friction at the contact point changes no angular
// momentum about it, I·ω0 = I·ω + m·v·r, and once it rolls ω = v/r: v = 2/7·ω0·r. As for the
// slide above, the friction row reaches zero slip within a substep once the clamp releases:
// rounding only (bound 2 %). Rolling resistance off: it would take angular momentum.
TEST(PhysicsAnalytic, SpinInPlaceTurnsIntoRollingAtTwoSevenths) {
    const double w0 = 10.0;
    Scene scene = spinScene(float(w0), 0.3f);
    scene.world.rolling = 0.0f;
    PhysicsWorld w(scene);
    for (int i = 0; i < stepsFor(3.0, w.settings()); ++i) w.step();
    const PhysicsBody& b = w.body(0);
    const double v = 2.0 / 7.0 * w0 * b.radius;
    EXPECT_NEAR(b.vel.x, v, 1e-9 * v);
    EXPECT_NEAR(b.vel.x, v, 0.02 * v);
    EXPECT_NEAR(b.spin.z * b.radius, -v, 1e-9 * v);
}

// Rolling resistance (SCENE_FORMAT.md `rolling` = c): a torque c·r·N against the roll. Rolling
// without slipping, m·a = −F and I·a/r = F·r − c·r·N with I = 2/5·m·r², N = m·g give a constant
// deceleration a = 5/7·c·g. The solver applies c·r·(normal impulse) per substep, so the
// deceleration is exact per substep; what is left is the friction row trailing the rolling row
// by one substep within a Gauss-Seidel pass, a velocity error of about c·g·h (4e-4 m/s here),
// not growing with time. Bound: 2·c·g·h on the speed, and the stop time within 1 %.
class PhysicsRolling : public ::testing::TestWithParam<double> {};

TEST_P(PhysicsRolling, RollingBallSlowsAtFiveSeventhsCG) {
    const double c = double(float(GetParam())), v0 = 2.0;
    PhysicsWorld w(rollScene(float(v0), float(c)));
    const PhysicsSettings& s = w.settings();
    const double a = 5.0 / 7.0 * c * kG, h = s.dt / s.substeps, T = 0.5 * v0 / a;  // half way
    for (int i = 0; i < stepsFor(T, s); ++i) w.step();
    const PhysicsBody& b = w.body(0);
    EXPECT_NEAR(b.vel.x, v0 - a * T, 2.0 * c * kG * h) << "deceleration " << (v0 - b.vel.x) / T;
    EXPECT_NEAR(b.spin.z * b.radius, -b.vel.x, 2.0 * c * kG * h) << "still rolling";
    EXPECT_NEAR(b.pos.x, v0 * T - 0.5 * a * T * T, 2.0 * c * kG * h * T);
    std::printf("rolling c = %g: v(%.3f s) = %.9f, exact %.9f\n", c, T, b.vel.x, v0 - a * T);
    // It stops at v0/a and then sleeps: friction changes the rate at which balls slow down.
    const double stop = v0 / a;
    for (int i = stepsFor(T, s); i < stepsFor(0.99 * stop, s); ++i) w.step();
    EXPECT_GT(w.body(0).vel.x, 0.0) << "stopped before " << 0.99 * stop << " s";
    for (int i = stepsFor(0.99 * stop, s); i < stepsFor(1.01 * stop + 1.0, s); ++i) w.step();
    EXPECT_LT(std::abs(w.body(0).vel.x), 1e-3) << "still rolling after " << 1.01 * stop << " s";
}

INSTANTIATE_TEST_SUITE_P(PhysicsRollingResistance, PhysicsRolling, ::testing::Values(0.02, 0.1));

// With rolling 0 nothing takes a rolling ball's energy: no slip, so friction does no work, and
// no torque. Rounding only, over 10 s (1e-9 relative).
TEST(PhysicsAnalytic, RollingZeroKeepsRolling) {
    const double v0 = 2.0;
    PhysicsWorld w(rollScene(float(v0), 0.0f));
    for (int i = 0; i < stepsFor(10.0, w.settings()); ++i) w.step();
    const PhysicsBody& b = w.body(0);
    EXPECT_NEAR(b.vel.x, v0, 1e-9);
    EXPECT_NEAR(b.spin.z * b.radius, -v0, 1e-9);
    EXPECT_NEAR(b.pos.x, v0 * 10.0, 1e-6);
}

// Newton's cradle, e = 1: a striker at 2 m/s into a touching row of four. Impacts are taken one
// after another (impacts.h): the striker's impact gives ball 1 its speed at the instant
// ball 1 touches ball 2, whose impact is then due at once, and so on down the row. Equal masses
// exchange velocities, so the last ball leaves at 2 m/s and the rest stop, to rounding (bound
// 1e-9, where ≥ 1.96 and ≤ 0.04 m/s would pass a plain solver).
TEST(PhysicsAnalytic, NewtonsCradleSendsOutTheLastBall) {
    const double v = 2.0;
    PhysicsWorld w(cradleScene(4, float(v)));
    const dvec3 p0 = momentum(w);
    const double e0 = w.kineticEnergy();
    for (int i = 0; i < stepsFor(1.0, w.settings()); ++i) {
        w.step();
        ASSERT_LE(w.kineticEnergy(), e0 * (1.0 + 1e-9)) << "step " << i;
    }
    const int last = w.bodyCount() - 1;
    EXPECT_NEAR(w.body(last).vel.x, v, 1e-9);
    EXPECT_GE(w.body(last).vel.x, 1.96);
    for (int i = 0; i < last; ++i) {
        EXPECT_LT(glm::length(w.body(i).vel), 1e-9) << "ball " << i;
        EXPECT_LE(glm::length(w.body(i).vel), 0.04) << "ball " << i;
    }
    EXPECT_LT(glm::length(momentum(w) - p0), 1e-9);
    EXPECT_NEAR(w.kineticEnergy(), e0, 1e-9 * e0);
    for (int i = 0; i < w.bodyCount(); ++i) std::printf("ball %d: v = %.9f\n", i, w.body(i).vel.x);
}

// Two strikers touching each other: the front one's impact runs down the row and sends out the
// last ball, then the back one's sends out the one before it, which follows the first at the
// same speed. Two in, two out, to rounding.
TEST(PhysicsAnalytic, NewtonsCradleTwoInTwoOut) {
    const double v = 1.5;
    Scene s = cradleScene(3, float(v));
    Object second = s.objects[0];
    second.pos.x -= 2.0f * second.radius;  // touching the first striker, at the same speed
    s.objects.insert(s.objects.begin(), second);
    PhysicsWorld w(s);
    for (int i = 0; i < stepsFor(1.0, w.settings()); ++i) w.step();
    const int n = w.bodyCount();
    for (int i = 0; i < n; ++i) {
        const double expected = i >= n - 2 ? v : 0.0;
        EXPECT_NEAR(w.body(i).vel.x, expected, 1e-9) << "ball " << i;
    }
}
