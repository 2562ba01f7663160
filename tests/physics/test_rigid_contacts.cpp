// test_rigid_contacts.cpp — bodies of every shape against the ground, slopes and each other,
// against closed forms.
#include "marchbox/physics/physics.h"
#include "marchbox/report/physics_scenes.h"
#include "physics_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace mb;
using glm::dquat;
using glm::dvec3;

namespace {

void run(PhysicsWorld& w, double seconds) {
    for (int i = 0; i < stepsFor(seconds, w.settings()); ++i) w.step();
}

Object dynamicShape(ShapeType type, glm::vec3 pos, float mass) {
    Object o;
    o.type = type;
    o.pos = pos;
    o.mass = mass;
    return o;
}

double slid(PhysicsWorld& w, double seconds, float degrees) {
    const double t = double(degrees) * M_PI / 180.0;
    const dvec3 along(std::cos(t), std::sin(t), 0.0);
    const dvec3 start = w.rigid(0).pos;
    run(w, seconds);
    return glm::dot(w.rigid(0).pos - start, along);
}

}  // namespace

// μ > tan θ: static friction holds the box (Coulomb's cone), to within 1 mm over 5 s.
TEST(RigidContacts, BoxHoldsOnASlopeSteeperFrictionThanItsTangent) {
    PhysicsWorld w(slopeScene(20.0f, 0.5f, dynamicBox({}, {0.2f, 0.1f, 0.15f})));
    EXPECT_LT(std::abs(slid(w, 5.0, 20.0f)), 1e-3);
}

// μ < tan θ: the box slides with a = g·(sin θ − μ·cos θ); from rest, s = ½·a·t², within 1 %.
TEST(RigidContacts, BoxSlidesDownASlopeAtTheCoulombAcceleration) {
    const float degrees = 30.0f, mu = 0.3f;
    PhysicsWorld w(slopeScene(degrees, mu, dynamicBox({}, {0.2f, 0.1f, 0.15f})));
    const double t = 1.0, theta = double(degrees) * M_PI / 180.0;
    const double a = 9.81 * (std::sin(theta) - double(mu) * std::cos(theta));
    const double s = slid(w, t, degrees);
    EXPECT_NEAR(-s, 0.5 * a * t * t, 0.01 * 0.5 * a * t * t)
        << "a = " << -2.0 * s / (t * t) << ", not " << a;
}

// A box w wide and h tall on a slope that holds it (μ = 1.5) tips once its weight passes the
// downhill edge: tan θ > w/h. Here w/h = 1/2, θc = 26.57°: 1° below it the box stands (its axis
// within 1° of the slope's normal after 3 s), 1° above it the box has fallen over (more than
// 45°); the threshold is found within 1°.
double tiltAfter3s(float degrees) {
    PhysicsWorld w(slopeScene(degrees, 1.5f, dynamicBox({}, {0.1f, 0.2f, 0.15f})));
    run(w, 3.0);
    const double t = double(degrees) * M_PI / 180.0;
    const dvec3 normal(-std::sin(t), std::cos(t), 0.0);
    const dvec3 axis = w.rigid(0).orient * dvec3(0, 1, 0);
    return std::acos(std::clamp(std::abs(glm::dot(axis, normal)), 0.0, 1.0)) * 180.0 / M_PI;
}

TEST(RigidContacts, TallBoxTipsWhereItsWeightPassesTheEdge) {
    const float critical = float(std::atan(0.5) * 180.0 / M_PI);
    EXPECT_LT(tiltAfter3s(critical - 1.0f), 1.0) << "tipped below tan θ = w/h";
    EXPECT_GT(tiltAfter3s(critical + 1.0f), 45.0) << "stood above tan θ = w/h";
}

// A solid cylinder rolling without slipping: a = ⅔·g·sin θ (I = ½·m·r²); a capsule rolls with
// a = g·sin θ / (1 + I/(m·r²)), its I about the axis from the closed form. Within 1 %.
class RigidRolling : public ::testing::TestWithParam<ShapeType> {};

// I / (m·r²) about the axis of a solid cylinder or a capsule, r = 0.2 and h = 0.6.
double inertiaRatio(ShapeType type) {
    if (type != ShapeType::Capsule) return 0.5;
    const double r = 0.2, h = 0.6;
    const double vc = M_PI * r * r * h, vs = 4.0 / 3.0 * M_PI * r * r * r;
    return (vc / (vc + vs)) * 0.5 + (vs / (vc + vs)) * 0.4;
}

TEST_P(RigidRolling, RollsDownASlopeAtItsClosedFormAcceleration) {
    const float degrees = 10.0f;
    Object body = dynamicShape(GetParam(), {}, 1.0f);
    body.radius = 0.2f;
    body.height = 0.6f;
    body.rot = {90.0f, 0.0f, 0.0f};  // its axis along z, across the slope
    PhysicsWorld w(slopeScene(degrees, 0.8f, body));
    const double theta = double(degrees) * M_PI / 180.0;
    const double a = 9.81 * std::sin(theta) / (1.0 + inertiaRatio(GetParam())), t = 1.0;
    const double s = slid(w, t, degrees);
    EXPECT_NEAR(-s, 0.5 * a * t * t, 0.01 * 0.5 * a * t * t)
        << "a = " << -2.0 * s / (t * t) << ", not " << a;
}

