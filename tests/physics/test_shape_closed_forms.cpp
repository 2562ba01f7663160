// test_shape_closed_forms.cpp — version 3's shapes (a pointed cone, a hollow ball, an ellipsoid,
// a rounded box) as bodies in a PhysicsWorld, against closed forms of their motion and rest: the
// mass properties the engine uses reach each check only through what the bodies do.
#include "marchbox/physics/physics.h"
#include "marchbox/scene/scene_io.h"
#include "physics_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

using namespace mb;
using glm::dmat3;
using glm::dvec3;

namespace {

constexpr double kG = 9.81;
constexpr double kDegree = M_PI / 180.0;

std::string num(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

std::string vec(dvec3 v) { return num(v.x) + "," + num(v.y) + "," + num(v.z); }

// A static plank (half extents 20, 0.5, 2) about the origin, turned by `degrees` about z: its top
// face rises along +x, with its normal `up` and its direction up the slope `along`. No ground.
struct Slope {
    double theta;
    dvec3 along, up;
    explicit Slope(double degrees)
        : theta(degrees * kDegree),
          along(std::cos(theta), std::sin(theta), 0.0),
          up(-std::sin(theta), std::cos(theta), 0.0) {}
    std::string text(double friction) const {
        return "scene version:3\nworld gravity:9.81 restitution:0 rolling:0 ground:0 friction:" +
               num(friction) + "\nobject type:box pos:0,0,0 size:20,0.5,2 rot:0,0," +
               num(theta / kDegree) + " static:1\n";
    }
    dvec3 onTop(double alongSlope, double above) const {  // a point `above` its top face
        return alongSlope * along + (0.5 + above) * up;
    }
};

// s(t) = c0 + c1·t + c2·t² by least squares (normal equations, Gauss–Jordan): a = 2·c2.
struct QuadraticFit {
    double m[3][4] = {};
    void add(double t, double s) {
        const double basis[3] = {1.0, t, t * t};
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c) m[r][c] += basis[r] * basis[c];
            m[r][3] += basis[r] * s;
        }
    }
    double acceleration() {
        for (int p = 0; p < 3; ++p)
            for (int r = 0; r < 3; ++r) {
                if (r == p) continue;
                const double f = m[r][p] / m[p][p];
                for (int c = 0; c < 4; ++c) m[r][c] -= f * m[p][c];
            }
        return 2.0 * m[2][3] / m[2][2];
    }
};

}  // namespace

// A pointed cone (base radius 0.3, height 0.8, no top) set on its base on the ground rests
// with its origin, the middle of its axis, h/2 up: within the contacts' slop (linearSlop, the
// overlap the solver leaves), after 3 s. Its centre of mass, as the engine has it
// (RigidState::centre), lies on its axis h/4 above the base, to rounding (1e-9 m), and so
// h/4 above the ground within the slop: not at the origin. Planted: the cone's centre of mass
// h/3 above its base (mass_moments.cpp's cone() with its first moment moved up by V·h/12): the
// origin still rests at h/2 (0.39952, the contacts are the shape's), but the centre is found
// 0.26667 m above the base, not 0.2, and 0.2662 above the ground. Measured: origin 0.39947,
// centre 0.2 above the base to 3e-9 (the float height's own rounding, the same on both sides).
TEST(ShapeClosedForms, PointedConeRestsOnItsBaseWithItsCentreAQuarterUp) {
    const double r = 0.3, h = 0.8;
    Scene s = sceneFromText(
        "scene version:3\nworld restitution:0.2 friction:0.6\n"
        "object type:cone pos:0," +
        num(h / 2 + 0.002) + ",0 radius:" + num(r) + " height:" + num(h) + " mass:1.5\n");
    PhysicsWorld w(s);
    ASSERT_EQ(w.rigidCount(), 1);
    const double height = double(s.objects[0].height);  // the float the engine was given
    for (int i = 0; i < stepsFor(3.0, w.settings()); ++i) w.step();
    const RigidState c = w.rigid(0);
    const dvec3 axis = c.orient * dvec3(0, 1, 0), base = c.pos - 0.5 * height * axis;
    const double aboveBase = glm::dot(c.centre - base, axis);
    const double offAxis = glm::length(c.centre - base - aboveBase * axis);
    std::printf(
        "pointed cone: origin %.6f (h/2 %.6f), centre %.9f above its base (h/4 %.9f), "
        "%.3g off its axis, centre %.6f up\n",
        c.pos.y, height / 2, aboveBase, height / 4, offAxis, c.centre.y);
    const double slop = PhysicsSettings{}.linearSlop;
    EXPECT_NEAR(c.pos.y, height / 2, slop);
    EXPECT_GT(axis.y, 0.9999) << "not standing on its base";
    EXPECT_NEAR(aboveBase, height / 4, 1e-9) << "the centre of mass is not h/4 above the base";
    EXPECT_LT(offAxis, 1e-9);
    EXPECT_NEAR(c.centre.y, height / 4, slop);
}

