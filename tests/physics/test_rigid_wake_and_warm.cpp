// test_rigid_wake_and_warm.cpp — waking and warm starting as a whole world shows them: a sphere
// asleep on the ground that a box hits rolls away, a row of sleeping boxes hit at one end moves
// as one, and rigid contacts that start each point from its own last impulse hold what static
// friction holds, and a stack kept awake, still.
// (test_solver_gaps.cpp holds the rigid bodies' own cases: a sleeping box hit by a ball or a box,
// and each corner's warm start read off the first substep.)
#include "marchbox/physics/physics.h"
#include "marchbox/report/physics_scenes.h"
#include "physics_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>

using namespace mb;
using glm::dvec3;

namespace {

void run(PhysicsWorld& w, double seconds) {
    for (int i = 0; i < stepsFor(seconds, w.settings()); ++i) w.step();
}

}  // namespace

// A frictionless box of 1 kg sliding at v = 2 m/s into a ball (1 kg, r = 0.1 m) asleep on the
// ground (μ = 0.5, e = 0, no rolling resistance). The face pushes through the ball's centre and
// shares no friction (√(0·μ) = 0), so the ground's friction at the ball's foot is the pair's only
// horizontal force: it takes from the pair's momentum, m·v, what it gives the ball's spin about
// its centre, I·ω/r. The box keeps pushing until the ball rolls, and then both go on at one speed
// u: 2·m·u + (2/5)·m·u = m·v, u = 5·v/12 = 0.833 m/s, the ball rolling (ω·r = u). Measured
// 0.8334 m/s for both. The tolerance is a tenth of the sleep speed (0.05 m/s). Planted:
// RigidBodies::wake leaving the spheres' islands asleep (the box's contact holds the ball fixed):
// the ball stays at 0 m/s and the box stops dead at its face.
TEST(RigidWakeAndWarm, BoxSlidIntoASleepingBallRollsItAway) {
    const float v = 2.0f, r = 0.1f;
    Scene s = physicsWorld(9.81f, 0.0f, 0.5f, true);
    s.world.rolling = 0.0f;
    s.objects.push_back(dynamicSphere({0, r, 0}, r, 1.0f));
    Object slider = dynamicBox({-3.0f, r, 0}, {r, r, r}, 1.0f);  // meets the ball after 1.4 s
    slider.vel = {v, 0, 0};
    slider.friction = 0.0f;
    s.objects.push_back(slider);
    PhysicsWorld w(s);
    run(w, 1.3);
    ASSERT_FALSE(w.body(0).awake) << "the ball should sleep before the box comes";
    run(w, 1.7);
    const double u = 5.0 * double(v) / 12.0, tolerance = 0.1 * w.settings().sleepSpeed;
    const PhysicsBody& ball = w.body(0);
    std::printf("ball %.4f m/s (rolling %.4f m/s), box %.4f m/s; u = %.4f m/s\n", ball.vel.x,
                -ball.spin.z * r, w.rigid(0).vel.x, u);
    EXPECT_NEAR(ball.vel.x, u, tolerance) << "the sleeping ball was not woken by the box";
    EXPECT_NEAR(-ball.spin.z * double(r), u, tolerance) << "the ball does not roll";
    EXPECT_NEAR(w.rigid(0).vel.x, u, tolerance) << "the box stopped at the ball";
}

// A box (0.4 × 0.2 × 0.3 m) on a 25° slope with μ = 0.5: tan 25° = 0.466 < μ, so static friction
// holds it and it should not move at all. Kept awake (a sleeping box is not solved), its four
// corners carry different loads, the downhill ones more (friction acts below the centre of mass).
// Which corner a wrong warm start copies depends on the corners' order, so the box is tried as
// placed and turned half round about the slope's normal. Measured: 5e-8 m and 5e-5 m in the 10 s
// after it settles (other boxes and turns, on slopes of 10° to 26°: at most 0.14 mm); allowed
// 0.5 mm. Planted: contact keys without the probe byte, so each corner starts each step from one
// corner's impulse: the box creeps down the slope at 0.35 mm/s, 3.5 mm in 10 s either way round
// (keys masked in the table instead of in the contact: 0.08 µm as placed, 4.1 mm turned).
TEST(RigidWakeAndWarm, BoxHeldByFrictionOnASlopeStaysPutWhileAwake) {
    PhysicsSettings settings;
    settings.sleep = false;
    for (float turn : {0.0f, 180.0f}) {
        Scene s = slopeScene(25.0f, 0.5f, dynamicBox({}, {0.2f, 0.1f, 0.15f}));
        s.objects.back().rot.y = turn;
        PhysicsWorld w(s, settings);
        run(w, 1.0);  // settles into its contacts
        const dvec3 settled = w.rigid(0).pos;
        run(w, 10.0);
        const double crept = glm::length(w.rigid(0).pos - settled);
        std::printf("box on a 25 deg slope, turned %.0f deg: crept %.3g m in 10 s\n", turn, crept);
        EXPECT_LT(crept, 5e-4) << "a box that static friction holds creeps down the slope (turned "
                               << turn << " deg)";
    }
}