// Rolling on level ground against rolling resistance c: the torque c·r·N against the roll,
// with the friction that keeps it rolling, slows it at a = c·g / (1 + I/(m·r²)), the same all
// the way to its stop (⅔·c·g for the solid cylinder). c = 0.05, μ = 0.8, from 2 m/s, within 1 %
// over 1 s (measured 0.22 % and 0.16 %). Planted: the rolling rows' masses left at 0: it rolls on
// unslowed; the torque's arm taken as the distance to the manifold's centre, which a lying
// capsule's four points of five put off its middle: it slows 1.2 % fast.
TEST_P(RigidRolling, RollingResistanceSlowsItAtItsClosedFormRate) {
    Scene s = physicsWorld(9.81f, 0.0f, 0.8f, true);
    s.world.rolling = 0.05f;
    Object body = dynamicShape(GetParam(), {0.0f, 0.2f, 0.0f}, 1.0f);
    body.radius = 0.2f;
    body.height = 0.6f;
    body.rot = {90.0f, 0.0f, 0.0f};  // its axis along z: it rolls along x
    body.vel = {2.0f, 0.0f, 0.0f};
    body.spin = {0.0f, 0.0f, -10.0f};  // v / r
    s.objects.push_back(body);
    PhysicsWorld w(s);
    run(w, 1.0);
    const double a = double(0.05f) * 9.81 / (1.0 + inertiaRatio(GetParam()));
    const double slowed = 2.0 - w.rigid(0).vel.x;
    std::printf("rolling resistance: slowed at %.5g m/s² (closed form %.5g)\n", slowed, a);
    EXPECT_NEAR(slowed, a, 0.01 * a);
}

// A ball spun on the spot about the vertical, on the ground and on a box: rolling resistance c
// holds the spin too, its torque c·r·N against it, so it slows at α = c·r·m·g / (⅖·m·r²) =
// 2.5·c·g / r on both, the box a thousand times the ball's mass. c = 0.05, r = 0.2: α = 6.13
// rad/s², from 5 rad/s to 1.93 in 0.5 s, within 1 %. Planted: a manifold's twist held by the
// friction across its points alone, r·μ = 0 for the ball's one point: on the box it kept its
// 5 rad/s for ever, where on the ground it stopped.
TEST(RigidContacts, ABallSpunOnTheSpotSlowsOnABoxAsOnTheGround) {
    Scene s = physicsWorld(9.81f, 0.0f, 0.8f, true);
    s.world.rolling = 0.05f;
    s.objects.push_back(dynamicBox({3.0f, 0.2f, 0.0f}, {1.0f, 0.2f, 1.0f}, 1000.0f));
    for (const float x : {0.0f, 3.0f}) {
        Object ball = dynamicSphere({x, x > 0.0f ? 0.6f : 0.2f, 0.0f}, 0.2f, 1.0f);
        ball.spin = {0.0f, 5.0f, 0.0f};
        s.objects.push_back(ball);
    }
    PhysicsWorld w(s);
    run(w, 0.5);
    const double spun = 5.0 - 2.5 * 0.05 * 9.81 / 0.2 * 0.5;
    for (int i = 0; i < w.bodyCount(); ++i) {
        std::printf("spun on the spot: %.4f rad/s after 0.5 s (closed form %.4f)\n",
                    w.body(i).spin.y, spun);
        EXPECT_NEAR(w.body(i).spin.y, spun, 0.01 * spun) << "ball " << i;
    }
}

INSTANTIATE_TEST_SUITE_P(CylinderAndCapsule, RigidRolling,
                         ::testing::Values(ShapeType::Cylinder, ShapeType::Capsule));

// Dropped flat from 1 m with e = 0.5, a box first rises to e²·h above where it landed, within
// 1 mm, and picks up no spin (< 1e-6 rad/s): its four corners bounce as one face.
TEST(RigidContacts, BoxDroppedFlatBouncesStraight) {
    Scene s = physicsWorld(9.81f, 0.5f, 0.5f, true);
    s.objects.push_back(dynamicBox({0, 1.25f, 0}, {0.25f, 0.25f, 0.25f}));
    PhysicsWorld w(s);
    double apex = 0.0, spin = 0.0;
    bool rising = false;
    for (int i = 0; i < stepsFor(1.0, w.settings()); ++i) {  // to just past the first apex
        w.step();
        const RigidState b = w.rigid(0);
        spin = std::max(spin, glm::length(b.spin));
        rising |= b.vel.y > 0.0;
        if (rising) apex = std::max(apex, b.pos.y - 0.25);
        if (rising && b.vel.y < 0.0) break;
    }
    std::printf("flat drop: apex %.4f m (e²·h 0.25), spin %.3g rad/s\n", apex, spin);
    EXPECT_NEAR(apex, 0.25, 1e-3);
    EXPECT_LT(spin, 1e-6);
}

// Dropped flat at speed onto the ground (μ = 0.3, e = 0), a body has nothing to push it aside:
// it stops where it lands, unturned. Measured: 1.5 mm aside at 20 m/s and 7.7 mm at 60 m/s for
// the unit box, under 0.1 mm for the slab and the disc, all turned under 0.02°. Allowed 1 cm
// and 0.5°. Planted: the slab's probes up its sides kept in its manifold (reached at 60 m/s,
// they stand in for two of its face's corners; it ends 11 m aside); an impact's face swept as
// often as a resting one (the unit box 2.2 cm aside at 20 m/s and 39 cm at 60, the disc 27 cm).
TEST(RigidContacts, ABodyDroppedFlatAtSpeedStopsWhereItLands) {
    const struct {
        const char* shape;
        float speed;
    } cases[] = {{"type:box size:0.5,0.5,0.5", 20.0f},
                 {"type:box size:0.5,0.5,0.5", 60.0f},
                 {"type:box size:1,0.1,0.5 rot:0,30,0", 60.0f},
                 {"type:cylinder radius:0.5 height:0.3", 60.0f}};
    for (const auto& c : cases) {
        PhysicsWorld w(sceneFromText("scene version:3\nworld restitution:0 friction:0.3\nobject " +
                                     std::string(c.shape) + " pos:0,1,0 mass:1 vel:0," +
                                     std::to_string(-c.speed) + ",0\n"));
        const dquat start = w.rigid(0).orient;
        run(w, 2.0);
        const RigidState b = w.rigid(0);
        const double aside = std::hypot(b.pos.x, b.pos.z);
        const double turned = 2.0 * std::acos(std::min(1.0, std::abs(glm::dot(start, b.orient))));
        std::printf("%s at %g m/s: %.3g m aside, turned %.3g°\n", c.shape, c.speed, aside,
                    glm::degrees(turned));
        EXPECT_LT(aside, 0.01) << c.shape << " at " << c.speed << " m/s";
        EXPECT_LT(glm::degrees(turned), 0.5) << c.shape << " at " << c.speed << " m/s";
    }
}

