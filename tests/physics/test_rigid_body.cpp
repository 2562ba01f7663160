// test_rigid_body.cpp — mass properties against closed forms and the shapes the renderer draws,
// and the free rigid body's rotation against its invariants and its known motions.
#include "rigid_body.h"

#include "marchbox/scene/sdf.h"

#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>
#include <glm/geometric.hpp>

using namespace mb;
using glm::dquat;
using glm::dvec3;

namespace {

constexpr double kH = 1.0 / 480.0;  // the default 1/120 s step with 4 substeps
constexpr int kTenSeconds = 4800;   // steps of kH
constexpr double kOneDegree = 3.14159265358979323846 / 180.0;

Object shape(ShapeType type) {
    Object o;
    o.type = type;
    o.mass = 3.0f;
    o.radius = 0.25f;  // every size here is exact in binary
    o.size = glm::vec3(0.1f, 0.2f, 0.4f);
    o.minor = 0.125f;
    o.height = 0.5f;
    return o;
}

// Jittered-grid integration over the shape's bounding cube: one point at a random spot (a fixed
// LCG) in each of n³ cells, inside where the renderer's SDF is negative; I = m · mean(r⊥²) over
// the points inside. A plain midpoint grid is biased by a cell's width where a face lies along
// the grid (0.8 % on the box at n = 160); the jitter leaves an unbiased, small scatter. This ties
// the closed forms to the shape that is drawn (its axes, which radius is which).
dvec3 sampledInertia(const Object& o, int n) {
    const SdfObject sdf = makeSdfObject(o);
    const double cell = 2.0 * double(sdf.bound) / n;
    std::uint32_t state = 12345;
    auto uniform = [&] {
        state = state * 1664525u + 1013904223u;
        return double(state >> 8) / 16777216.0;  // the top 24 bits, in [0, 1)
    };
    dvec3 sum(0.0);
    long inside = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                const dvec3 jitter(uniform(), uniform(), uniform());
                const dvec3 p = (dvec3(i, j, k) + jitter) * cell - double(sdf.bound);
                if (sdObjectLocal(sdf, glm::vec3(p)) >= 0.0f) continue;
                sum += dvec3(p.y * p.y + p.z * p.z, p.x * p.x + p.z * p.z, p.x * p.x + p.y * p.y);
                ++inside;
            }
    return double(o.mass) * sum / double(inside);
}

// A body in flight: its orientation, world angular velocity and principal moments.
struct Tumbler {
    dquat q;
    dvec3 spin;
    dvec3 inertia;

    dvec3 momentum() const { return q * (inertia * (glm::conjugate(q) * spin)); }  // world L
    double energy() const { return 0.5 * glm::dot(spin, momentum()); }
    dvec3 axis(int k) const {
        dvec3 e(0.0);
        e[k] = 1.0;
        return q * e;
    }  // in the world
    void step() { rotateFree(q, spin, inertia, kH); }
};

const dquat kGenericTurn = glm::angleAxis(0.7, glm::normalize(dvec3(1.0, -2.0, 0.5)));

// Spinning at rate w about body axis k, with 1e-3 of w about each of the other two.
Tumbler spunAbout(int k, double w) {
    const dvec3 inertia = massProperties(shape(ShapeType::Box)).inertia;
    dvec3 bodySpin(1e-3 * w);
    bodySpin[k] = w;
    return {kGenericTurn, kGenericTurn * bodySpin, inertia};
}

// The most the body axis k strays from the momentum's direction over 10 s, in radians.
double widestWander(Tumbler t, int k) {
    const dvec3 l = glm::normalize(t.momentum());
    double widest = 0.0;
    for (int n = 0; n < kTenSeconds; ++n) {
        t.step();
        widest = std::max(widest, std::acos(std::min(1.0, std::abs(glm::dot(t.axis(k), l)))));
    }
    return widest;
}

}  // namespace

