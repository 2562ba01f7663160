// test_group_bodies.cpp — dynamic groups as rigid bodies, and the version 3 shapes (cone,
// ellipsoid, round, shell) as bodies, against closed forms.
#include "group_body.h"
#include "mass_moments.h"
#include "rigid_body.h"

#include "marchbox/physics/physics.h"
#include "marchbox/report/physics_scenes.h"
#include "marchbox/scene/scene_io.h"
#include "physics_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

using namespace mb;
using glm::dmat3;
using glm::dquat;
using glm::dvec3;

namespace {

constexpr double kG = 9.81;

void run(PhysicsWorld& w, double seconds) {
    for (int i = 0; i < stepsFor(seconds, w.settings()); ++i) w.step();
}

std::string num(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

std::string vec(dvec3 v) { return num(v.x) + "," + num(v.y) + "," + num(v.z); }

// FNV-1a over every body's state: the spheres', then the rigid bodies' and groups'.
std::uint64_t stateHash(const PhysicsWorld& w) {
    std::uint64_t h = 1469598103934665603ull;
    auto add = [&h](const double* values, size_t n) {
        unsigned char bytes[13 * sizeof(double)];
        std::memcpy(bytes, values, n * sizeof(double));
        for (size_t k = 0; k < n * sizeof(double); ++k) h = (h ^ bytes[k]) * 1099511628211ull;
    };
    for (int i = 0; i < w.bodyCount(); ++i) {
        const PhysicsBody& b = w.body(i);
        const double v[9] = {b.pos.x, b.pos.y,  b.pos.z,  b.vel.x, b.vel.y,
                             b.vel.z, b.spin.x, b.spin.y, b.spin.z};
        add(v, 9);
    }
    for (int i = 0; i < w.rigidCount(); ++i) {
        const RigidState b = w.rigid(i);
        const double v[13] = {b.pos.x,    b.pos.y,    b.pos.z,   b.vel.x,  b.vel.y,
                              b.vel.z,    b.spin.x,   b.spin.y,  b.spin.z, b.orient.w,
                              b.orient.x, b.orient.y, b.orient.z};
        add(v, 13);
    }
    return h;
}

// A cup: a cylinder of radius 0.5 and height 0.8 less a cylinder of 0.44 that starts 0.06 above
// its bottom and pokes 0.06 above its rim (so the subtraction leaves no skin there).
std::string cup(const std::string& name, dvec3 pos, double mass) {
    return "group name:" + name + " pos:" + vec(pos) + " mass:" + num(mass) + "\n" +
           "object in:" + name + " type:cylinder pos:0,0,0 radius:0.5 height:0.8\n" +
           "object in:" + name + " type:cylinder pos:0,0.06,0 radius:0.44 height:0.8 op:subtract\n";
}

}  // namespace

// A tube of outer radius r0 and inner r1 (a cylinder less a longer coaxial one) rolls down a
// 10° slope without slipping, with a = g·sin θ / (1 + I/(m·r0²)), I/m = (r0² + r1²)/2. The
// distance along the slope, fitted by least squares to s0 + v0·t + a·t²/2 over 1 s, gives a
// within 1 %. Planted: the integrator's cubes without their own spread (h²/3 in ∫x·xᵀ dropped):
// the tube's I, integrated, comes out small and it rolls too fast (a 2.6 % over).
TEST(GroupBodies, TubeRollsDownASlopeAtItsClosedFormAcceleration) {
    const double r0 = 0.2, r1 = 0.12, degrees = 10.0, theta = degrees * M_PI / 180.0;
    const dvec3 along(std::cos(theta), std::sin(theta), 0.0);
    PhysicsWorld w(tubeSlopeScene(float(degrees), 0.8f, float(r0), float(r1)));
    ASSERT_EQ(w.rigidCount(), 1);
    const dvec3 start = w.rigid(0).centre;
    const double a = kG * std::sin(theta) / (1.0 + (r0 * r0 + r1 * r1) / (2.0 * r0 * r0));
    // Normal equations of s(t) = c0 + c1·t + c2·t², over the steps of 1 s.
    double m[3][4] = {};
    for (int i = 1; i <= stepsFor(1.0, w.settings()); ++i) {
        w.step();
        const double t = i * w.settings().dt, d = -glm::dot(w.rigid(0).centre - start, along);
        const double basis[3] = {1.0, t, t * t};
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c) m[r][c] += basis[r] * basis[c];
            m[r][3] += basis[r] * d;
        }
    }
    for (int p = 0; p < 3; ++p)  // Gauss–Jordan: three unknowns
        for (int r = 0; r < 3; ++r) {
            if (r == p) continue;
            const double f = m[r][p] / m[p][p];
            for (int c = 0; c < 4; ++c) m[r][c] -= f * m[p][c];
        }
    const double fitted = 2.0 * m[2][3] / m[2][2];
    std::printf("tube: a = %.5f m/s², closed form %.5f (%+.3f %%)\n", fitted, a,
                100.0 * (fitted / a - 1.0));
    EXPECT_NEAR(fitted, a, 0.01 * a);
    // Rolling, not sliding: the axis stays across the slope.
    EXPECT_GT(std::abs((w.rigid(0).orient * dvec3(0, 1, 0)).z), 0.999);
}

