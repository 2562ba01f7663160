// Capsules against capsules and boxes in closed form (capsule_contacts.h): points, normals and
// separations against hand-worked geometry, exact to 1e-9 m (the sums are a few roundings).
#include "capsule_contacts.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mb {
namespace {

using glm::dquat;
using glm::dvec3;

constexpr double kExact = 1e-9;

const dquat kAlongX = glm::angleAxis(-0.5 * M_PI, dvec3(0, 0, 1));  // the local y axis to +x
const dquat kAlongZ = glm::angleAxis(0.5 * M_PI, dvec3(1, 0, 0));   // the local y axis to +z
const dquat kUpright(1.0, 0.0, 0.0, 0.0);

void expectNear(const dvec3& actual, const dvec3& expected, const char* what) {
    EXPECT_LT(glm::length(actual - expected), kExact)
        << what << " (" << actual.x << ", " << actual.y << ", " << actual.z << ")";
}

void expectContact(const PairContact& c, const dvec3& point, const dvec3& normal,
                   double separation) {
    expectNear(c.point, point, "point");
    expectNear(c.normal, normal, "normal");
    EXPECT_NEAR(c.separation, separation, kExact);
}

//-----------------------------------------------------------------------------
// Capsule against capsule
//-----------------------------------------------------------------------------

// One along x at the origin, one along z 0.19 above it and off to the side: their segments come
// closest at (0.05, 0, 0) and (0.05, 0.19, 0), radii 0.1 + 0.1 overlap by 1 cm, and the point
// lies midway between the surfaces, at y = 0.095.
TEST(CapsuleContacts, CrossedCapsulesTouchWhereTheirSegmentsComeClosest) {
    const auto found = collideCapsules({dvec3(0.0), kAlongX, 0.3, 0.1},
                                       {dvec3(0.05, 0.19, -0.07), kAlongZ, 0.3, 0.1}, 0.02);
    ASSERT_EQ(found.size(), 1u);
    expectContact(found[0], dvec3(0.05, 0.095, 0.0), dvec3(0, 1, 0), -0.01);
}

// A leaning capsule (axis (0.6, 0.8, 0)) with its lower end over a lying one: the end
// (0.1, 0.2, 0.02) against the point (0.1, 0, 0) under it, 0.2 · √1.01 apart. Their lines
// come closest at x = −0.05, below the end: clamping to the end moves the lying one's point.
TEST(CapsuleContacts, AnEndMeetsTheSideOfAnother) {
    const dquat leaning = glm::angleAxis(-std::asin(0.6), dvec3(0, 0, 1));
    const auto found = collideCapsules({dvec3(0.0), kAlongX, 0.3, 0.1},
                                       {dvec3(0.25, 0.4, 0.02), leaning, 0.25, 0.1}, 0.02);
    ASSERT_EQ(found.size(), 1u);
    const dvec3 d(0.0, 0.2, 0.02);
    const double len = glm::length(d), separation = len - 0.2;
    expectContact(found[0], dvec3(0.1, 0, 0) + (0.1 + 0.5 * separation) * d / len, d / len,
                  separation);
}

// Parallel capsules, the upper one shifted along x: they touch along x ∈ [0.05, 0.3], and the
// two ends of that line are the points, so the upper one rests on both.
TEST(CapsuleContacts, ParallelCapsulesTouchAtBothEndsOfTheirOverlap) {
    const dquat alongMinusX = glm::angleAxis(0.5 * M_PI, dvec3(0, 0, 1));
    for (const dquat& upper : {kAlongX, alongMinusX}) {
        const auto found = collideCapsules({dvec3(0.0), kAlongX, 0.3, 0.1},
                                           {dvec3(0.25, 0.19, 0.0), upper, 0.2, 0.1}, 0.02);
        ASSERT_EQ(found.size(), 2u);
        expectContact(found[0], dvec3(0.05, 0.095, 0), dvec3(0, 1, 0), -0.01);
        expectContact(found[1], dvec3(0.3, 0.095, 0), dvec3(0, 1, 0), -0.01);
        EXPECT_NE(found[0].feature, found[1].feature);
    }
}

// Crossing at β, one 0.19 above the other: the centre sinks deepest, and the ends of their
// overlap lie √(0.19² + (0.15·sin 2β)²) apart, higher: points that a turning pair would meet.
// At 2° they touch (1 cm deep, like the centre); at 30°, 3 cm apart, they are speculative.
TEST(CapsuleContacts, CapsulesCrossingAtAnAngleKeepTheirOverlapsEnds) {
    for (double degrees : {2.0, 30.0}) {
        const double beta = degrees * M_PI / 180.0;
        const dquat turned = glm::angleAxis(-beta, dvec3(0, 1, 0)) * kAlongX;
        const auto found = collideCapsules({dvec3(0.0), kAlongX, 0.3, 0.1},
                                           {dvec3(0, 0.19, 0), turned, 0.3, 0.1}, 0.05);
        ASSERT_EQ(found.size(), 3u) << degrees << "°";
        expectContact(found[0], dvec3(0, 0.095, 0), dvec3(0, 1, 0), -0.01);
        const double ends = std::hypot(0.19, 0.15 * std::sin(2.0 * beta)) - 0.2;
        EXPECT_NEAR(found[1].separation, ends, kExact) << degrees << "°";
        EXPECT_NEAR(found[2].separation, ends, kExact) << degrees << "°";
    }
}

TEST(CapsuleContacts, CapsulesApartBeyondReachDoNotTouch) {
    EXPECT_TRUE(collideCapsules({dvec3(0.0), kAlongX, 0.3, 0.1},
                                {dvec3(0, 0.23, 0), kAlongZ, 0.3, 0.1}, 0.02)
                    .empty());
}

//-----------------------------------------------------------------------------
// Capsule against box
//-----------------------------------------------------------------------------

// A box at the origin, top face at y = 0.1; turned and moved as a whole, the same contacts turn
// and move with it.
const BoxPose kSlab{dvec3(0.0), kUpright, dvec3(0.5, 0.1, 0.4)};
const dquat kTurn = glm::normalize(dquat(0.9, 0.2, -0.3, 0.25));
const dvec3 kMove(1.0, -2.0, 0.5);

std::vector<PairContact> collideTurned(const CapsulePose& c, const BoxPose& b, double reach) {
    std::vector<PairContact> found =
        collideCapsuleBox({kTurn * c.centre + kMove, kTurn * c.orient, c.half, c.radius},
                          {kTurn * b.centre + kMove, kTurn * b.orient, b.half}, reach);
    for (PairContact& f : found) {  // back to the untouched frame
        f.point = glm::conjugate(kTurn) * (f.point - kMove);
        f.normal = glm::conjugate(kTurn) * f.normal;
    }
    return found;
}

// Lying on the top face, 2 mm deep: two points under its segment's ends, x = −0.1 and 0.3,
// midway between the surfaces (y = 0.099), the normal straight down into the box.
TEST(CapsuleContacts, CapsuleLyingOnABoxFaceTouchesUnderBothEnds) {
    for (bool turn : {false, true}) {
        const CapsulePose lying{dvec3(0.1, 0.198, 0.05), kAlongX, 0.2, 0.1};
        const auto found =
            turn ? collideTurned(lying, kSlab, 0.02) : collideCapsuleBox(lying, kSlab, 0.02);
        ASSERT_EQ(found.size(), 2u);
        expectContact(found[0], dvec3(-0.1, 0.099, 0.05), dvec3(0, -1, 0), -0.002);
        expectContact(found[1], dvec3(0.3, 0.099, 0.05), dvec3(0, -1, 0), -0.002);
    }
}

// Longer than the face (x from −0.15 to 0.75 over a face ending at 0.5): the line ends at the
// face's edge, not beyond it.
TEST(CapsuleContacts, CapsuleOverhangingAFaceTouchesUpToItsEdge) {
    const auto found = collideCapsuleBox({dvec3(0.3, 0.198, 0.0), kAlongX, 0.45, 0.1}, kSlab, 0.02);
    ASSERT_EQ(found.size(), 2u);
    expectContact(found[0], dvec3(-0.15, 0.099, 0), dvec3(0, -1, 0), -0.002);
    expectContact(found[1], dvec3(0.5, 0.099, 0), dvec3(0, -1, 0), -0.002);
}

// Tilted 30° with its lower end 1 mm into the face: that end alone (the upper one is 0.2 m up).
TEST(CapsuleContacts, TiltedCapsuleTouchesAFaceAtItsLowerEnd) {
    const double t = M_PI / 6.0;
    const dvec3 axis(std::cos(t), std::sin(t), 0.0), end(0.0, 0.199, 0.0);
    const dquat tilted = glm::angleAxis(t - 0.5 * M_PI, dvec3(0, 0, 1));
    const auto found = collideTurned({end + 0.2 * axis, tilted, 0.2, 0.1}, kSlab, 0.02);
    ASSERT_EQ(found.size(), 1u);
    expectContact(found[0], dvec3(0, 0.0995, 0), dvec3(0, -1, 0), -0.001);
}

// Across the box's top edge (x = 0.5, y = 0.1), 0.1 from it along (0.6, 0.8): the normal points
// from the capsule at the edge, and it overlaps by radius − 0.1.
TEST(CapsuleContacts, CapsuleOnABoxEdgeTouchesAlongTheEdgesDiagonal) {
    const auto found = collideTurned({dvec3(0.56, 0.18, 0.0), kAlongZ, 0.2, 0.101}, kSlab, 0.02);
    ASSERT_EQ(found.size(), 1u);
    expectNear(found[0].normal, -dvec3(0.6, 0.8, 0.0), "normal");
    EXPECT_NEAR(found[0].separation, -0.001, kExact);
}

// Its segment inside the box, 5 cm below the top face and far from every other face: pushed
// out through the top, 0.05 + 0.1 deep, at both ends.
TEST(CapsuleContacts, SegmentInsideABoxLeavesThroughTheNearestFace) {
    const auto found = collideTurned({dvec3(0.1, 0.05, 0.0), kAlongX, 0.2, 0.1}, kSlab, 0.02);
    ASSERT_EQ(found.size(), 2u);
    expectContact(found[0], dvec3(-0.1, 0.05 - 0.1 + 0.075, 0), dvec3(0, -1, 0), -0.15);
    expectContact(found[1], dvec3(0.3, 0.05 - 0.1 + 0.075, 0), dvec3(0, -1, 0), -0.15);
}

}  // namespace
}  // namespace mb