// Box (0.1, 0.2, 0.4), m = 3: Ix = (0.04 + 0.16), Iy = (0.01 + 0.16), Iz = (0.01 + 0.04), m/3 = 1.
// Sphere r = 0.25: 2/5 · 3 · 0.0625 = 0.075. Cylinder r = 0.25, h = 0.5: Iy = 3 · 0.0625 / 2,
// Ix = 3 · (0.1875 + 0.25) / 12. Torus R = 0.25, a = 0.125: Iy = 3 · (0.0625 + 0.01171875),
// Ix = 3 · (0.03125 + 0.009765625). The box's float extents are exact to 1e-8.
TEST(RigidBodyMass, EachShapeMatchesItsClosedForm) {
    auto expectInertia = [](ShapeType type, dvec3 expected) {
        const MassProperties mp = massProperties(shape(type));
        EXPECT_EQ(mp.mass, 3.0) << shapeTypeName(type);
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(mp.inertia[k], expected[k], 1e-8) << shapeTypeName(type) << " axis " << k;
    };
    expectInertia(ShapeType::Sphere, dvec3(0.075));
    expectInertia(ShapeType::Box, dvec3(0.2, 0.17, 0.05));
    expectInertia(ShapeType::Cylinder, dvec3(0.109375, 0.09375, 0.109375));
    expectInertia(ShapeType::Torus, dvec3(0.123046875, 0.22265625, 0.123046875));
}

// A capsule with no segment is a sphere; with a long one, nearly a rod of length h + 2r whose
// caps hold little of the mass: Ix → m (h + 2r)² / 12 within O(r/h).
TEST(RigidBodyMass, CapsuleLimitsAreTheSphereAndTheRod) {
    Object o = shape(ShapeType::Capsule);
    o.height = 0.0f;
    const MassProperties ball = massProperties(o);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(ball.inertia[k], 0.075, 1e-12);
    o.radius = 0.001f;
    o.height = 10.0f;
    const double rod = 3.0 * (10.0 + 0.002) * (10.0 + 0.002) / 12.0;
    EXPECT_NEAR(massProperties(o).inertia.x / rod, 1.0, 1e-3);
}

// At n = 160 the sampled moments came within 2.7e-4 of the closed forms on every shape and axis;
// the bound, 1e-3, is far under the smallest planted formula error (a capsule without its caps'
// −9r²/64 is 4.6 % off here).
TEST(RigidBodyMass, EachShapeMatchesASampledIntegralOfItsSdf) {
    for (ShapeType type : {ShapeType::Sphere, ShapeType::Box, ShapeType::Torus, ShapeType::Capsule,
                           ShapeType::Cylinder}) {
        const Object o = shape(type);
        const dvec3 closed = massProperties(o).inertia, sampled = sampledInertia(o, 160);
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(closed[k] / sampled[k], 1.0, 1e-3) << shapeTypeName(type) << " axis " << k;
    }
}