// Two unequal boxes as one group spinning with no gravity and nothing to touch, 10 s: the
// centre of mass, found from the group's origin and turn as written (the boxes' volumes, in
// closed form), stays where it began to 1e-6 m, and the angular momentum about it, I·ω with I
// summed box by box (parallel axes), keeps to 1e-6 of itself, while the origin circles it.
// Planted: the origin written back from the body's turn instead of the group's (orient, not
// orient·axes⁻¹): the centre found from it wanders by 0.08 m; the body started in the group's
// turn, not in its principal axes (orient = turn, not turn·axes): 0.09 off the group's turn.
TEST(GroupBodies, FreeGroupKeepsItsCentreAndAngularMomentum) {
    Scene s = sceneFromText(
        "scene version:3\n"
        "world gravity:0 ground:0\n"
        "group name:pair pos:0,2,0 rot:10,20,30 mass:3 spin:1.5,-2,3\n"
        "object in:pair type:box pos:0.35,0,0 size:0.25,0.1,0.15\n"
        "object in:pair type:box pos:-0.2,0.1,0.05 size:0.1,0.12,0.08 rot:0,0,30\n");
    PhysicsWorld w(s);
    ASSERT_EQ(w.rigidCount(), 1);
    struct Part {
        dvec3 pos, half;
        dquat turn;
    };
    const Part parts[2] = {
        {dvec3(s.objects[0].pos), dvec3(s.objects[0].size), dquat(s.objects[0].orientation())},
        {dvec3(s.objects[1].pos), dvec3(s.objects[1].size), dquat(s.objects[1].orientation())}};
    double volume[2], total = 0.0;
    for (int k = 0; k < 2; ++k)
        total += volume[k] = 8.0 * parts[k].half.x * parts[k].half.y * parts[k].half.z;
    const double mass = 3.0;
    auto centre = [&](const RigidState& b) {
        dvec3 c(0.0);
        for (int k = 0; k < 2; ++k) c += volume[k] / total * (b.pos + b.orient * parts[k].pos);
        return c;
    };
    auto momentum = [&](const RigidState& b) {
        const dvec3 c = centre(b);
        dmat3 inertia(0.0);
        for (int k = 0; k < 2; ++k) {
            const double m = mass * volume[k] / total;
            const dvec3 h2 = parts[k].half * parts[k].half;
            const dmat3 own(m / 3.0 * (h2.y + h2.z), 0, 0, 0, m / 3.0 * (h2.x + h2.z), 0, 0, 0,
                            m / 3.0 * (h2.x + h2.y));
            const dmat3 r = glm::mat3_cast(b.orient * parts[k].turn);
            const dvec3 d = b.pos + b.orient * parts[k].pos - c;
            inertia +=
                r * own * glm::transpose(r) + m * (dmat3(glm::dot(d, d)) - glm::outerProduct(d, d));
        }
        return inertia * b.spin;
    };
    const RigidState first = w.rigid(0);
    const dvec3 c0 = centre(first), l0 = momentum(first);
    EXPECT_LT(glm::length(first.pos - dvec3(s.groups[0].pos)), 1e-12) << "not where it was put";
    EXPECT_LT(glm::length(first.orient - dquat(s.groups[0].orientation())), 1e-7)
        << "not turned as it was put";
    EXPECT_LT(glm::length(first.centre - c0), 1e-6) << "the body's centre is not the boxes'";
    double drift = 0.0, turn = 0.0, circled = 0.0;
    for (int i = 0; i < stepsFor(10.0, w.settings()); ++i) {
        w.step();
        const RigidState b = w.rigid(0);
        drift = std::max(drift, glm::length(centre(b) - c0));
        turn = std::max(turn, glm::length(momentum(b) - l0) / glm::length(l0));
        circled = std::max(circled, glm::length(b.pos - first.pos));
    }
    std::printf("free group: centre moved %.3g m, |ΔL|/|L| %.3g, origin swept %.3f m\n", drift,
                turn, circled);
    EXPECT_LT(drift, 1e-6);
    EXPECT_LT(turn, 1e-6);
    EXPECT_GT(circled, 0.1) << "the origin should circle the centre of mass";
}

