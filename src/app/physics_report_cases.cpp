// physics_report_cases.cpp — the report's analytic cases, solver variants and extreme suite.
#include "physics_report_cases.h"

#include "marchbox/physics_scenes.h"

#include <chrono>
#include <cmath>
#include <glm/geometric.hpp>

namespace mb {

namespace {

constexpr double kG = double(9.81f);
using Clock = std::chrono::steady_clock;

double elapsed(Clock::time_point since) {
    return std::chrono::duration<double>(Clock::now() - since).count();
}

double freeFallError(const PhysicsSettings& s) {
    PhysicsWorld w(freeFallScene(100.0f), s);
    const int steps = int(std::llround(2.0 / s.dt));
    for (int i = 0; i < steps; ++i) w.step();
    const double t = steps * s.dt;
    return std::abs(w.body(0).pos.y - (100.0 - 0.5 * kG * t * t));
}

// Third apex after a 1 m drop with e = 0.8, against e⁶·h.
double bounceError(const PhysicsSettings& s) {
    const double e = double(0.8f);
    PhysicsWorld w(bounceScene(1.0f, float(e)), s);
    double apex = 0.0, previousVy = 0.0;
    int bounces = 0;
    for (int i = 0; i < int(5.0 / s.dt); ++i) {
        w.step();
        const PhysicsBody& b = w.body(0);
        if (bounces == 3) apex = std::max(apex, b.pos.y - b.radius);
        if (previousVy < 0.0 && b.vel.y > 0.0) ++bounces;
        if (bounces == 3 && previousVy > 0.0 && b.vel.y <= 0.0) break;
        previousVy = b.vel.y;
    }
    return std::abs(apex - std::pow(e, 6.0));
}

double headOnError(const PhysicsSettings& s) {
    const double e = 0.5, m1 = 1, m2 = 3, v1 = 2, v2 = -1, u = (m1 * v1 + m2 * v2) / (m1 + m2);
    PhysicsWorld w(headOnScene(float(e), float(m1), float(m2), float(v1), float(v2)), s);
    for (int i = 0; i < int(std::llround(1.0 / s.dt)); ++i) w.step();
    return std::max(std::abs(w.body(0).vel.x - (u - e * m2 * (v1 - v2) / (m1 + m2))),
                    std::abs(w.body(1).vel.x - (u + e * m1 * (v1 - v2) / (m1 + m2))));
}

// Position after 2 s of a sphere launched sliding at 5 m/s, μ = 0.3: slides, then rolls at 5/7.
double slideError(const PhysicsSettings& settings) {
    const PhysicsSettings& s = settings;
    const double v0 = 5.0, mu = double(0.3f), v = 5.0 / 7.0 * v0, ts = 2.0 * v0 / (7.0 * mu * kG);
    Scene scene = slideScene(float(v0), float(mu));
    scene.world.rolling = 0.0f;  // pure Coulomb friction: rolling resistance would slow it down
    PhysicsWorld w(scene, s);
    const int steps = int(std::llround(2.0 / s.dt));
    for (int i = 0; i < steps; ++i) w.step();
    const double t = steps * s.dt;
    return std::abs(w.body(0).pos.x - (v0 * ts - 0.5 * mu * kG * ts * ts + v * (t - ts)));
}

}  // namespace

std::vector<AnalyticCase> analyticCases() {
    return {{"Free fall", "|y − exact| after 2 s, m", 2.0, freeFallError},
            {"Bounce", "|third apex − e⁶·h|, m (h = 1 m, e = 0.8)", 3.0, bounceError},
            {"Head-on collision", "max |v − exact| after impact, m/s (e = 0.5, 1:3)", 1.0, headOnError},
            {"Slide to roll", "|x − exact| after 2 s, m (v0 = 5 m/s, μ = 0.3)", 2.0, slideError}};
}

std::vector<Variant> reportVariants() {
    std::vector<Variant> out;
    const int rates[] = {60, 120, 240, 480};
    for (Integrator integrator : {Integrator::ExactGravity, Integrator::SymplecticEuler})
        for (int rate : rates) {
            PhysicsSettings s;
            s.dt = 1.0 / rate;
            s.integrator = integrator;
            out.push_back({integrator == Integrator::ExactGravity ? "dt (exact gravity)" : "dt (symplectic Euler)",
                           "dt = 1/" + std::to_string(rate), s});
        }
    for (int substeps : {1, 2, 4, 8}) {
        PhysicsSettings s;
        s.substeps = substeps;
        out.push_back({"substeps", std::to_string(substeps) + " substeps", s});
    }
    for (int iterations : {1, 2, 4, 8}) {
        PhysicsSettings s;
        s.iterations = iterations;
        out.push_back({"iterations", std::to_string(iterations) + " iterations", s});
    }
    return out;
}

WorkPoint measureWork(const AnalyticCase& c, const PhysicsSettings& s) {
    const double error = c.run(s);
    int runs = 0;
    const Clock::time_point start = Clock::now();
    while (elapsed(start) < 0.03 || runs < 3) {  // at least 30 ms for a steady clock reading
        c.run(s);
        ++runs;
    }
    return {elapsed(start) / (runs * c.seconds), error};
}

}  // namespace mb
