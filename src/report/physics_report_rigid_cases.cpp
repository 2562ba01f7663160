// physics_report_rigid_cases.cpp — the analytic cases of bodies that turn: boxes, cylinders and
// a tube (a group) on slopes, a box landing flat, a box tumbling free.
#include "physics_report_cases.h"

#include "marchbox/report/physics_scenes.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace mb {

namespace {

constexpr double kG = double(9.81f);

Object body(ShapeType type) {
    Object o;
    o.type = type;
    o.size = {0.2f, 0.1f, 0.15f};
    o.radius = 0.2f;
    o.height = 0.6f;
    if (type != ShapeType::Box) o.rot = {90.0f, 0.0f, 0.0f};  // axis along z, across the slope
    return o;
}

// |a/expected − 1|, a from the distance the body's centre of mass went down the slope in 1 s
// from rest.
double slopeError(const PhysicsSettings& s, const Scene& scene, float degrees, double expected) {
    PhysicsWorld w(scene, s);
    const double t = double(degrees) * M_PI / 180.0;
    const glm::dvec3 down(-std::cos(t), -std::sin(t), 0.0), start = w.rigid(0).centre;
    const int steps = int(std::llround(1.0 / s.dt));
    for (int i = 0; i < steps; ++i) w.step();
    const double time = steps * s.dt;
    return std::abs(2.0 * glm::dot(w.rigid(0).centre - start, down) / (time * time) / expected -
                    1.0);
}

// 30°, μ = 0.3: a = g·(sin θ − μ·cos θ).
double boxSlideError(const PhysicsSettings& s) {
    const double theta = M_PI / 6.0, mu = double(0.3f);
    return slopeError(s, slopeScene(30.0f, 0.3f, body(ShapeType::Box)), 30.0f,
                      kG * (std::sin(theta) - mu * std::cos(theta)));
}

// 10°, μ = 0.8 (no slip): a = ⅔·g·sin θ.
double cylinderRollError(const PhysicsSettings& s) {
    const double theta = double(10.0f) * M_PI / 180.0;
    return slopeError(s, slopeScene(10.0f, 0.8f, body(ShapeType::Cylinder)), 10.0f,
                      2.0 / 3.0 * kG * std::sin(theta));
}

// A tube, a dynamic group whose mass properties are integrated, at 10°, μ = 0.8 (no slip):
// a = g·sin θ / (1 + I/(m·r0²)), I/m = (r0² + r1²)/2.
double tubeRollError(const PhysicsSettings& s) {
    const double theta = double(10.0f) * M_PI / 180.0, r0 = double(0.2f), r1 = double(0.12f);
    return slopeError(s, tubeSlopeScene(10.0f, 0.8f, 0.2f, 0.12f), 10.0f,
                      kG * std::sin(theta) / (1.0 + (r0 * r0 + r1 * r1) / (2.0 * r0 * r0)));
}

}  // namespace

// A cube of 0.5 m dropped flat from 1 m, e = 0.5: its first apex against e²·h, and the spin it
// picked up by then (the second landing's is another question).
FlatLanding landFlat(const PhysicsSettings& s) {
    Scene scene = physicsWorld(9.81f, 0.5f, 0.5f, true);
    Object cube = body(ShapeType::Box);
    cube.size = glm::vec3(0.25f);
    cube.pos = {0.0f, 1.25f, 0.0f};
    scene.objects.push_back(cube);
    PhysicsWorld w(scene, s);
    double apex = 0.0, spin = 0.0;
    bool rising = false, fell = false;
    for (int i = 0; i < int(std::llround(1.2 / s.dt)); ++i) {
        w.step();
        const RigidState b = w.rigid(0);
        rising = rising || b.vel.y > 0.0;
        fell = fell || (rising && b.vel.y < 0.0);
        if (rising) apex = std::max(apex, b.pos.y - 0.25);
        if (!fell) spin = std::max(spin, glm::length(b.spin));
    }
    const double e = double(0.5f);
    return {std::abs(apex - e * e * 1.0), spin};
}

namespace {

double flatDropError(const PhysicsSettings& s) { return landFlat(s).apexError; }

// A box of three different moments tumbling free for 10 s: |E/E0 − 1| at the end.
double tumbleError(const PhysicsSettings& s) {
    Scene scene = physicsWorld(0.0f, 0.5f, 0.5f, false);
    Object box = body(ShapeType::Box);
    box.size = {0.1f, 0.2f, 0.4f};
    box.spin = {3.0f, 5.0f, -4.0f};
    box.rot = {20.0f, 40.0f, 10.0f};
    scene.objects.push_back(box);
    PhysicsWorld w(scene, s);
    const double e0 = w.kineticEnergy();
    for (int i = 0; i < int(std::llround(10.0 / s.dt)); ++i) w.step();
    return std::abs(w.kineticEnergy() / e0 - 1.0);
}

}  // namespace

std::vector<AnalyticCase> rigidAnalyticCases() {
    return {
        {"Box slide", "|a/(g·(sin θ − μ·cos θ)) − 1| from the distance in 1 s (box, 30°, μ = 0.3)",
         1.0, boxSlideError},
        {"Cylinder roll", "|a/(⅔·g·sin θ) − 1| from the distance in 1 s (10°, μ = 0.8)", 1.0,
         cylinderRollError},
        {"Tube roll",
         "|a/(g·sin θ / (1 + (r0² + r1²)/(2·r0²))) − 1| from the distance in 1 s (a group: "
         "r0 = 0.2 m less r1 = 0.12 m, 10°, μ = 0.8)",
         1.0, tubeRollError},
        {"Box landing flat", "|first apex − e²·h|, m (0.5 m cube, h = 1 m, e = 0.5)", 1.2,
         flatDropError},
        {"Tumbling box", "|E(10 s)/E(0) − 1| (half extents 0.1, 0.2, 0.4, no gravity)", 10.0,
         tumbleError},
    };
}

}  // namespace mb