// A ball dropped into a cup standing on the ground ends inside it, resting on the inner floor
// (its centre r above it, within the contacts' slop), and the cup stays upright (within 1°).
// Over the mouth the cup's SDF, max(outer, −inner), is the distance to a lid that is not drawn:
// the ball is measured from the true surface. Planted: the bound taken as the distance (no
// projection): the ball rests on the lid, its centre 1 m up.
TEST(GroupBodies, CupCatchesABall) {
    Scene s = sceneFromText("scene version:3\nworld gravity:9.81 restitution:0.3 friction:0.5\n" +
                            cup("cup", dvec3(0, 0.4, 0), 0.5) +
                            "object type:sphere pos:0.05,2,0 radius:0.2 mass:0.3\n");
    PhysicsWorld w(s);
    ASSERT_EQ(w.rigidCount(), 1);
    ASSERT_EQ(w.bodyCount(), 1);
    run(w, 4.0);
    const PhysicsBody& ball = w.body(0);
    const RigidState c = w.rigid(0);
    const double floor = 0.06;  // the inner floor, above the ground
    std::printf("cup: ball at (%.4f, %.4f, %.4f), cup at %.4f, awake %d\n", ball.pos.x, ball.pos.y,
                ball.pos.z, c.pos.y, w.stats().awake);
    EXPECT_NEAR(ball.pos.y, floor + 0.2, PhysicsSettings{}.linearSlop) << "on the inner floor";
    EXPECT_LT(glm::length(glm::dvec2(ball.pos.x - c.pos.x, ball.pos.z - c.pos.z)), 0.44 - 0.2);
    EXPECT_GT((c.orient * dvec3(0, 1, 0)).y, std::cos(M_PI / 180.0)) << "tipped over";
    EXPECT_NEAR(c.pos.y, 0.4, PhysicsSettings{}.linearSlop) << "standing on its base";
}

// The certified integral of a box (half extents 0.5, 0.3, 0.4) with a hole of radius 0.15
// through it along y, 0.1 off centre along x, against the closed form (the box's moments less
// the cylinder's): volume, first and second moments each within the integral's stated bound (the
// straddling cells' own moments: 8 % of the volume at the simulator's depth). The bound is the
// certificate; the estimate itself came within 1.5e-4 of the volume and 5.5e-4 of each second
// moment, so it is held to 1e-3 as well (of the volume, and of the largest second moment, the
// first moments' and the off-diagonals' scale), which a bug under the bound still fails.
// Planted, each inside the loose certified bound and caught by 1e-3: a straddling cell counted
// as half inside whatever f says (the volume 0.4 % under); the cube's own spread h²/3 dropped
// from ∫x·xᵀ (S_yy 1.6 % under); the certificate's half-diagonal taken as the half side, which
// calls cells whole that the surface crosses (S_yy 0.11 % over).
TEST(GroupBodies, HoledBoxMassPropertiesMatchTheClosedFormWithinTheBound) {
    const HoledBox holed;
    const GroupShape shape = groupShapeOf(holedBoxScene(holed), 0);
    const auto start = std::chrono::steady_clock::now();
    const GroupMoments found = groupMoments(shape);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    ASSERT_FALSE(found.closedForm);
    const Moments& m = found.moments;
    const Moments& bound = found.integral.bound;
    const SolidMoments exact = holedBoxMoments(holed);
    std::printf("holed box: %ld evaluations, %ld straddling cells, %.0f ms\n",
                found.integral.evaluations, found.integral.straddling, ms);
    std::printf("  V %.7f exact %.7f (error %.2g, bound %.2g)\n", m.volume, exact.volume,
                m.volume - exact.volume, bound.volume);
    EXPECT_LE(std::abs(m.volume - exact.volume), bound.volume);
    EXPECT_LE(std::abs(m.volume - exact.volume), 1e-3 * exact.volume);
    const double scale = exact.second[0][0];  // the largest second moment
    for (int k = 0; k < 3; ++k) {
        const double error = m.first[k] - exact.first[k];
        std::printf("  s%d %.7f exact %.7f (error %.2g, bound %.2g)\n", k, m.first[k],
                    exact.first[k], error, bound.first[k]);
        EXPECT_LE(std::abs(error), bound.first[k]) << "axis " << k;
        EXPECT_LE(std::abs(error), 1e-3 * scale / holed.half.x) << "axis " << k;
    }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const double error = m.second[i][j] - exact.second[i][j];
            if (i == j)
                std::printf("  S%d%d %.7f exact %.7f (error %.2g, bound %.2g)\n", i, j,
                            m.second[i][j], exact.second[i][j], error, bound.second[i][j]);
            EXPECT_LE(std::abs(error), bound.second[i][j]) << i << j;
            EXPECT_LE(std::abs(error), 1e-3 * (i == j ? exact.second[i][j] : scale)) << i << j;
        }
}