// A static object's own corners, edges, rims and round crowns touch a body's faces where none
// of the body's probes lie. Each within the slop after 2 s, unturned: a box overhanging a static
// table's edge by 5 cm (its centre 15 cm inside) stays where it was put; a slab dropped onto a
// thin post rests on its top; a slab on a static dome of radius 5 rests on its crown. Measured:
// 0.08 mm aside, 0.1 mm and 0.5 mm low. Planted: the static objects' probes left out (the box
// tips off the table, the slab falls past the post to the ground, and sinks 10 cm into the dome).
TEST(RigidContacts, AStaticEdgePostOrDomeHoldsAFaceOnIt) {
    const struct {
        const char* name;
        const char* scene;
        dvec3 rest;
    } cases[] = {
        {"overhang",
         "world restitution:0.2 friction:0.6\n"
         "object type:box pos:0,0.25,0 size:1,0.25,1 static:1\n"
         "object type:box pos:0.85,0.7,0 size:0.2,0.2,0.2 mass:1\n",
         {0.85, 0.7, 0.0}},
        {"post",
         "world restitution:0.2 friction:0.6\n"
         "object type:cylinder pos:0,0.6,0 radius:0.05 height:1.2 static:1\n"
         "object type:box size:0.5,0.1,0.5 pos:0,1.32,0 mass:1\n",
         {0.0, 1.3, 0.0}},
        {"dome",
         "world ground:0 restitution:0.2 friction:0.6\n"
         "object type:sphere pos:0,-5,0 radius:5 static:1\n"
         "object type:box size:1,0.2,1 pos:0,0.22,0 mass:1\n",
         {0.0, 0.2, 0.0}},
    };
    const double slop = PhysicsSettings{}.linearSlop;
    for (const auto& c : cases) {
        PhysicsWorld w(sceneFromText(std::string("scene version:3\n") + c.scene));
        run(w, 2.0);
        const RigidState b = w.rigid(0);
        std::printf("%s: %.4f m from rest, turned %.3g°\n", c.name, glm::length(b.pos - c.rest),
                    glm::degrees(2.0 * std::acos(std::min(1.0, std::abs(b.orient.w)))));
        EXPECT_LT(glm::length(b.pos - c.rest), slop) << c.name;
        EXPECT_GT(std::abs(b.orient.w), std::cos(glm::radians(0.25))) << c.name << " turned";
    }
}

// Bodies of one height side by side have their edges level: each sharp probe of one lies on an
// edge of the other, where the normal is any between the edge's faces. Struck at 2 m/s with
// restitution 1 and no friction, an equal body takes the striker's whole speed (the striker
// stops) and a static one sends it back at 2 m/s, square on: no spin, no speed across, kinetic
// energy kept. Measured: 0.002 % of the energy lost at most, spin 0.04 rad/s at most. Planted,
// the normals as the straddling samples give them, (0.64, ±0.64, ±0.42): between bodies, the two
// cylinders lose 50 % and the groups spin at 3.3 rad/s; against a static surface, the box leaves
// 1.2 m/s off; against the static objects' own probes, 1.6 m/s off.
TEST(RigidContacts, BodiesOfOneHeightBounceSquareOffEachOther) {
    const char* fast = "mass:1 vel:-2,0,0\n";
    const std::string member =
        "type:cylinder radius:0.3 height:0.5 pos:0,-0.25,0\n"
        "object type:cylinder radius:0.2 height:0.5 pos:0,0.25,0 in:";
    const struct {
        const char* name;
        std::string scene;
        bool staticFirst;
    } cases[] = {
        {"cylinders",
         std::string("object type:cylinder pos:0,0,0 radius:0.3 height:1 mass:1\n"
                     "object type:cylinder pos:1.5,0,0 radius:0.3 height:1 ") +
             fast,
         false},
        {"groups",
         "group name:a mass:1\nobject in:a " + member + "a\ngroup name:b pos:1.5,0,0 " + fast +
             "object in:b " + member + "b\n",
         false},
        {"cylinder at a static box",
         std::string("object type:box pos:0,0,0 size:0.3,0.5,0.3 static:1\n"
                     "object type:cylinder pos:1.5,0,0 radius:0.3 height:1 ") +
             fast,
         true},
        {"box at a static box",
         std::string("object type:box pos:0,0,0 size:0.3,0.5,0.3 static:1\n"
                     "object type:box pos:1.5,0,0 size:0.3,0.5,0.3 ") +
             fast,
         true},
    };
    for (const auto& c : cases) {
        PhysicsWorld w(sceneFromText(
            "scene version:3\nworld gravity:0 restitution:1 friction:0 ground:0\n" + c.scene));
        const double energy = w.kineticEnergy();
        run(w, 1.0);
        // The first body: the one struck, or the striker sent back from a static one.
        const RigidState first = w.rigid(0), last = w.rigid(w.rigidCount() - 1);
        const dvec3 expected = c.staticFirst ? dvec3(2, 0, 0) : dvec3(-2, 0, 0);
        const double spin = std::max(glm::length(first.spin), glm::length(last.spin));
        std::printf("%s: %.4g m/s off, spin %.3g rad/s, energy %+.3g %%\n", c.name,
                    glm::length(first.vel - expected), spin,
                    100.0 * (w.kineticEnergy() / energy - 1.0));
        EXPECT_LT(glm::length(first.vel - expected), 0.02) << c.name;
        if (!c.staticFirst) {
            EXPECT_LT(glm::length(last.vel), 0.02) << c.name << ": the striker goes on";
        }
        EXPECT_LT(spin, 0.1) << c.name;
        EXPECT_NEAR(w.kineticEnergy(), energy, 1e-3 * energy) << c.name;
    }
}