// A pointed cone standing on a rough slope of angle θ tips over its downhill rim point once
// gravity's line through the centre of mass (h/4 above the base, on the axis) leaves the base:
// tan θc = r/(h/4) = 4r/h. r = 0.15, h = 0.9: θc = atan(2/3) = 33.69°. Friction 1.5, above
// tan θ at every angle here (0.71 at 35.2°), so it cannot slide first. Set on the slope at rest
// it stands 3 s at θc − 1° (its axis within 1° of the slope's normal, its base within 1 cm of
// where it was put) and at θc + 1° goes over (the axis more than 45° off the normal within
// 3 s). Measured: 0.16° of tilt and 1.2 mm of creep at θc − 1°, 99.5° at θc + 1° (it ends on
// its side); the change comes between θc − 0.5° (stands, 0.18°) and θc − 0.25° (tips), the
// soft contacts' compression on the downhill side. The slope turns about z, so the base's flat
// rim stands on four points one of which points straight downhill (rimSupport); on a slope
// falling between x and z none does, and the cone tips about 2° early. Planted: the centre of mass
// at h/3 above the base (as in the test above; θc becomes 26.6°): at θc − 1° the cone tips (99.5°,
// its base 0.94 m away).
TEST(ShapeClosedForms, PointedConeTipsOnASlopeWhereTanThetaIsFourROverH) {
    const double r = 0.15, h = 0.9;
    const double critical = std::atan(4.0 * r / h) / kDegree;
    struct Outcome {
        double tilt, slid;  // degrees at most, off the slope's normal; m moved along the slope
    };
    auto standOn = [&](double degrees) {
        const Slope slope(degrees);
        const dvec3 start = slope.onTop(0.0, 0.5 * h + 0.001);
        Scene s = sceneFromText(slope.text(1.5) + "object type:cone pos:" + vec(start) +
                                " radius:" + num(r) + " height:" + num(h) + " rot:0,0," +
                                num(degrees) + " mass:1\n");
        PhysicsWorld w(s);
        EXPECT_EQ(w.rigidCount(), 1);
        Outcome o{0.0, 0.0};
        const double height = double(s.objects[1].height);
        const dvec3 base0 = start - 0.5 * height * slope.up;
        for (int i = 0; i < stepsFor(3.0, w.settings()); ++i) {
            w.step();
            const RigidState c = w.rigid(0);
            const dvec3 axis = c.orient * dvec3(0, 1, 0);
            o.tilt = std::max(o.tilt, std::acos(std::min(1.0, glm::dot(axis, slope.up))) / kDegree);
            o.slid = std::max(o.slid, glm::length(c.pos - 0.5 * height * axis - base0));
        }
        return o;
    };
    const Outcome below = standOn(critical - 1.0), above = standOn(critical + 1.0);
    std::printf(
        "cone on a slope: θc %.3f°; at %.3f° tilted %.4f°, base moved %.2g m; at %.3f° "
        "tilted %.2f°\n",
        critical, critical - 1.0, below.tilt, below.slid, critical + 1.0, above.tilt);
    EXPECT_LT(below.tilt, 1.0) << "tipped below the critical angle";
    EXPECT_LT(below.slid, 0.01) << "slid or crept below the critical angle";
    EXPECT_GT(above.tilt, 45.0) << "stood above the critical angle";
}