// Version 3's shapes: cones (pointed and cut), an ellipsoid, every shape hollowed, the edged
// ones rounded. Their moments about the shape's own origin, I + m·(|c|² − c_k²) from the
// centre c, against the same sampled integral of the SDF that is drawn; and a cone's centre of
// mass in closed form: a frustum's lies h·(R² + 2Rr + 3r²) / (4·(R² + Rr + r²)) above its base,
// a pointed cone's h/4. Closed forms and integrals alike within 1.5e-3 of the samples (the
// worst measured: 1.1e-3, the ellipsoid's thin shell, integrated where the others have closed
// forms; the closed forms within 5e-4, the samples' own scatter). Planted: the frustum's
// Gauss–Legendre nodes at ±√(1/3) (the cone 41 % off); a hollow cylinder's inner cylinder only
// t shorter, not 2t (8 % off).
TEST(RigidBodyMass, VersionThreeShapesMatchASampledIntegralOfTheirSdf) {
    std::vector<Object> shapes;
    Object o = shape(ShapeType::Cone);
    shapes.push_back(o);
    o.top = 0.125f;
    shapes.push_back(o);
    shapes.push_back(shape(ShapeType::Ellipsoid));
    for (ShapeType type : {ShapeType::Sphere, ShapeType::Box, ShapeType::Torus, ShapeType::Capsule,
                           ShapeType::Cylinder, ShapeType::Cone, ShapeType::Ellipsoid}) {
        o = shape(type);
        o.shell = type == ShapeType::Torus ? 0.03125f : 0.0625f;
        if (type == ShapeType::Box) o.shell = 0.03125f;
        shapes.push_back(o);
    }
    for (ShapeType type : {ShapeType::Box, ShapeType::Cylinder, ShapeType::Cone}) {
        o = shape(type);
        o.round = 0.03125f;
        shapes.push_back(o);
    }
    for (const Object& body : shapes) {
        const MassProperties mp = massProperties(body);
        EXPECT_EQ(mp.axes, dquat(1.0, 0.0, 0.0, 0.0));
        dvec3 aboutOrigin = mp.inertia;
        for (int k = 0; k < 3; ++k)
            aboutOrigin[k] +=
                mp.mass * (glm::dot(mp.centre, mp.centre) - mp.centre[k] * mp.centre[k]);
        const dvec3 sampled = sampledInertia(body, 160);
        const std::string name =
            std::string(shapeTypeName(body.type)) + (body.shell > 0.0f ? " shell" : "") +
            (body.round > 0.0f ? " round" : "") + (body.top > 0.0f ? " cut" : "");
        for (int k = 0; k < 3; ++k) {
            std::printf("%-16s axis %d: %.6f sampled %.6f (%+.2g)\n", name.c_str(), k,
                        aboutOrigin[k], sampled[k], aboutOrigin[k] / sampled[k] - 1.0);
            EXPECT_NEAR(aboutOrigin[k] / sampled[k], 1.0, 1.5e-3) << name << " axis " << k;
        }
    }
    const double h = 0.5, big = 0.25, small = 0.125;
    EXPECT_NEAR(massProperties(shapes[0]).centre.y, -h / 2 + h / 4, 1e-12);
    EXPECT_NEAR(massProperties(shapes[1]).centre.y,
                -h / 2 + h * (big * big + 2 * big * small + 3 * small * small) /
                             (4 * (big * big + big * small + small * small)),
                1e-12);
}

// The worst relative drift of the energy and of the world angular momentum over 10 s.
struct Drift {
    double energy = 0.0, momentum = 0.0;
};

Drift driftOver10s(Tumbler t) {
    const dvec3 l0 = t.momentum();
    const double e0 = t.energy();
    Drift d;
    for (int n = 0; n < kTenSeconds; ++n) {
        t.step();
        d.energy = std::max(d.energy, std::abs(t.energy() / e0 - 1.0));
        d.momentum = std::max(d.momentum, glm::length(t.momentum() - l0) / glm::length(l0));
    }
    EXPECT_NEAR(glm::length(t.q), 1.0, 1e-15);
    return d;
}

// The splitting keeps world L to rounding (7e-13 measured, the ω ↔ L conversions) and T to its
// fourth-order error (1.5e-10 measured; Strang alone leaves 5.6e-6).
TEST(RigidBodyRotation, FreeTumblingKeepsEnergyAndMomentum) {
    const Drift d = driftOver10s(
        {kGenericTurn, dvec3(3.0, 5.0, 7.0), massProperties(shape(ShapeType::Box)).inertia});
    EXPECT_LT(d.energy, 1e-6);
    EXPECT_LT(d.momentum, 1e-6);
}

// The box's largest moment is about x, its smallest about z: both axes are stable, so a 1e-3
// perturbation nutates the axis about L by a few 1e-3 rad at most.
TEST(RigidBodyRotation, SpinAboutTheLargestOrSmallestAxisIsStable) {
    EXPECT_LT(widestWander(spunAbout(0, 8.0), 0), kOneDegree);
    EXPECT_LT(widestWander(spunAbout(2, 8.0), 2), kOneDegree);
}

// About the intermediate axis (y) the perturbation grows as exp(λt), λ = w·sqrt((Ix − Iy)(Iy −
// Iz) / (Ix·Iz)) = 0.6·w: at w = 8 from 1e-3 to O(1) in about 1.4 s, then the axis flips.
TEST(RigidBodyRotation, SpinAboutTheIntermediateAxisFlips) {
    Tumbler t = spunAbout(1, 8.0);
    const dvec3 l = glm::normalize(t.momentum());
    double lowest = 1.0;
    for (int n = 0; n < kTenSeconds; ++n) {
        t.step();
        lowest = std::min(lowest, glm::dot(t.axis(1), l));
    }
    EXPECT_LT(lowest, -0.9);
}

