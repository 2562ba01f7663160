// test_physics_world.cpp — driving the simulator: step counts, determinism, frame rates.
#include "marchbox/physics/physics.h"
#include "marchbox/report/physics_scenes.h"
#include "marchbox/scene/scene_io.h"
#include "physics_test_util.h"

#include <gtest/gtest.h>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

using namespace mb;

namespace {

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

Scene torusPile() {
    Scene s = pileScene(60, 11);
    Object torus;
    torus.type = ShapeType::Torus;
    torus.pos = {0.0f, 0.3f, 0.0f};
    torus.radius = 0.5f;
    torus.minor = 0.1f;
    torus.isStatic = true;
    s.objects.push_back(torus);
    return s;
}

}  // namespace

TEST(PhysicsWorld, SimulateTakesRoundedStepsAndWritesStateBack) {
    Scene s = projectileScene({1.0f, 2.0f, 0.0f});
    EXPECT_EQ(simulate(s, 1.0), 120);
    EXPECT_NEAR(s.objects[0].vel.y, 2.0 - 9.81, 1e-5);
    EXPECT_NEAR(s.objects[0].pos.x, 1.0, 1e-6);
    Scene t = projectileScene({0.0f, 0.0f, 0.0f});
    EXPECT_EQ(simulate(t, 0.5041), 60);  // 60.49 steps round down
    EXPECT_EQ(simulate(t, 0.5042), 61);  // 60.50 rounds up
}

// Zero seconds are no steps, and the scene is left as it was, field for field: a render at t = 0
// builds no world (a group of forty coins repeated 512 times took 20 s to build).
TEST(PhysicsWorld, ZeroSecondsLeaveTheSceneAsItWas) {
    Scene s = pileScene(20, 3);
    s.objects[0].orient = glm::normalize(glm::quat(0.9f, 0.1f, 0.2f, 0.3f));
    const Scene before = s;
    EXPECT_EQ(simulate(s, 0.0), 0);
    EXPECT_TRUE(s == before);
}

// A run of 250 steps reports each hundredth once, in order, ending at the whole run; the
// state is the one a run without progress reaches.
TEST(PhysicsWorld, SimulateReportsEachHundredthOfItsSteps) {
    static std::vector<double> reported;
    reported.clear();
    Scene s = projectileScene({1.0f, 2.0f, 0.0f}), quiet = s;
    EXPECT_EQ(simulate(s, 250.0 / 120, {}, [](double done) { reported.push_back(done); }), 250);
    ASSERT_EQ(reported.size(), 100u);
    for (size_t i = 0; i < reported.size();
         ++i)  // step ceil(2.5 (i + 1)) is the first past i + 1 %
        EXPECT_DOUBLE_EQ(reported[i], std::ceil(2.5 * double(i + 1)) / 250.0) << i;
    simulate(quiet, 250.0 / 120);
    EXPECT_EQ(s.objects[0].pos, quiet.objects[0].pos);
    EXPECT_EQ(s.objects[0].vel, quiet.objects[0].vel);
}

TEST(PhysicsWorld, AccumulatorClampsALongFrame) {
    PhysicsSettings s;
    StepAccumulator acc;
    EXPECT_EQ(acc.advance(1.0, s), 30);  // clamped to maxFrame = 0.25 s
    EXPECT_EQ(acc.advance(0.5 / 120, s), 0);
    EXPECT_EQ(acc.advance(0.5 / 120, s), 1);
    EXPECT_NEAR(acc.acc, 0.0, 1e-12);
}

// Same scene, frames of 1/30, 1/60 and 1/144 s for one second: all take the same 120 fixed
// steps, so the end states must be identical to the bit.
TEST(PhysicsWorld, FrameRateDoesNotChangeTheResult) {
    const Scene scene = torusPile();
    std::uint64_t hashes[3];
    const int rates[3] = {30, 60, 144};
    for (int k = 0; k < 3; ++k) {
        PhysicsWorld w(scene);
        StepAccumulator acc;
        for (int frame = 0; frame < rates[k]; ++frame)
            for (int n = acc.advance(1.0 / rates[k], w.settings()); n > 0; --n) w.step();
        EXPECT_EQ(w.stepCount(), 120) << rates[k] << " Hz";
        hashes[k] = stateHash(w);
    }
    EXPECT_EQ(hashes[0], hashes[1]);
    EXPECT_EQ(hashes[0], hashes[2]);
}

// Golden hash of a pile falling onto a torus for 1.5 s. A change in any arithmetic of the step
// changes it: update it deliberately, with the reason in the commit.
TEST(PhysicsWorld, DeterminismHash) {
    const std::uint64_t golden = 0xe4b80c2abff286a8ull;
    PhysicsWorld a(torusPile()), b(torusPile());
    for (int i = 0; i < stepsFor(1.5, a.settings()); ++i) {
        a.step();
        b.step();
    }
    EXPECT_EQ(stateHash(a), stateHash(b)) << "two runs differ";
    EXPECT_EQ(stateHash(a), golden) << "actual hash: 0x" << std::hex << stateHash(a) << "ull";
}

// The solver's two halves share no body, so a second thread changes nothing: the same bytes.
TEST(PhysicsWorld, TwoThreadsGiveTheSameBytesAsOne) {
    PhysicsSettings one, two;
    one.threads = 1;
    two.threads = 2;
    const Scene scene = pileScene(300, 5);
    PhysicsWorld a(scene, one), b(scene, two);
    int split = 0;  // steps where the halves were solved at once
    for (int i = 0; i < stepsFor(1.0, one); ++i) {
        a.step();
        b.step();
        split += b.stats().halves > 0 ? 1 : 0;
    }
    EXPECT_GT(split, 0) << "the pile never split: the test would not see the second thread";
    EXPECT_EQ(stateHash(a), stateHash(b));
}

// CPUs without AVX2 solve a batch of four contacts in halves of two (contact_batches.cpp); the
// lanes are independent, so they give the bytes this CPU's own code gives, which on the machines
// tests run on is four wide.
TEST(PhysicsWorld, TwoLanesGiveTheSameBytesAsThisCpusLanes) {
    PhysicsSettings own, halves;
    halves.twoLanes = true;
    const Scene scene = pileScene(300, 5);
    PhysicsWorld a(scene, own), b(scene, halves);
    for (int i = 0; i < stepsFor(1.0, own); ++i) {
        a.step();
        b.step();
    }
    EXPECT_EQ(stateHash(a), stateHash(b));
}

// tests/scenes/split_pile.txt is the scene cli.files simulates on one thread and on two to
// compare their bytes: that says something only if its contacts are many enough to be split.
TEST(PhysicsWorld, TheCliThreadsSceneSplitsItsContacts) {
    Scene scene;
    std::vector<std::string> errors;
    ASSERT_TRUE(loadScene(std::string(MARCHBOX_SOURCE_DIR) + "/tests/scenes/split_pile.txt", &scene,
                          &errors))
        << (errors.empty() ? "" : errors[0]);
    PhysicsSettings two;
    two.threads = 2;
    PhysicsWorld w(scene, two);
    int split = 0;
    for (int i = 0; i < stepsFor(1.5, two); ++i) {
        w.step();
        split += w.stats().halves > 0 ? 1 : 0;
    }
    EXPECT_GT(split, stepsFor(1.0, two)) << "the contacts were split on only " << split << " steps";
}
