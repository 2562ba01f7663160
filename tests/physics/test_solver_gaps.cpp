// test_solver_gaps.cpp — two things the rigid bodies' solver must do that no other test watched:
// a sleeping body that a moving one hits wakes and is pushed, and each point of a manifold is
// warm started from its own impulse of the last step, not from another point's.
#include "marchbox/physics/physics.h"
#include "marchbox/report/physics_scenes.h"
#include "physics_test_util.h"
#include "rigid_bodies.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace mb;
using glm::dvec3;

namespace {

constexpr double kGravity = 9.81;
constexpr float kHalf = 0.1f;   // the boxes' half extent and the ball's radius, m
constexpr float kSpeed = 2.0f;  // m/s, the mover's along +x
constexpr float kFriction = 0.5f;

// A box of 1 kg resting on the ground at the origin and, 3 m away along −x, `mover` (1 kg, its
// centre at the box's height) coming at kSpeed: it meets the box after 1.4 s, long after the box
// has slept (timeToSleep, 0.5 s). No restitution and no rolling resistance.
Scene hitScene(Object mover) {
    Scene s = physicsWorld(float(kGravity), 0.0f, kFriction, true);
    s.world.rolling = 0.0f;
    s.objects.push_back(dynamicBox({0, kHalf, 0}, {kHalf, kHalf, kHalf}, 1.0f));
    s.objects.push_back(mover);
    return s;
}

struct Hit {
    bool asleepBefore = false;  // the box slept until the mover came within 5 cm of it
    double boxMoved = 0.0;      // m along +x, by the end
    double moverOn = 0.0;       // m along +x past where the mover first touched the box
};

// 3 s: the hit and everything after it is over within 2 s. `moverX` reads the mover's centre.
template <class MoverX>
Hit runHit(const Scene& scene, MoverX moverX) {
    PhysicsWorld w(scene);
    const double touching = -2.0 * double(kHalf);  // the mover's centre where the faces meet
    const dvec3 start = w.rigid(0).pos;
    Hit hit;
    bool near = false;
    for (int i = 0; i < stepsFor(3.0, w.settings()); ++i) {
        if (!near && moverX(w) > touching - 0.05) {
            near = true;
            hit.asleepBefore = !w.rigid(0).awake;
        }
        w.step();
    }
    hit.boxMoved = w.rigid(0).pos.x - start.x;
    hit.moverOn = moverX(w) - touching;
    std::printf("box moved %.4f m, mover went on %.4f m\n", hit.boxMoved, hit.moverOn);
    return hit;
}

}  // namespace

// A ball rolling at v = 2 m/s (μ = 0.5, e = 0, equal masses) into a box asleep on the ground.
// The impact (impulse J ≤ m·v) leaves ball and box at one speed V along x (e = 0). Of the pair's
// momentum m·v, the ground's friction on the box takes at most μ times the box's weight over the
// step, m·g·dt, and the ball's spin dragging its face down, at most μ·J: so
// V ≥ v/2·(1 − μ²) − μ·g·dt/2 = 0.73 m/s. After it the box slows by at most μ·g (the ball's push
// exceeds the μ² times it that its drag adds to the friction), so it slides at least
// V²/(2·μ·g) = 5.4 cm; it went 13 cm. The ball is slowed only by the box (its spin drives it on)
// and follows it, within the speculative contact's reach of 4 slops. Planted: wake() leaving rigid
// bodies asleep; the box stays put and the ball stops dead at its face (moved 0.0000 m, went on
// −0.0009 m).
TEST(SolverGaps, BallRolledIntoASleepingBoxPushesItOn) {
    const double v = kSpeed, mu = kFriction, dt = PhysicsSettings{}.dt;
    Object ball = dynamicSphere({-3.0f, kHalf, 0}, kHalf, 1.0f, {kSpeed, 0, 0});
    ball.spin = {0, 0, -kSpeed / kHalf};  // rolling along +x
    const Hit hit = runHit(hitScene(ball), [](const PhysicsWorld& w) { return w.body(0).pos.x; });
    ASSERT_TRUE(hit.asleepBefore) << "the box should sleep on the ground before the ball comes";
    const double V = 0.5 * v * (1.0 - mu * mu) - 0.5 * mu * kGravity * dt;
    const double least = V * V / (2.0 * mu * kGravity);
    EXPECT_GT(hit.boxMoved, least) << "the sleeping box was not woken by the ball";
    EXPECT_GT(hit.moverOn, least - 4.0 * PhysicsSettings{}.linearSlop)
        << "the ball stopped at the box's face";
}