// A ring (a torus of radius 0.3, tube 0.05) on its edge rolls as a wheel of radius 0.35: on
// level ground (no rolling resistance) it keeps its 2 m/s and does not bounce; down a 20° ramp
// it gains g·sin θ / (1 + I/(m·ρ²)) a second, I = m·(R² + ¾·r²) about its axis, ρ = R + r.
// Within 0.5 % and 1 % after 2 s (measured 0.04 % and 0.06 %). Planted: the core circle as 24
// fixed points: it rolls as a polygon, slows to 1.03 m/s, and gains 0.75-0.89 of the closed form.
TEST(RigidContacts, ARingRollsOnItsEdgeAsAWheel) {
    PhysicsWorld level(sceneFromText(
        "scene version:3\nworld friction:0.8 rolling:0 restitution:0\n"
        "object type:torus pos:0,0.35,0 radius:0.3 minor:0.05 rot:90,0,0 mass:1 vel:2,0,0 "
        "spin:0,0,-5.714285714\n"));
    run(level, 2.0);
    std::printf("ring on level ground: %.5f m/s after 2 s, %.3g m/s up\n", level.rigid(0).vel.x,
                level.rigid(0).vel.y);
    EXPECT_NEAR(level.rigid(0).vel.x, 2.0, 0.01);
    EXPECT_LT(std::abs(level.rigid(0).vel.y), 1e-3) << "it bounces";
    PhysicsWorld ramp(sceneFromText(
        "scene version:3\nworld friction:0.8 rolling:0 restitution:0 ground:0\n"
        "object type:box pos:0,0,0 size:6,0.5,2 rot:0,0,20 static:1\n"
        "object type:torus pos:2.52836074,1.82479916,0 radius:0.3 minor:0.05 rot:90,0,0 "
        "mass:1\n"));
    run(ramp, 2.0);
    const double R = 0.3, r = 0.05, rho = R + r;
    const double a =
        9.81 * std::sin(glm::radians(20.0)) / (1.0 + (R * R + 0.75 * r * r) / (rho * rho));
    std::printf("ring down the ramp: %.5f m/s after 2 s (closed form %.5f)\n",
                glm::length(ramp.rigid(0).vel), 2.0 * a);
    EXPECT_NEAR(glm::length(ramp.rigid(0).vel), 2.0 * a, 0.01 * 2.0 * a);
}

// Ten unit boxes stacked: the top moves less than 1 cm in 60 s once the stack has settled into
// its contacts (the first second), and it settles by less than 1.5 cm: ten contacts, each
// squeezed by the weight above to about its slop (measured 1.2 cm).
TEST(RigidContacts, TenBoxStackStands) {
    PhysicsWorld w(boxStackScene(10));
    const dvec3 placed = w.rigid(9).pos;
    run(w, 1.0);
    const dvec3 settled = w.rigid(9).pos;
    run(w, 60.0);
    std::printf("stack: settled %.4g m, then moved %.4g m, %d awake\n",
                glm::length(settled - placed), glm::length(w.rigid(9).pos - settled),
                w.stats().awake);
    EXPECT_LT(glm::length(settled - placed), 0.015);
    EXPECT_LT(glm::length(w.rigid(9).pos - settled), 0.01);
}

// Cylinders of one radius stacked: each rim lies on the other cylinder's edge, inside its side
// wall as soon as the contacts press in. A column of eight on the ground, and three on a static
// cylinder, stand: the top settles by the slop and the weight (measured 7.9 and 2.4 mm) and does
// not tip. Planted: the rims' points that meet the wall not looked for again inside the rim:
// both columns sink through themselves, the eight by 3.5 m, the three by 1 m.
TEST(RigidContacts, ColumnsOfCylindersOfOneRadiusStand) {
    const struct {
        const char* name;
        const char* base;
        int count;
    } cases[] = {{"eight on the ground", "", 8},
                 {"three on a static one",
                  "object type:cylinder pos:0,0.25,0 radius:0.3 height:0.5 static:1\n", 3}};
    for (const auto& c : cases) {
        std::string text =
            std::string("scene version:3\nworld restitution:0.3 friction:0.5\n") + c.base;
        const int first = *c.base ? 1 : 0;
        for (int i = first; i < first + c.count; ++i)
            text += "object type:cylinder radius:0.3 height:0.5 mass:1 pos:0," +
                    std::to_string(0.25 + 0.5 * i) + ",0\n";
        PhysicsWorld w(sceneFromText(text));
        const dvec3 placed = w.rigid(c.count - 1).pos;
        run(w, 10.0);
        const RigidState top = w.rigid(c.count - 1);
        std::printf("%s: top %.4g m from where it was placed, turned %.3g°\n", c.name,
                    glm::length(top.pos - placed),
                    glm::degrees(2.0 * std::acos(std::min(1.0, std::abs(top.orient.w)))));
        EXPECT_LT(glm::length(top.pos - placed), 0.02) << c.name;
        EXPECT_GT(std::abs(top.orient.w), std::cos(glm::radians(1.0))) << c.name << " tipped";
    }
}