// A frustum (base 0.3, top 0.1, height 0.6) stands on its base with its origin h/2 up; a pointed
// cone (base 0.3, height 0.6) dropped lying across lies on a generator, its origin h·r/(2·√(h² +
// r²)) up; an ellipsoid (0.4, 0.25, 0.3) tilted 8° rights itself onto its shortest axis, its
// centre 0.25 up. Each within the contacts' slop, after 4 s. Planted: the cone's rims left in
// its own frame, not moved to its centre of mass (the frustum rests 9 cm high, the cone on its
// side 2 cm low); the ellipsoid's support point found along the normal as the world has it, not
// as its own frame does (it sinks through the ground).
TEST(GroupBodies, ConeAndEllipsoidRestAtTheHeightTheirShapeGives) {
    const double h = 0.6, r = 0.3;
    Scene s = sceneFromText(
        "scene version:3\nworld restitution:0.2 friction:0.6\n"
        "object type:cone pos:-2,0.35,0 radius:0.3 top:0.1 height:0.6 mass:1\n"
        "object type:cone pos:0,0.5,0 radius:0.3 height:0.6 rot:0,0,90 mass:1\n"
        "object type:ellipsoid pos:2,0.5,0 size:0.4,0.25,0.3 rot:8,0,5 mass:1\n");
    PhysicsWorld w(s);
    ASSERT_EQ(w.rigidCount(), 3);
    run(w, 4.0);
    const double slop = PhysicsSettings{}.linearSlop;
    const double lying = h * r / (2.0 * std::sqrt(h * h + r * r));
    std::printf(
        "frustum origin %.4f (%.4f), cone on its side %.4f (%.4f), ellipsoid %.4f "
        "(0.25), awake %d\n",
        w.rigid(0).pos.y, h / 2, w.rigid(1).pos.y, lying, w.rigid(2).pos.y, w.stats().awake);
    EXPECT_NEAR(w.rigid(0).pos.y, h / 2, slop);
    EXPECT_GT((w.rigid(0).orient * dvec3(0, 1, 0)).y, 0.9999) << "the frustum tipped";
    EXPECT_NEAR(w.rigid(1).pos.y, lying, slop);
    EXPECT_NEAR(w.rigid(2).pos.y, 0.25, slop);
    EXPECT_GT(std::abs((w.rigid(2).orient * dvec3(0, 1, 0)).y), 0.9999) << "not on its short axis";
}