// A frictionless box sliding at v = 2 m/s into a box (μ = 0.5 on the ground, e = 0, equal
// masses) asleep on the ground: the two faces share no friction (√(0·μ) = 0). The impact leaves
// both at V ≥ v/2 − μ·g·dt/2 (the box's ground friction during the impact's step) = 0.98 m/s,
// and the slider keeps pushing, so the pair of 2m slows at μ·g/2 and goes V²/(μ·g): at least
// 19.6 cm, and no more than the impulsive (v/2)²/(μ·g) = 20.4 cm (and a slop); it went 20.05 cm.
// The slider is slowed only by the box and stays against it, within 4 slops. Planted: wake()
// leaving rigid bodies asleep; the box stays put and the slider stops at it and backs off
// (moved 0.0000 m, went on −0.057 m).
TEST(SolverGaps, BoxSlidIntoASleepingBoxPushesItOn) {
    const double v = kSpeed, mu = kFriction, dt = PhysicsSettings{}.dt;
    const double slop = PhysicsSettings{}.linearSlop;
    Object slider = dynamicBox({-3.0f, kHalf, 0}, {kHalf, kHalf, kHalf}, 1.0f);
    slider.vel = {kSpeed, 0, 0};
    slider.friction = 0.0f;
    const Hit hit =
        runHit(hitScene(slider), [](const PhysicsWorld& w) { return w.rigid(1).pos.x; });
    ASSERT_TRUE(hit.asleepBefore) << "the box should sleep on the ground before the slider comes";
    const double V = 0.5 * v - 0.5 * mu * kGravity * dt;
    const double least = V * V / (mu * kGravity), most = 0.25 * v * v / (mu * kGravity) + slop;
    EXPECT_GT(hit.boxMoved, least) << "the sleeping box was not woken by the slider";
    EXPECT_LT(hit.boxMoved, most);
    EXPECT_GT(hit.moverOn, least - 4.0 * slop) << "the slider stopped at the box's face";
}

namespace {

// What the warm start of a step's first substep gave the body: its change of velocity and spin.
struct WarmKick {
    dvec3 vel{0.0}, spin{0.0};
};

// One step of the rigid bodies alone, as PhysicsWorld::step takes it for a scene with no
// spheres (`spheres` holds only the static body).
WarmKick stepRigid(RigidBodies& rigid, std::vector<PhysicsBody>& spheres,
                   const PhysicsSettings& settings) {
    rigid.collide(spheres, kGravity);
    const double h = settings.dt / settings.substeps;
    const Softness soft = makeSoftness(0.125 / h, settings.contactDampingRatio, h);
    WarmKick kick;
    for (int k = 0; k < settings.substeps; ++k) {
        rigid.integrateVelocities(h, kGravity);
        const dvec3 vel = rigid.body(0).vel, spin = rigid.body(0).spin;
        rigid.warmStart();
        if (k == 0) kick = {rigid.body(0).vel - vel, rigid.body(0).spin - spin};
        rigid.solve(soft, h, true);
        rigid.integratePositions(h, kGravity);
        rigid.solve(soft, h, false);
    }
    rigid.restitute(settings.restitutionThreshold, kGravity);
    rigid.finishStep();
    return kick;
}

}  // namespace

// A box (0.4 × 0.2 × 0.3 m) held by friction on a 20° slope (μ = 0.5 > tan 20°) rests on four
// corners that carry different loads: friction acts at the contact plane, below the centre of
// mass, and the downhill corners take the torque it makes. At rest, last step's impulses balance
// gravity over a substep, so a warm start that gives each point its own impulse undoes the
// substep's gravity, Δv = g·h upward, and turns the box not at all, Δω = 0. The relax pass stops
// sweeping once no row changes its speed by more than 1e-3 m/s (kSweepTolerance), so the impulses
// it keeps balance to that: both |Δv − g·h| and |Δω|·R (R the box's reach) stay under 1e-3 m/s.
// They are ~1e-8 m/s here, but in a step where the manifold picks other corners, which start from
// nothing: at most a tenth of the steps may miss. Planted: contact keys without the probe byte,
// so each corner starts from the deepest corner's impulse: every step misses, |Δω|·R = 0.011 m/s
// and |Δv − g·h| up to 0.0045 m/s.
TEST(SolverGaps, EachCornerOfAManifoldWarmStartsFromItsOwnImpulse) {
    PhysicsSettings settings;
    settings.sleep = false;  // a sleeping box takes no impulses to warm start
    const Scene scene = slopeScene(20.0f, 0.5f, dynamicBox({}, {0.2f, 0.1f, 0.15f}));
    RigidBodies rigid(scene, settings);
    std::vector<PhysicsBody> spheres(1);  // the static body alone
    const double h = settings.dt / settings.substeps, tolerance = 1e-3;
    for (int i = 0; i < stepsFor(2.0, settings); ++i) stepRigid(rigid, spheres, settings);
    ASSERT_EQ(rigid.contactCount(), 4) << "the box should rest on four corners";
    const int steps = stepsFor(5.0, settings);
    int missed = 0;
    double worstVel = 0.0, worstSpin = 0.0;
    for (int i = 0; i < steps; ++i) {
        const WarmKick kick = stepRigid(rigid, spheres, settings);
        const double vel = glm::length(kick.vel - dvec3(0.0, kGravity * h, 0.0));
        const double spin = glm::length(kick.spin) * rigid.body(0).bound;
        worstVel = std::max(worstVel, vel);
        worstSpin = std::max(worstSpin, spin);
        if (vel > tolerance || spin > tolerance) ++missed;
    }
    std::printf(
        "warm start: %d of %d steps off balance; worst |dv - g h| %.3g m/s, |dw| R %.3g m/s\n",
        missed, steps, worstVel, worstSpin);
    EXPECT_LE(missed, steps / 10) << "the corners do not start from their own impulses";
}