// A box on a static box of its own footprint: each corner lies on the static box's side wall
// once pressed in. Two stacked on it stand (the top settles 1.7 mm). Planted: corners that meet
// the wall not looked at again inside: both boxes fall through into the static one (1 m).
TEST(RigidContacts, BoxesOnAStaticBoxOfTheirFootprintStand) {
    PhysicsWorld w(
        sceneFromText("scene version:3\nworld restitution:0.3 friction:0.5\n"
                      "object type:box size:0.5,0.5,0.5 pos:0,0.5,0 static:1\n"
                      "object type:box size:0.5,0.5,0.5 pos:0,1.5,0 mass:1\n"
                      "object type:box size:0.5,0.5,0.5 pos:0,2.5,0 mass:1\n"));
    run(w, 5.0);
    const RigidState top = w.rigid(1);
    std::printf("top box: %.4g m from where it was placed\n",
                glm::length(top.pos - dvec3(0, 2.5, 0)));
    EXPECT_LT(glm::length(top.pos - dvec3(0, 2.5, 0)), 0.01);
}

// A torus (ring 0.3, tube 0.05) dropped tilted over an upright capsule peg (radius 0.1) settles
// around it: its centre on the peg's axis within the hole's play, lying flat on its tube.
TEST(RigidContacts, TorusDroppedOverAPegSettlesAroundIt) {
    Scene s = physicsWorld(9.81f, 0.2f, 0.5f, true);
    Object peg = staticShape(ShapeType::Capsule, {0, 0.6f, 0});
    peg.radius = 0.1f;
    peg.height = 1.0f;
    s.objects.push_back(peg);
    Object ring = dynamicShape(ShapeType::Torus, {0.05f, 1.5f, 0}, 1.0f);
    ring.radius = 0.3f;
    ring.minor = 0.05f;
    ring.rot = {10.0f, 0.0f, 0.0f};
    s.objects.push_back(ring);
    PhysicsWorld w(s);
    run(w, 4.0);
    const RigidState b = w.rigid(0);
    EXPECT_LT(std::hypot(b.pos.x, b.pos.z), 0.3 - 0.05 - 0.1 + 0.01) << "not around the peg";
    EXPECT_NEAR(b.pos.y, 0.05, 0.005) << "not lying on the ground on its tube";
}

// A box 5 cm thick thrown at 50 m/s against a wall 10 cm thick does not pass through it:
// 42 cm a step, more than both together; its speculative contacts stop it at the face.
TEST(RigidContacts, ThinFastBoxDoesNotPassThroughAWall) {
    PhysicsWorld w(thinBoxScene(50.0f));
    run(w, 0.5);
    EXPECT_LT(w.rigid(0).pos.x, 2.0 - 0.05) << "passed into or through the wall";
}

namespace {

// A capsule (r = 0.1, segment 0.4) dropped along x onto a heavy box lying on the ground, tilted
// by `tilt` degrees, from 2 cm above the face.
Scene capsuleOnBoxScene(float tilt) {
    Scene s = physicsWorld(9.81f, 0.2f, 0.5f, true);
    s.objects.push_back(dynamicBox({0, 0.1f, 0}, {0.5f, 0.1f, 0.4f}, 10.0f));
    Object capsule = dynamicShape(ShapeType::Capsule, {0.05f, 0.32f, 0}, 1.0f);
    capsule.radius = 0.1f;
    capsule.height = 0.4f;
    capsule.rot = {0.0f, 0.0f, 90.0f - tilt};
    if (tilt > 0.0f) capsule.pos.y += 0.2f * std::sin(float(tilt) * float(M_PI) / 180.0f);
    s.objects.push_back(capsule);
    return s;
}

// Each of a line's two points may rest anywhere within the rows' slop (0.1 · linearSlop) of
// its surface, so a capsule lying on points 0.4 apart is level to 0.1 · linearSlop / 0.4 rad.
double levelBound(const PhysicsWorld& w) { return 0.1 * w.settings().linearSlop / 0.4; }

// After 3 s the capsule lies on the face (its line of two points): its centre at the box's top
// + r, within the linear slop the solver allows, level (levelBound) and with no spin left
// (< 1e-3 rad/s). On one point it would rock about it and tilt.
void expectRestingFlat(float tilt) {
    PhysicsSettings awake;  // sleep would zero the spin this measures
    awake.sleep = false;
    PhysicsWorld w(capsuleOnBoxScene(tilt), awake);
    run(w, 3.0);
    const RigidState box = w.rigid(0), capsule = w.rigid(1);
    const double top = box.pos.y + 0.1, level = std::abs((capsule.orient * dvec3(0, 1, 0)).y);
    std::printf("capsule on box, tilt %g: above the top by %.5f m, axis %.3g rad, spin %.3g\n",
                double(tilt), capsule.pos.y - top, level, glm::length(capsule.spin));
    EXPECT_NEAR(capsule.pos.y, top + 0.1, w.settings().linearSlop);
    EXPECT_LT(level, levelBound(w));
    EXPECT_LT(glm::length(capsule.spin), 1e-3);
}

}  // namespace

TEST(RigidContacts, CapsuleLyingOnABoxRestsFlatAtItsRadius) { expectRestingFlat(0.0f); }