// Ten unit boxes stacked (μ = 0.6), kept awake for a minute after they settle into their
// contacts (the first second, 1.2 cm: each contact squeezed under the weight above): nothing
// pushes the stack sideways, so its top should stay where it settled. Measured: 0.36 mm;
// allowed 2 mm. Planted: contact keys without the probe byte: each corner starts from another's
// impulse, the stack sways, its top 34 cm off by 10 s, and it falls (19.6 m by 60 s).
TEST(RigidWakeAndWarm, TenBoxStackKeptAwakeStandsAMinute) {
    PhysicsSettings settings;
    settings.sleep = false;
    PhysicsWorld w(boxStackScene(10), settings);
    const dvec3 placed = w.rigid(9).pos;
    run(w, 1.0);
    const dvec3 settled = w.rigid(9).pos;
    run(w, 60.0);
    const double moved = glm::length(w.rigid(9).pos - settled);
    std::printf("awake stack: settled %.4g m, then the top moved %.3g m in 60 s\n",
                glm::length(settled - placed), moved);
    EXPECT_LT(moved, 0.002) << "the stack's top drifted";
}

// A frictionless box (1 kg, 2 m/s) slides into a row of three 1 kg boxes asleep side by side,
// face to face, on the ground (μ = 0.5, e = 0). The row must wake whole: the four then move as
// one at u = v/4 = 0.5 m/s, and the ground's friction on the three, 3·μ·m·g over the four
// masses, stops them in u²/(2·¾·μ·g) = 3.4 cm. The same row kept awake is the reference: the
// far box ends within 5 mm of where it ends then, and so does the slider. Measured: 3.29 cm
// asleep, 3.30 awake; the slider 4.4 mm apart (the soft contacts' squeeze). Planted: a woken
// box leaving its sleeping neighbours asleep (sleeping pairs make no contacts, so the first box
// is held by the second, still fixed): the far box does not move and the slider bounces back
// 0.29 m.
TEST(RigidWakeAndWarm, ARowOfSleepingBoxesHitAtOneEndMovesAsOne) {
    auto run3s = [](bool sleep) {
        Scene s = physicsWorld(9.81f, 0.0f, 0.5f, true);
        for (int k = 0; k < 3; ++k)
            s.objects.push_back(dynamicBox({0.2f * float(k), 0.1f, 0}, {0.1f, 0.1f, 0.1f}, 1.0f));
        Object slider = dynamicBox({-3.0f, 0.1f, 0}, {0.1f, 0.1f, 0.1f}, 1.0f);
        slider.vel = {2.0f, 0, 0};
        slider.friction = 0.0f;
        s.objects.push_back(slider);
        PhysicsSettings settings;
        settings.sleep = sleep;
        PhysicsWorld w(s, settings);
        run(w, 1.3);  // the row asleep before the slider comes (1.4 s)
        if (sleep) {
            EXPECT_EQ(w.stats().awake, 1) << "the row should sleep before it is hit";
        }
        run(w, 1.7);
        return std::pair{w.rigid(2).pos.x - 0.4, w.rigid(3).pos.x};
    };
    const auto [slept, sliderSlept] = run3s(true);
    const auto [awake, sliderAwake] = run3s(false);
    const double mu = 0.5, g = 9.81, u = 0.5, closedForm = u * u / (2.0 * 0.75 * mu * g);
    std::printf(
        "far box moved %.4f m asleep, %.4f m awake (closed form %.4f); slider at %.4f "
        "and %.4f\n",
        slept, awake, closedForm, sliderSlept, sliderAwake);
    EXPECT_NEAR(slept, awake, 5e-3) << "the sleeping row did not move as the awake one";
    EXPECT_NEAR(sliderSlept, sliderAwake, 5e-3) << "the slider stopped at the sleeping row";
}

// A box dropped onto the 256th of 300 static boxes sleeps within 2 s while another, 20 m away,
// is still falling from 100 m (for 4.5 s): the two share no island. A static surface's manifold
// key held its feature in the byte above the probe's, so from feature 256 on it spilled into the
// second body's bits and named body 0: the resting box joined the falling one's island, and
// stayed awake as long as it fell.
TEST(RigidWakeAndWarm, ABoxOnTheManyHundredthStaticBoxSleepsAlone) {
    Scene s = physicsWorld(9.81f, 0.0f, 0.6f, true);
    s.objects.push_back(dynamicBox({-20.0f, 100.0f, 0}, glm::vec3(0.2f)));
    for (int k = 0; k < 300; ++k)
        s.objects.push_back(staticBox({float(k), 0.4f, 0}, glm::vec3(0.4f)));
    s.objects.push_back(dynamicBox({255.0f, 1.0f, 0}, glm::vec3(0.2f)));
    PhysicsWorld w(s);
    run(w, 2.0);
    ASSERT_TRUE(w.rigid(0).awake) << "the far box should still be falling";
    EXPECT_NEAR(w.rigid(1).pos.y, 1.0, 0.01) << "the box should rest on the 256th static box";
    EXPECT_FALSE(w.rigid(1).awake) << "the box at rest should sleep on its own";
}