// A ball of radius 1 carved or hollowed is still a sphere where it was not cut: with a notch in
// its top, as its lower half (a dome down), or hollow, it rests with its centre 1 up; its upper
// half (a dome up) rests on its cut face, its centre on the ground. Each within the slop, after
// 3 s. Two notched balls of 0.5 meeting head-on (μ = 0, e = 0) stop 1 apart, with no sideways
// speed. Planted: a carved member's sphere left out of the probes (each ball sinks 10.9 cm onto
// the lattice's points, 27° apart; the pair, let in between those points, is pushed out and
// apart, 1.11 m at 0.2 m/s after 2 s); its contacts not checked against the solid (the dome up
// stands on the sphere it was cut from, 1 m high).
TEST(GroupBodies, ACarvedBallRestsOnTheSphereLeftOfIt) {
    Scene s = sceneFromText(
        "scene version:3\nworld restitution:0.1 friction:0.5\n"
        "group name:notch pos:0,1.2,0 mass:1\nobject in:notch type:sphere pos:0,0,0 radius:1\n"
        "object in:notch type:box pos:0,1,0 size:0.05,0.05,0.05 op:subtract\n"
        "group name:down pos:3,1.2,0 mass:1\nobject in:down type:sphere pos:0,0,0 radius:1\n"
        "object in:down type:box pos:0,-1,0 size:1,1,1 op:intersect\n"
        "group name:hollow pos:6,1.2,0 mass:1\n"
        "object in:hollow type:sphere pos:0,0,0 radius:1 shell:0.1\n"
        "group name:up pos:9,0.2,0 mass:1\nobject in:up type:sphere pos:0,0,0 radius:1\n"
        "object in:up type:box pos:0,1,0 size:1,1,1 op:intersect\n");
    PhysicsWorld w(s);
    ASSERT_EQ(w.rigidCount(), 4);
    run(w, 3.0);
    const double slop = PhysicsSettings{}.linearSlop;
    Scene after = s;
    w.writeBack(after);  // the groups' origins: each sphere's centre
    const double heights[] = {1.0, 1.0, 1.0, 0.0};
    for (size_t i = 0; i < 4; ++i) {
        std::printf("%s ball: centre %.4f m up (%.0f)\n", after.groups[i].name.c_str(),
                    after.groups[i].pos.y, heights[i]);
        EXPECT_NEAR(after.groups[i].pos.y, heights[i], slop) << after.groups[i].name;
    }
    Scene pair = sceneFromText(
        "scene version:3\nworld gravity:0 ground:0 restitution:0 friction:0\n"
        "group name:a pos:-1,0,0 mass:1 vel:1,0,0\nobject in:a type:sphere pos:0,0,0 radius:0.5\n"
        "object in:a type:box pos:0,0.5,0 size:0.02,0.02,0.02 op:subtract\n"
        "group name:b pos:1,0,0 mass:1 vel:-1,0,0\nobject in:b type:sphere pos:0,0,0 radius:0.5\n"
        "object in:b type:box pos:0,0.5,0 size:0.02,0.02,0.02 op:subtract\n");
    PhysicsWorld met(pair);
    run(met, 2.0);
    std::printf("notched balls head-on: %.4f m apart, %.3g m/s\n",
                met.rigid(1).pos.x - met.rigid(0).pos.x,
                glm::length(met.rigid(0).vel) + glm::length(met.rigid(1).vel));
    EXPECT_NEAR(met.rigid(1).pos.x - met.rigid(0).pos.x, 1.0, slop);
    EXPECT_LT(glm::length(met.rigid(0).vel) + glm::length(met.rigid(1).vel), 1e-3);
}

// simulate writes a group's origin, turn, velocity and spin (and leaves its members alone): a
// scene saved mid-run and read again goes on as the run that was not stopped, to the float
// precision of the file. An L of two boxes whose centre of mass is off its origin, tumbling
// through the air; and a frustum (its centre of mass below its origin) flying. 1e-5 m, as for
// the other shapes (RigidWorld). Planted: writeBack storing the body's centre as the scene's
// pos (the group's origin 0.19 m off after the reload, the frustum's 0.13 m).
TEST(GroupBodies, ASceneSavedMidRunContinuesAsTheRunDoes) {
    const Scene s = sceneFromText(
        "scene version:3\nworld ground:0\n"
        "group name:ell pos:0,8,0 rot:10,0,0 mass:2 vel:1,2,0 spin:2,-3,5\n"
        "object in:ell type:box pos:0.2,0,0 size:0.2,0.05,0.1\n"
        "object in:ell type:box pos:0.05,0.25,0 size:0.05,0.2,0.1\n"
        "object type:cone pos:2,8,0 radius:0.3 top:0.1 height:0.6 mass:1 "
        "vel:1,2,0 spin:1,2,3\n");
    const std::vector<Object> members(s.objects.begin(), s.objects.begin() + 2);
    PhysicsWorld whole(s);
    ASSERT_EQ(whole.rigidCount(), 2);
    for (int i = 0; i < stepsFor(1.0, whole.settings()); ++i) whole.step();
    Scene halves = s, again;
    simulate(halves, 0.5);
    std::vector<SceneError> errors;
    ASSERT_TRUE(parseScene(formatScene(halves), &again, &errors));
    simulate(again, 0.5);
    const Group& ell = again.groups[0];
    EXPECT_LT(glm::length(dvec3(ell.pos) - whole.rigid(0).pos), 1e-5);
    EXPECT_LT(glm::length(dquat(ell.orientation()) - whole.rigid(0).orient), 1e-5);
    EXPECT_LT(glm::length(dvec3(ell.vel) - whole.rigid(0).vel), 1e-5);
    EXPECT_LT(glm::length(dvec3(again.objects[2].pos) - whole.rigid(1).pos), 1e-5);
    for (size_t k = 0; k < members.size(); ++k)
        EXPECT_EQ(again.objects[k].pos, members[k].pos) << "a member moved in the scene";
}