TEST(RigidContacts, CapsuleDroppedTiltedOnABoxComesToRestFlat) { expectRestingFlat(20.0f); }

// A capsule (segment 0.6) lying on another on the ground, shifted 0.2 along it: its centre is
// over their overlap, so it rests there on the overlap's two ends (0.4 apart), level
// (levelBound), its centre 2r above the lower one's within the slop, and still (< 0.01 rad/s).
// On the one closest point (under the lower one's centre) it would rock, at 0.2 rad/s.
TEST(RigidContacts, ParallelCapsuleRestsOnAShiftedOne) {
    Scene s = physicsWorld(9.81f, 0.2f, 0.5f, true);
    for (float x : {0.0f, 0.2f}) {
        Object capsule = dynamicShape(ShapeType::Capsule, {x, x == 0.0f ? 0.1f : 0.31f, 0}, 1.0f);
        capsule.radius = 0.1f;
        capsule.height = 0.6f;
        capsule.rot = {0.0f, 0.0f, 90.0f};
        s.objects.push_back(capsule);
    }
    PhysicsSettings awake;  // sleep would stop the tipping this looks for
    awake.sleep = false;
    PhysicsWorld w(s, awake);
    run(w, 3.0);
    const RigidState lower = w.rigid(0), upper = w.rigid(1);
    const double level = std::abs((upper.orient * dvec3(0, 1, 0)).y);
    std::printf("capsule on capsule: %.5f m above, axis %.3g rad, shift %.4f m, spin %.3g\n",
                upper.pos.y - lower.pos.y, level, upper.pos.x - lower.pos.x,
                glm::length(upper.spin));
    EXPECT_NEAR(upper.pos.y - lower.pos.y, 0.2, w.settings().linearSlop);
    EXPECT_LT(level, levelBound(w));
    EXPECT_NEAR(upper.pos.x - lower.pos.x, 0.2, 0.01);
    EXPECT_LT(glm::length(upper.spin), 0.01);
}

// A capsule rolling without slipping at 6 m/s (60 rad/s) across a long heavy box stays on the
// face: its centre within 1 mm of the box's top + r the whole way (0.55 s), twice the rows'
// slop (0.1 · linearSlop: it rests 0.6 mm deep). Its contact stays under its segment as it
// turns; were the contact's anchor carried round with the body, each substep's rows would see
// the surface fall away under it and let it sink (4.3 mm).
TEST(RigidContacts, CapsuleRollsAcrossABoxAtItsRadius) {
    Scene s = physicsWorld(9.81f, 0.0f, 0.8f, true);
    s.objects.push_back(dynamicBox({0, 0.1f, 0}, {2.0f, 0.1f, 0.5f}, 100.0f));
    Object capsule = dynamicShape(ShapeType::Capsule, {-1.8f, 0.3f, 0}, 1.0f);
    capsule.radius = 0.1f;
    capsule.height = 0.4f;
    capsule.rot = {90.0f, 0.0f, 0.0f};  // its axis along z, across the way it rolls
    capsule.vel = {6.0f, 0.0f, 0.0f};
    capsule.spin = {0.0f, 0.0f, -60.0f};
    s.objects.push_back(capsule);
    PhysicsSettings awake;
    awake.sleep = false;
    PhysicsWorld w(s, awake);
    double worst = 0.0;
    for (int i = 0; i < stepsFor(0.55, w.settings()); ++i) {
        w.step();
        worst = std::max(worst, std::abs(w.rigid(1).pos.y - (w.rigid(0).pos.y + 0.2)));
    }
    std::printf("rolling capsule: %.4f m from the top + r at worst, at x = %.3f\n", worst,
                w.rigid(1).pos.x);
    EXPECT_LT(worst, 0.2 * w.settings().linearSlop);
}

// Bodies laid across a lying cylinder's side, where no rim of it and no corner or edge point of
// theirs meets the other: each comes to rest on the side, its centre the radii above it, within
// the slop (5 mm), and sleeps. Groups too: a tube (carved, searched by a scan) and a group's
// cylinder member (a union's part, searched as convex). Planted: no side probes (nearestOnSide
// finding nothing): every one falls through the cylinder under it, the tube by 14 cm.
TEST(RigidContacts, BodiesLaidAcrossACylinderRestOnItsSide) {
    const struct {
        const char* name;
        const char* scene;
        int body;       // the one laid across, in scene order among the dynamic bodies
        double height;  // where its centre rests
    } cases[] = {
        {"a cylinder across a static one",
         "object type:cylinder pos:0,0.2,0 radius:0.2 height:2 rot:90,0,0 static:1\n"
         "object type:cylinder pos:0,0.7,0 radius:0.2 height:2 rot:0,0,90 mass:1\n",
         0, 0.6},
        {"a cylinder across a lying one",
         "object type:cylinder pos:0,0.2,0 radius:0.2 height:2 rot:90,0,0 mass:1\n"
         "object type:cylinder pos:0,0.7,0 radius:0.2 height:2 rot:0,0,90 mass:1\n",
         1, 0.6},
        {"a bar across two static pipes",
         "object type:cylinder pos:-0.3,0.1,0 radius:0.1 height:2 rot:90,0,0 static:1\n"
         "object type:cylinder pos:0.3,0.1,0 radius:0.1 height:2 rot:90,0,0 static:1\n"
         "object type:box pos:0,0.35,0 size:0.6,0.1,0.1 mass:1\n",
         0, 0.3},
        {"a tube across a tube",
         "group name:a pos:0,0.2,0 rot:90,0,0 mass:1\n"
         "object in:a type:cylinder pos:0,0,0 radius:0.2 height:2\n"
         "object in:a type:cylinder pos:0,0,0 radius:0.1 height:2.2 op:subtract\n"
         "group name:b pos:0,0.7,0 rot:0,0,90 mass:1\n"
         "object in:b type:cylinder pos:0,0,0 radius:0.2 height:2\n"
         "object in:b type:cylinder pos:0,0,0 radius:0.1 height:2.2 op:subtract\n",
         1, 0.6},
        {"a group's leg across another's",
         "group name:a pos:0,0.2,0 rot:90,0,0 mass:1\n"
         "object in:a type:cylinder pos:0,0,0 radius:0.2 height:2\n"
         "group name:b pos:0,0.7,0 rot:0,0,90 mass:1\n"
         "object in:b type:cylinder pos:0,0,0 radius:0.2 height:2\n",
         1, 0.6},
        {"a cylinder across two static rails",
         "object type:box pos:0.6,0.05,-0.5 size:1,0.05,0.05 static:1\n"
         "object type:box pos:0.6,0.05,0.5 size:1,0.05,0.05 static:1\n"
         "object type:cylinder pos:0,0.35,0 radius:0.2 height:2 rot:90,0,0 mass:1\n",
         0, 0.3},
    };
    for (const auto& c : cases) {
        PhysicsWorld w(sceneFromText(std::string("scene version:3\nworld restitution:0.3 "
                                                 "friction:0.5\n") +
                                     c.scene));
        run(w, 5.0);
        const RigidState laid = w.rigid(c.body);
        std::printf("%s: rests at %.4f m (%.4f), %d awake\n", c.name, laid.pos.y, c.height,
                    w.stats().awake);
        EXPECT_NEAR(laid.pos.y, c.height, 0.005) << c.name;
        EXPECT_EQ(w.stats().awake, 0) << c.name;
    }
}