// A hollow ball (outer radius r0 = 0.2, shell t = 0.02, so inner r1 = 0.18) rolls without
// slipping down a 10° slope (friction 0.8, no rolling resistance): a = g·sin θ / (1 + k) with
// k = I/(m·r0²) = ⅖·(r0⁵ − r1⁵) / ((r0³ − r1³)·r0²) = 0.6044; a solid ball's k = ⅖ rolls 8.5 %
// faster (a = g·sin θ / 1.4), far outside the bound. The distance along the slope, fitted by
// least squares to s0 + v0·t + a·t²/2 over 1 s, gives a within 1 % (the tube's bound, same
// fit); and it rolls, |ω|·r0 = |v| within 1 %. Planted: the shell's inertia as a solid ball's
// (closedFormMoments not subtracting a sphere's inside): a = 1.2156 against 1.0617, +14.5 %.
// Measured: a = 1.06037, −0.13 %; |ω|·r0 = 1.06204 against |v| = 1.06054.
TEST(ShapeClosedForms, HollowBallRollsDownASlopeAtItsClosedFormAcceleration) {
    const double r0 = 0.2, t = 0.02, degrees = 10.0;
    const Slope slope(degrees);
    Scene s =
        sceneFromText(slope.text(0.8) + "object type:sphere pos:" + vec(slope.onTop(3.0, r0)) +
                      " radius:" + num(r0) + " shell:" + num(t) + " mass:1\n");
    PhysicsWorld w(s);
    ASSERT_EQ(w.rigidCount(), 1) << "a hollow ball is a rigid body, not a solid sphere";
    const double outer = double(s.objects[1].radius), inner = outer - double(s.objects[1].shell);
    const double k = 0.4 * (std::pow(outer, 5) - std::pow(inner, 5)) /
                     ((std::pow(outer, 3) - std::pow(inner, 3)) * outer * outer);
    const double a = kG * std::sin(slope.theta) / (1.0 + k);
    const double solid = kG * std::sin(slope.theta) / 1.4;
    const dvec3 start = w.rigid(0).centre;
    QuadraticFit fit;
    for (int i = 1; i <= stepsFor(1.0, w.settings()); ++i) {
        w.step();
        fit.add(i * w.settings().dt, -glm::dot(w.rigid(0).centre - start, slope.along));
    }
    const double fitted = fit.acceleration();
    const RigidState b = w.rigid(0);
    std::printf(
        "hollow ball: k %.5f, a = %.5f m/s², closed form %.5f (%+.3f %%), solid ball "
        "%.5f; |ω|·r0 %.5f, |v| %.5f\n",
        k, fitted, a, 100.0 * (fitted / a - 1.0), solid, glm::length(b.spin) * outer,
        glm::length(b.vel));
    ASSERT_GT(std::abs(solid / a - 1.0), 0.05) << "the two balls should differ beyond the bound";
    EXPECT_NEAR(fitted, a, 0.01 * a);
    EXPECT_NEAR(glm::length(b.spin) * outer, glm::length(b.vel), 0.01 * glm::length(b.vel))
        << "slipping";
}