// A world written back before any step gives the scene as it was read, to the byte: a turned
// box's orient and a turned group's origin come back as written, so saving again and again
// changes nothing (frame 0 of an animation is such a world's). Planted: writing every body from
// its double state (the box's orient walks by an ulp a save, and the chair's z flips between 0
// and ±5.6e-17).
TEST(GroupBodies, AWorldWrittenBackBeforeAnyStepSavesTheSameBytes) {
    const std::string text =
        "scene version:3\nmaterial r:1 g:1 b:1\n"
        "group name:chair pos:0,0.02,0 rot:-24,0,0 mass:4\n"
        "object in:chair type:box pos:0,0.45,0 size:0.22,0.03,0.22\n"
        "object in:chair type:box pos:0,0.8,-0.195 size:0.22,0.32,0.025\n"
        "object type:box pos:1.9027233,0.15466198,0.00026834977 size:0.04,0.3,0.15 "
        "orient:0.8353106,9.123029e-05,-5.9323662e-05,-0.5497784 mass:0.2\n";
    const std::string saved = formatScene(sceneFromText(text));
    std::string again = saved;
    for (int k = 0; k < 3; ++k) {
        Scene s;
        std::vector<SceneError> errors;
        ASSERT_TRUE(parseScene(again, &s, &errors));
        PhysicsWorld(s).writeBack(s);
        again = formatScene(s);
        EXPECT_EQ(again, saved) << "save " << k + 1;
    }
}

// Cups and balls dropped on one another in a heap on the open ground (cupPileScene: 9 cups,
// 400 balls, no walls: nothing but the ground is static), 1.5 s: the same bytes on one thread
// and on two (the spheres' contacts are many enough to split), and a golden hash: a change in
// the groups' or the shapes' arithmetic changes it; update it deliberately, with the reason in
// the commit. Planted: a group's manifolds of four points, not eight (another hash).
TEST(GroupBodies, PileOfCupsAndBallsIsDeterministic) {
    const std::uint64_t golden = 0x2be1c2e34b737528ull;
    const Scene s = cupPileScene(9, 400, 7, 0.25f, false);
    PhysicsSettings one, two;
    two.threads = 2;
    PhysicsWorld a(s, one), b(s, two);
    int split = 0;
    for (int i = 0; i < stepsFor(1.5, one); ++i) {
        a.step();
        b.step();
        split = std::max(split, b.stats().halves);
    }
    ASSERT_EQ(a.rigidCount(), 9);
    EXPECT_GT(split, 0) << "two threads never split the contacts";
    EXPECT_EQ(stateHash(a), stateHash(b)) << "two threads differ from one";
    EXPECT_EQ(stateHash(a), golden) << "actual hash: 0x" << std::hex << stateHash(a) << "ull";
}

// Two one-box groups in empty space, one thrown at the other at 6 m/s: 5 cm a step, more than
// the speculative distance (2 cm). Its points are kept while they approach fast enough to close
// within the step, so it stops at the other's face: no overlap deeper than the slop, the
// momentum kept to rounding, and the two going on together (no bounce: apart at under 1 % of
// the impact's speed).
// Planted: points dropped beyond the speculative distance whatever their approach, or with the
// approach's sign turned (either way it sinks 1.3 cm in).
TEST(GroupBodies, AGroupThrownFastAtAnotherStopsAtItsFace) {
    const Scene s = sceneFromText(
        "scene version:3\nworld gravity:0 ground:0 restitution:0 friction:0\n"
        "group name:a pos:0,0,0 mass:1\nobject in:a type:box pos:0,0,0 size:0.5,0.5,0.5\n"
        "group name:b pos:1.237,0,0 mass:1 vel:-6,0,0\n"
        "object in:b type:box pos:0,0,0 size:0.5,0.5,0.5\n");
    PhysicsWorld w(s);
    ASSERT_EQ(w.rigidCount(), 2);
    double deepest = 0.0;
    for (int i = 0; i < stepsFor(0.5, w.settings()); ++i) {
        w.step();
        deepest = std::max(deepest, w.rigid(0).pos.x + 1.0 - w.rigid(1).pos.x);
    }
    std::printf("deepest overlap %.5f m, speeds %.7f %.7f\n", deepest, w.rigid(0).vel.x,
                w.rigid(1).vel.x);
    EXPECT_LT(deepest, PhysicsSettings{}.linearSlop);
    EXPECT_NEAR(w.rigid(0).vel.x + w.rigid(1).vel.x, -6.0, 1e-9) << "momentum";
    EXPECT_LT(std::abs(w.rigid(0).vel.x - w.rigid(1).vel.x), 0.06) << "bounced";
}