// A rod-like ellipsoid (1 m by 5 cm) laid across two static rails, whose support point under
// its middle meets nothing: it rests on them, its centre 0.1 + 0.05·√(1 − 0.5²) m up (the
// rails 0.5 m from its middle, within 2 mm), and sleeps. One 6 cm thick dropped tilted 10°
// across a wall's top edge stays on the wall (its centre above the top). Measured: 0.1434 m
// (0.1433); 1.032 m. Planted: no sides: the first falls between the rails to 0.049 m, the
// second through the wall to 0.04 m.
TEST(RigidContacts, AnEllipsoidLaidAcrossEdgesRestsOnThem) {
    PhysicsWorld rails(
        sceneFromText("scene version:3\nworld restitution:0.3 friction:0.5\n"
                      "object type:box pos:0.6,0.05,-0.5 size:1,0.05,0.05 static:1\n"
                      "object type:box pos:0.6,0.05,0.5 size:1,0.05,0.05 static:1\n"
                      "object type:ellipsoid pos:0,0.3,0 size:0.05,1,0.05 rot:90,0,0 mass:1\n"));
    run(rails, 2.0);
    const double expected = 0.1 + 0.05 * std::sqrt(0.75);
    std::printf("ellipsoid on rails: rests at %.4f m (%.4f), %d awake\n", rails.rigid(0).pos.y,
                expected, rails.stats().awake);
    EXPECT_NEAR(rails.rigid(0).pos.y, expected, 0.002);
    EXPECT_EQ(rails.stats().awake, 0);
    PhysicsWorld wall(
        sceneFromText("scene version:3\nobject type:box pos:0,0.5,0 size:0.5,0.5,3 static:1\n"
                      "object type:ellipsoid pos:0.3,1.2,0 size:1,0.03,0.03 rot:0,0,10 mass:1\n"));
    run(wall, 2.0);
    std::printf("ellipsoid across a wall's edge: centre at %.3f m\n", wall.rigid(0).pos.y);
    EXPECT_GT(wall.rigid(0).pos.y, 1.0) << "the rod went through the wall";
}

// A rod-like ellipsoid 1.7 m long and 16 mm thick lands at 30 m/s nearly flat, its lower tip
// first: the tip's contact stops that tip, and the rod turns flat within the step. Its centre
// never goes deeper than its own half thickness (measured: 2 mm below the ground at the worst,
// then it bounces). Planted: no tip probes (the step's contacts at the start's support point
// alone): the rod's far half comes down through the ground, its centre to 0.63 m below it.
TEST(RigidContacts, AThinEllipsoidTurningAsItLandsStaysOnTheGround) {
    PhysicsWorld w(sceneFromText(
        "scene version:3\nobject type:ellipsoid pos:0,0.45,0 size:0.008,0.85,0.008 "
        "orient:-0.0588,-0.7443,0.6568,0.1052 mass:0.2 vel:5,-30.5,20 spin:-3.9,4.4,5.3\n"));
    double lowest = w.rigid(0).pos.y;
    for (int i = 0; i < stepsFor(0.5, w.settings()); ++i) {
        w.step();
        lowest = std::min(lowest, w.rigid(0).pos.y);
    }
    std::printf("landing rod: centre at least %.4f m high\n", lowest);
    EXPECT_GT(lowest, -0.008) << "the rod went into the ground";
}