// A symmetric body (Ix = Iz = I⊥) has ω = L/I⊥ + (1/I∥ − 1/I⊥)·L∥·a for its axis a, so
// da/dt = ω × a = (L/I⊥) × a: the axis turns about L at Ω = |L|/I⊥.
TEST(RigidBodyRotation, ACylinderPrecessesAtMomentumOverITransverse) {
    const dvec3 inertia = massProperties(shape(ShapeType::Cylinder)).inertia;
    Tumbler t{kGenericTurn, dvec3(2.0, 6.0, -3.0), inertia};
    const dvec3 l = t.momentum(), a0 = t.axis(1);
    const double rate = glm::length(l) / inertia.x;
    double worst = 0.0;
    for (int n = 1; n <= kTenSeconds; ++n) {
        t.step();
        const dvec3 expected = glm::angleAxis(rate * n * kH, glm::normalize(l)) * a0;
        worst = std::max(worst, glm::length(t.axis(1) - expected));
    }
    EXPECT_LT(worst, 1e-9);  // the symmetric top's flow is exact: rounding alone (measured WORST)
}

// Two equal moments take the exact flow: energy and momentum to rounding, for the capsule (two
// moments equal) and the cube (three), where the splitting leaves 1e-10.
TEST(RigidBodyRotation, ASymmetricTopKeepsItsEnergyToRounding) {
    Object cube = shape(ShapeType::Box);
    cube.size = glm::vec3(0.3f);
    for (const Object& o : {shape(ShapeType::Capsule), cube}) {
        const Drift d =
            driftOver10s({kGenericTurn, dvec3(3.0, 5.0, 7.0), massProperties(o).inertia});
        EXPECT_LT(d.energy, 1e-11) << int(o.type);  // 4800 steps of rounding
        EXPECT_LT(d.momentum, 1e-11) << int(o.type);
    }
}

// The exact flow turns the capsule as the splitting does: a moment changed by 1e-12 (relative)
// takes the splitting's path, whose error over 10 s is about 1e-10, so the two orientations
// agree far inside 1e-7 (the spin about the capsule's own axis included, which neither energy
// nor momentum sees).
TEST(RigidBodyRotation, ASymmetricTopTurnsAsTheSplittingDoes) {
    const dvec3 inertia = massProperties(shape(ShapeType::Capsule)).inertia;
    Tumbler exact{kGenericTurn, dvec3(3.0, 5.0, 7.0), inertia};
    Tumbler split{kGenericTurn, dvec3(3.0, 5.0, 7.0), inertia * dvec3(1.0, 1.0, 1.0 + 1e-12)};
    for (int n = 0; n < kTenSeconds; ++n) {
        exact.step();
        split.step();
    }
    const double apart = std::min(glm::length(exact.q - split.q), glm::length(exact.q + split.q));
    EXPECT_LT(apart, 1e-7);
}

// untwist: a body turned 1 rad about its own y axis and then 0.3 rad about the world's x keeps
// q's y axis, and lies from where it began only as far as that axis turned (0.25 rad, the swing
// alone); the twist alone leaves it where it began. Planted: q returned whole, 0.86 rad away.
TEST(RigidBodyRotation, UntwistKeepsTheAxisAndDropsTheTurnAboutIt) {
    const dquat from = glm::normalize(dquat(0.9, 0.2, -0.3, 0.25));
    const dvec3 axis = from * dvec3(0.0, 1.0, 0.0);
    const dquat twisted = glm::angleAxis(1.0, axis) * from;
    const dquat q = glm::angleAxis(0.3, dvec3(1.0, 0.0, 0.0)) * twisted;
    const dquat u = untwist(q, from);
    EXPECT_LT(glm::length(u * dvec3(0, 1, 0) - q * dvec3(0, 1, 0)), 1e-12);
    const double turned = 2.0 * std::acos(std::min(1.0, std::abs(glm::dot(u, from))));
    const double swing = std::acos(glm::dot(axis, q * dvec3(0, 1, 0)));
    EXPECT_NEAR(turned, swing, 1e-9) << "untwist turned more than its axis did";
    const dquat still = untwist(twisted, from);
    EXPECT_NEAR(std::abs(glm::dot(still, from)), 1.0, 1e-12);
}