// The report's table upside down and tilted, dropped so that a corner of its top lands first:
// no corner of the top goes below the ground by more than the slop while it tumbles and
// settles. Planted: the probes thinned with the corners among them (the top's upper corners,
// 6 cm from its lower ones, are dropped, and the leading corner sinks 5.7 cm in).
TEST(GroupBodies, ATableLandingOnACornerOfItsTopKeepsItAboveTheGround) {
    std::string text =
        "scene version:3\nworld ground:1 friction:0.6 restitution:0\n"
        "group name:t pos:0,1.6,0 rot:160,10,25 mass:1\n"
        "object in:t type:box pos:0,0.72,0 size:0.5,0.03,0.35\n";
    for (const char* leg :
         {"0.42,0.345,0.27", "-0.42,0.345,0.27", "0.42,0.345,-0.27", "-0.42,0.345,-0.27"})
        text += std::string("object in:t type:cylinder pos:") + leg + " radius:0.03 height:0.69\n";
    PhysicsWorld w(sceneFromText(text));
    ASSERT_EQ(w.rigidCount(), 1);
    double lowest = 1e9;
    for (int i = 0; i < stepsFor(2.0, w.settings()); ++i) {
        w.step();
        const RigidState t = w.rigid(0);
        for (const double x : {-0.5, 0.5})
            for (const double z : {-0.35, 0.35})
                lowest = std::min(lowest, (t.pos + t.orient * dvec3(x, 0.75, z)).y);
    }
    std::printf("lowest corner of the top %.5f m\n", lowest);
    EXPECT_GT(lowest, -PhysicsSettings{}.linearSlop);
}

// A cart, a box chassis on four cylinder wheels (eight whole rims), dropped upside down rests on
// the chassis's top, its origin 0.45 m up. Planted: rims first and no keys kept for points:
// the eight rims took the 120 contact keys, six of them whole, the chassis kept no point, and
// it sank onto its wheels' rims (0.30 m).
TEST(GroupBodies, ACartOfManyWheelsDroppedUpsideDownRestsOnItsChassis) {
    std::string text =
        "scene version:3\nworld ground:1 friction:0.6 restitution:0\n"
        "group name:cart pos:0,1,0 rot:180,0,0 mass:10\n"
        "object in:cart type:box pos:0,0.3,0 size:1,0.15,0.5\n";
    for (const char* wheel : {"-0.7,0.15,-0.6", "0.7,0.15,-0.6", "-0.7,0.15,0.6", "0.7,0.15,0.6"})
        text += std::string("object in:cart type:cylinder pos:") + wheel +
                " rot:90,0,0 radius:0.15 height:0.1\n";
    const GroupProbes probes = groupProbes(groupShapeOf(sceneFromText(text), 0));
    std::printf("cart: %zu probes, %zu rims, %zu sides\n", probes.probes.size(), probes.rims.size(),
                probes.sides.size());
    PhysicsWorld w(sceneFromText(text));
    run(w, 3.0);
    EXPECT_NEAR(w.rigid(0).pos.y, 0.45, 0.01);
}