// A disc (r 0.2 m) on edge, spinning about its axis at 600 rad/s, meets a frictionless wall at
// 10 m/s, e = 0.5, no gravity: the wall's push on its rim passes through the axis, so it leaves
// at e·10 = 5 m/s still spinning at 600 rad/s. Measured: 4.47 m/s (the rim's other contact
// points take some of the bounce), 598.9 rad/s. Planted: the rows' speed along the normal
// taken with the spin about the axis: the rim's points a quarter turn from the wall read
// 120 m/s coming in, and the disc left at 54 m/s, spinning at 43 rad/s.
TEST(RigidContacts, ADiscSpinningOnEdgeBouncesOffAWallAsIfStill) {
    PhysicsWorld w(sceneFromText(
        "scene version:3\nworld gravity:0 restitution:0.5 friction:0 ground:0\n"
        "object type:box pos:-2.5,0,0 size:0.5,2,2 static:1\n"
        "object type:cylinder pos:0,0,0 radius:0.2 height:0.05 rot:90,0,0 vel:-10,0,0 "
        "spin:0,0,600\n"));
    run(w, 0.5);
    const RigidState disc = w.rigid(0);
    std::printf("spinning disc: leaves at %.3f m/s (5), spinning at %.1f rad/s (600)\n", disc.vel.x,
                disc.spin.z);
    EXPECT_NEAR(disc.vel.x, 5.0, 1.0);
    EXPECT_NEAR(disc.spin.z, 600.0, 6.0);
}

// A cone 2.4 m long and 8 cm across, spinning, comes at a wall's vertical end edge at 16 m/s.
// Its side's sphere there has its centre just inside the wall, where the wall's distance is
// creased between two faces, and too thick to be sampled beside the crease: its normal is then
// the wall's as seen from the cone's centre. It bounces off, never deeper into the wall than
// its own width (8 cm). Measured: 5.0 cm once, as it turns against the edge. Planted: the creased
// normal kept ((0.65, 0.54, −0.54): the tetrahedral samples on either side of the crease, which
// have no part along the edge, sum to one with it): the cone slid along it 0.32 m into the wall.
TEST(RigidContacts, AThinConeAtAWallsEdgeBouncesOff) {
    PhysicsWorld w(
        sceneFromText("scene version:3\nobject type:box pos:-3.5,1,0 size:0.5,2,3 static:1\n"
                      "object type:cone pos:-2.702,0.878,-2.29 radius:0.0392 height:2.359 "
                      "orient:0.0554,-0.1551,0.834,-0.5267 mass:5.75 vel:-12.44,0.77,-10.58 "
                      "spin:105,-190,434\n"));
    double deepest = 0.0;
    for (int i = 0; i < 12; ++i) {
        w.step();
        deepest = std::max(deepest, w.stats().maxPenetration);
    }
    std::printf("cone at a wall's edge: %.4f m deep at most, leaves at %.2f m/s\n", deepest,
                w.rigid(0).vel.x);
    EXPECT_LT(deepest, 0.08) << "the cone went into the wall";
    EXPECT_GT(w.rigid(0).vel.x, 0.0) << "the cone did not bounce";
}

// A bar laid across a ring lying flat crosses its tube twice, 30° from where the four support
// points of its flat core stand (a static ring's fixed points, 22.5° apart, miss it by 7.5°): it
// rests on the tube, its centre a tube's diameter and its own half height above the ground
// (0.25 m), within 2 mm, and sleeps: on a ring, a static ring, and a group's ring. Planted: the
// ring's core not searched along for the nearest point, the bar falls through the ring to the
// ground (0.049 m); the static ring's, it sinks 8.7 mm between the fixed points.
TEST(RigidContacts, ABarLaidAcrossARingRestsOnItsTube) {
    const struct {
        const char* name;
        const char* ring;
    } cases[] = {{"a ring", "object type:torus pos:0,0.1,0 radius:0.5 minor:0.1 mass:1\n"},
                 {"a static ring", "object type:torus pos:0,0.1,0 radius:0.5 minor:0.1 static:1\n"},
                 {"a group's ring",
                  "group name:ring pos:0,0.1,0 mass:1\n"
                  "object in:ring type:torus pos:0,0,0 radius:0.5 minor:0.1\n"}};
    for (const auto& c : cases) {
        PhysicsWorld w(sceneFromText(
            std::string("scene version:3\nworld restitution:0.2 friction:0.5\n") + c.ring +
            "object type:box pos:0,0.5,0 size:1,0.05,0.05 rot:0,30,0 mass:1\n"));
        run(w, 3.0);
        const RigidState bar = w.rigid(w.rigidCount() - 1);
        std::printf("bar on %s: rests at %.4f m (0.25), %d awake\n", c.name, bar.pos.y,
                    w.stats().awake);
        EXPECT_NEAR(bar.pos.y, 0.25, 0.002) << c.name;
        EXPECT_EQ(w.stats().awake, 0) << c.name;
    }
}

// A ring laid flat on two static bars, one turned 30°: each crosses its tube away from the four
// support points of its flat core. It rests on both, level (within 1°), its centre a bar's
// height and a tube's radius up (0.2 m) within the slop. Planted: the static scene not searched
// along the core: it sinks 1.7 cm into the bars and tilts 9.6°.
TEST(RigidContacts, ARingLaidOnTwoStaticBarsRestsLevel) {
    PhysicsWorld w(
        sceneFromText("scene version:3\nworld restitution:0.2 friction:0.5\n"
                      "object type:box pos:0,0.05,0 size:1,0.05,0.05 rot:0,30,0 static:1\n"
                      "object type:box pos:0,0.05,0.8 size:1,0.05,0.05 static:1\n"
                      "object type:torus pos:0,0.5,0.4 radius:0.5 minor:0.1 mass:1\n"));
    run(w, 3.0);
    const RigidState ring = w.rigid(0);
    const double tilt = glm::degrees(2.0 * std::acos(std::min(1.0, std::abs(ring.orient.w))));
    std::printf("ring: rests at %.4f m (0.2), tilted %.2f°\n", ring.pos.y, tilt);
    EXPECT_NEAR(ring.pos.y, 0.2, 0.005);
    EXPECT_LT(tilt, 1.0);
}