// A free ellipsoid (semi-axes 0.5, 0.3, 0.2, m = 2; no gravity, no ground) spun about a generic
// axis: with the closed-form principal moments I_x = m/5·(b² + c²), I_y = m/5·(a² + c²),
// I_z = m/5·(a² + b²) in its own frame, the world angular momentum L = R·I·Rᵀ·ω and the
// energy E = ½·ωᵀ·L, computed here from the body's turn R and spin ω, keep to 1e-6 (relative)
// over 5 s. That holds only if the engine's inertia is this one (another inertia turns the body
// another way, and L and E computed with this one drift) and it conserves both: its splitting
// keeps L to rounding and E to 1.5e-10 on a box over 10 s (RigidBodyRotation). Planted: the
// ellipsoid's ∫x² and ∫y² swapped in mass_moments.cpp (I_x and I_y exchanged): L drifts by 0.58
// of itself and E by 0.35. Measured: 1.8e-13 and 1.3e-11.
TEST(ShapeClosedForms, FreeEllipsoidKeepsItsClosedFormMomentumAndEnergy) {
    Scene s = sceneFromText(
        "scene version:3\nworld gravity:0 ground:0\n"
        "object type:ellipsoid pos:0,2,0 size:0.5,0.3,0.2 rot:10,20,30 mass:2 "
        "spin:1.5,-2,3\n");
    PhysicsWorld w(s);
    ASSERT_EQ(w.rigidCount(), 1);
    const dvec3 e = dvec3(s.objects[0].size), e2 = e * e;
    const double m = double(s.objects[0].mass);
    const dmat3 inertia(m / 5 * (e2.y + e2.z), 0, 0, 0, m / 5 * (e2.x + e2.z), 0, 0, 0,
                        m / 5 * (e2.x + e2.y));
    auto momentum = [&](const RigidState& b) {
        const dmat3 turn = glm::mat3_cast(b.orient);
        return turn * inertia * glm::transpose(turn) * b.spin;
    };
    auto energy = [&](const RigidState& b) { return 0.5 * glm::dot(b.spin, momentum(b)); };
    const RigidState first = w.rigid(0);
    const dvec3 l0 = momentum(first);
    const double e0 = energy(first);
    double dl = 0.0, de = 0.0;
    for (int i = 0; i < stepsFor(5.0, w.settings()); ++i) {
        w.step();
        const RigidState b = w.rigid(0);
        dl = std::max(dl, glm::length(momentum(b) - l0) / glm::length(l0));
        de = std::max(de, std::abs(energy(b) / e0 - 1.0));
    }
    std::printf("free ellipsoid: |ΔL|/|L| %.3g, |ΔE|/E %.3g over 5 s (L %.5f, E %.5f)\n", dl, de,
                glm::length(l0), e0);
    EXPECT_LT(dl, 1e-6);
    EXPECT_LT(de, 1e-6);
}

// A rounded box (half extents 0.3, 0.2, 0.25, edges rounded 0.05) dropped flat from 5 cm rests
// on its face: its centre 0.2 (the half height: rounding keeps the faces in place) above the
// ground within the contacts' slop, its up axis within 1e-3 of vertical, and no rocking after
// 3 s: its spin under 1e-3 rad/s and its speed under 1e-3 m/s. Planted: the rounded box's
// probes (its inset corners) without their spheres of radius `round` (rigid_probes.cpp): it
// sinks to 0.1495, the inset box's half height. Measured: 0.19947 (0.5 mm in), 4.8e-5 off
// vertical, asleep.
TEST(ShapeClosedForms, RoundedBoxRestsFlatOnAFace) {
    Scene s = sceneFromText(
        "scene version:3\nworld restitution:0.2 friction:0.6\n"
        "object type:box pos:0,0.25,0 size:0.3,0.2,0.25 round:0.05 mass:1\n");
    PhysicsWorld w(s);
    ASSERT_EQ(w.rigidCount(), 1);
    const double half = double(s.objects[0].size.y);
    for (int i = 0; i < stepsFor(3.0, w.settings()); ++i) w.step();
    const RigidState b = w.rigid(0);
    const dvec3 up = b.orient * dvec3(0, 1, 0);
    std::printf(
        "rounded box: centre %.6f (%.6f), up off vertical %.3g, spin %.3g rad/s, speed "
        "%.3g m/s, awake %d\n",
        b.centre.y, half, glm::length(up - dvec3(0, 1, 0)), glm::length(b.spin), glm::length(b.vel),
        int(b.awake));
    EXPECT_NEAR(b.centre.y, half, PhysicsSettings{}.linearSlop);
    EXPECT_LT(glm::length(up - dvec3(0, 1, 0)), 1e-3) << "not flat on a face";
    EXPECT_LT(glm::length(b.spin), 1e-3) << "rocking";
    EXPECT_LT(glm::length(b.vel), 1e-3);
}
