// test_pair_cache.cpp — a pair's points kept while the pair barely moves (pair_cache.h): each
// end follows its own body, the separation follows the motion along the kept normal, and a pair
// that moved further, or was not met in the last step, is found anew.
#include "pair_cache.h"
#include "rigid_bodies.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

using namespace mb;
using glm::dquat;
using glm::dvec3;

namespace {

// a turned a quarter about y; b 1 m above it, turned about x. One point between them, 2 mm
// apart, its normal straight up: a's top face under b's bottom face.
struct Pair {
    RigidBody a, b;
    PairCandidate point;
};

Pair restingPair() {
    Pair p;
    p.a.pos = dvec3(0.5, 0.5, -0.25);
    p.a.orient = glm::angleAxis(glm::radians(90.0), dvec3(0, 1, 0));
    p.b.pos = p.a.pos + dvec3(0.1, 1.0, 0.0);
    p.b.orient = glm::angleAxis(glm::radians(30.0), dvec3(1, 0, 0));
    p.b.bound = 0.6;
    const dvec3 mid = p.a.pos + dvec3(0.2, 0.5, 0.1);
    p.point = {mid, dvec3(0, 1, 0), 0.002, 7, mid, mid + dvec3(0, 0.3, 0)};
    return p;
}

constexpr std::uint64_t kPair = 42;
constexpr double kReach = 0.02;

}  // namespace

TEST(PairCache, PointsFollowTheirBodiesWhileThePairBarelyMoves) {
    Pair p = restingPair();
    PairCache cache;
    cache.keep(kPair, p.a, p.b, kReach, {p.point});
    cache.nextStep();
    // The pair as a whole moves and turns (nothing changes between them), then b sinks 0.3 mm
    // into a and turns by half the bound about the normal.
    const dquat whole = glm::angleAxis(glm::radians(20.0), glm::normalize(dvec3(1, 2, 3)));
    const dvec3 lift(3, -1, 2);
    for (RigidBody* body : {&p.a, &p.b}) {
        body->pos = lift + whole * body->pos;
        body->orient = whole * body->orient;
    }
    const dvec3 up = p.a.orient *
                     glm::conjugate(glm::angleAxis(glm::radians(90.0), dvec3(0, 1, 0))) *
                     dvec3(0, 1, 0);  // the kept normal, where a now faces
    const dquat turn = glm::angleAxis(glm::radians(0.5 * PairCache::kTurnedMost), up);
    const dvec3 spot = p.b.pos;  // b turns about its own origin
    p.b.pos = spot - 3e-4 * up;
    p.b.orient = turn * p.b.orient;
    std::vector<PairCandidate> found;
    ASSERT_TRUE(cache.reuse(kPair, p.a, p.b, kReach, &found));
    ASSERT_EQ(found.size(), 1u);
    const PairCandidate& c = found[0];
    EXPECT_LT(glm::length(c.normal - up), 1e-12) << "the normal did not turn with a";
    EXPECT_EQ(c.probe, 7);
    // b's end of the point: where b carries it, from the point that was 1 mm above the middle.
    const dvec3 onB =
        p.b.pos + turn * (lift + whole * (p.point.point + 0.001 * dvec3(0, 1, 0)) - spot);
    const dvec3 onA = lift + whole * (p.point.point - 0.001 * dvec3(0, 1, 0));
    EXPECT_LT(glm::length(c.point - 0.5 * (onA + onB)), 1e-12);
    EXPECT_NEAR(c.separation, glm::dot(onB - onA, up), 1e-12);
    EXPECT_NEAR(c.separation, 0.002 - 3e-4, 2e-5) << "the sinking did not close the gap";
}

TEST(PairCache, APairThatMovedFurtherOrWasNotMetIsFoundAnew) {
    Pair p = restingPair();
    std::vector<PairCandidate> found;
    PairCache cache;
    cache.keep(kPair, p.a, p.b, kReach, {p.point});
    cache.nextStep();
    RigidBody slid = p.b;
    slid.pos.x += 1.5 * PairCache::kMovedMost;
    EXPECT_FALSE(cache.reuse(kPair, p.a, slid, kReach, &found)) << "slid past the bound";
    RigidBody turned = p.b;
    turned.orient =
        glm::angleAxis(glm::radians(1.5 * PairCache::kTurnedMost), dvec3(0, 0, 1)) * p.b.orient;
    EXPECT_FALSE(cache.reuse(kPair, p.a, turned, kReach, &found)) << "turned past the bound";
    EXPECT_TRUE(cache.reuse(kPair, p.a, p.b, kReach, &found));
    cache.nextStep();  // reused in that step: kept for the next
    EXPECT_TRUE(cache.reuse(kPair, p.a, p.b, kReach, &found));
    cache.nextStep();
    cache.nextStep();  // a step in which the pair was not met
    EXPECT_FALSE(cache.reuse(kPair, p.a, p.b, kReach, &found)) << "kept past a step unmet";
}

// Nothing was within the reach it was searched to: nothing is while the reach now, plus how far
// b's surface can have come (its shift, its turn times its bound), stays inside that.
TEST(PairCache, APairWithNothingNearStaysApartWhileItCannotHaveCome) {
    Pair p = restingPair();
    std::vector<PairCandidate> found{p.point};
    PairCache cache;
    cache.keep(kPair, p.a, p.b, kReach, {});
    cache.nextStep();
    RigidBody moved = p.b;
    moved.pos.y -= 0.004;
    moved.orient = glm::angleAxis(0.01, dvec3(0, 0, 1)) * p.b.orient;  // 0.6 · 0.01 = 6 mm more
    EXPECT_TRUE(cache.reuse(kPair, p.a, moved, 0.009, &found));
    EXPECT_TRUE(found.empty());
    EXPECT_FALSE(cache.reuse(kPair, p.a, moved, 0.011, &found)) << "it may have come within reach";
}