// A ladder of two box rails and sixty rungs, a cylinder repeated, buried in them at both ends,
// lying on the ground: sixty sides, whose keys left none for points before the points' share
// was kept. It kept no point, and its rails fell through the ground (2.1 m in 1 s); standing,
// with its rungs placed a little otherwise, the spacing that thins the points grew for ever
// and the world was never built. Now it has points, within the keys, and lies on its rails.
TEST(GroupBodies, ALadderOfSixtyRungsIsBuiltWithPoints) {
    const std::string text =
        "scene version:3\nworld ground:1 friction:0.6 restitution:0\n"
        "group name:ladder pos:0,0.03,0 rot:90,0,0 mass:5\n"
        "object in:ladder type:box pos:-0.3,4.5,0 size:0.03,4.6,0.03\n"
        "object in:ladder type:box pos:0.3,4.5,0 size:0.03,4.6,0.03\n"
        "group name:rungs in:ladder pos:0,0.075,0 repeat:1,60,1 spacing:1,0.15,1\n"
        "object in:rungs type:cylinder pos:0,0,0 rot:0,0,90 radius:0.015 height:0.62\n";
    const GroupProbes probes = groupProbes(groupShapeOf(sceneFromText(text), 0));
    EXPECT_GT(probes.probes.size(), 0u);
    EXPECT_LE(int(probes.probes.size()) + kRimIds * int(probes.rims.size()) +
                  kSideIds * int(probes.sides.size()),
              kMaxGroupProbeIds);
    PhysicsWorld w(sceneFromText(text));
    run(w, 1.0);
    EXPECT_NEAR(w.rigid(0).pos.y, 0.03, 0.01);
}

// Two overlapping coaxial cylinders cut level by a wider one: the edge left is where each
// cylinder's side meets the cutter's cap. Each named it, and it was kept twice, two of the
// group's few rims on one circle; in a stack of forty coins, each cap named by twenty coins
// was looked for twenty times over in every copy of the group. One circle, one rim.
TEST(GroupBodies, AnEdgeThatTwoMembersMakeIsOneRim) {
    const Scene s = sceneFromText(
        "scene version:3\nworld ground:1\n"
        "group name:g pos:0,2,0 mass:1\n"
        "object in:g type:cylinder pos:0,0,0 radius:0.3 height:1\n"
        "object in:g type:cylinder pos:0,0.2,0 radius:0.3 height:0.8\n"
        "object in:g type:cylinder pos:0,0.8,0 radius:0.5 height:1 op:subtract\n");
    const GroupProbes probes = groupProbes(groupShapeOf(s, 0));
    int atCut = 0;
    for (const Rim& r : probes.rims)
        if (glm::length(r.centre - glm::dvec3(0.0, 0.3, 0.0)) < 1e-6 &&
            std::abs(r.radius - 0.3) < 1e-6)
            ++atCut;
    EXPECT_EQ(atCut, 1);
}

// The same circle before the images is another edge where a member's mirrors and copies make
// it elsewhere: a cone's base rim in a pair of copies 3 m apart lies, before them, on the cut
// edge of the cylinder between them. That edge is kept.
TEST(GroupBodies, AnEdgeIsKeptBesideTheSameCircleInCopiesElsewhere) {
    const Scene s = sceneFromText(
        "scene version:3\nworld ground:1\n"
        "group name:g pos:0,2,0 mass:1\n"
        "object in:g type:cylinder pos:0,0.5,0 radius:0.3 height:2\n"
        "object in:g type:cylinder pos:0,1.5,0 radius:0.5 height:2 op:subtract\n"
        "group name:s in:g repeat:2,1,1 spacing:3,1,1\n"
        "object in:s type:cone pos:0,1,0 radius:0.3 height:1\n");
    const GroupProbes probes = groupProbes(groupShapeOf(s, 0));
    EXPECT_TRUE(std::any_of(probes.rims.begin(), probes.rims.end(), [](const Rim& r) {
        return glm::length(r.centre - glm::dvec3(0.0, 0.5, 0.0)) < 1e-6 &&
               std::abs(r.radius - 0.3) < 1e-6;
    }));
}

// A group of subtractions alone, 121 spheres carved out of nothing, has no solid and no body.
// Its size counts its unions alone, 0, and the spacing that thins its probes started at 0 and
// never grew: the world was never built. Now it is, without the group, whose probes are not
// looked for, and they are found if asked for.
TEST(GroupBodies, AGroupOfSubtractionsAloneIsNoBodyAndTheWorldIsBuilt) {
    const Scene s = sceneFromText(
        "scene version:3\nworld ground:1\n"
        "group name:g pos:0,2,0 mass:1\n"
        "group name:h in:g op:subtract repeat:11,11,1\n"
        "object in:h type:sphere pos:0,0,0 radius:0.2\n");
    const GroupProbes probes = groupProbes(groupShapeOf(s, 0));
    EXPECT_LE(int(probes.probes.size()), kMaxGroupProbeIds);
    PhysicsWorld w(s);
    EXPECT_EQ(w.rigidCount(), 0);
}
