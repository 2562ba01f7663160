// physics_report_cases.cpp — the report's analytic cases, solver variants and extreme suite.
#include "physics_report_cases.h"

#include "marchbox/report/physics_scenes.h"

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

// A sphere spinning in place at ω0 = 10 rad/s on the ground, μ = 0.3: friction turns the spin into
// rolling at v = 2/7·ω0·r (angular momentum about the contact point is kept).
double spinError(const PhysicsSettings& s) {
    const double w0 = 10.0;
    Scene scene = spinScene(float(w0), 0.3f);
    scene.world.rolling = 0.0f;  // pure Coulomb friction: rolling resistance would slow it down
    PhysicsWorld w(scene, s);
    for (int i = 0; i < int(std::llround(3.0 / s.dt)); ++i) w.step();
    const double v = 2.0 / 7.0 * w0 * w.body(0).radius;
    return std::abs(w.body(0).vel.x / v - 1.0);
}

// Kinetic energy of 64 elastic, frictionless spheres in a closed box after 30 s, against the start.
double gasError(const PhysicsSettings& s) {
    PhysicsWorld w(gasScene(64, 3), s);
    const double e0 = w.kineticEnergy();
    for (int i = 0; i < int(std::llround(30.0 / s.dt)); ++i) w.step();
    return std::abs(w.kineticEnergy() / e0 - 1.0);
}

// A striker at 2 m/s into a touching row of four, e = 1: the last ball leaves at 2 m/s, the rest
// stop.
double cradleError(const PhysicsSettings& s) {
    const double v = 2.0;
    PhysicsWorld w(cradleScene(4, float(v)), s);
    for (int i = 0; i < int(std::llround(1.0 / s.dt)); ++i) w.step();
    const int last = w.bodyCount() - 1;
    double error = std::abs(w.body(last).vel.x - v);
    for (int i = 0; i < last; ++i) error = std::max(error, glm::length(w.body(i).vel));
    return error;
}

// Largest |E − E0| over 10 periods of a frictionless ball in a bowl, against its swing energy.
double bowlError(const PhysicsSettings& s) {
    const float bowl = 1.5f, ball = 0.2f;
    PhysicsWorld w(bowlScene(bowl, ball, 20.0f, 0.0f), s);
    const double rho = double(bowl) - double(ball), e0 = w.kineticEnergy() + w.potentialEnergy();
    const double swing = e0 - kG * (double(bowlCentre(bowl).y) - rho) / w.body(0).invMass;
    double drift = 0.0;
    for (int i = 0; i < int(std::llround(10.0 * 2.0 * M_PI * std::sqrt(rho / kG) / s.dt)); ++i) {
        w.step();
        drift = std::max(drift, std::abs(w.kineticEnergy() + w.potentialEnergy() - e0));
    }
    return drift / swing;
}

// Acceleration down a tilted plank from the distance covered in 1 s, relative to closed form.
double rampError(const PhysicsSettings& s, float degrees, float mu, float rolling, bool rolls) {
    PhysicsWorld w(rampScene(degrees, mu, rolling), s);
    const double theta = double(degrees) * M_PI / 180.0;
    const glm::dvec3 down(-std::cos(theta), -std::sin(theta), 0.0), start = w.body(0).pos;
    const double a = rolls ? 5.0 / 7.0 * kG * (std::sin(theta) - double(rolling) * std::cos(theta))
                           : kG * (std::sin(theta) - double(mu) * std::cos(theta));
    const int steps = int(std::llround(1.0 / s.dt));
    for (int i = 0; i < steps; ++i) w.step();
    const double t = steps * s.dt;
    return std::abs(2.0 * glm::dot(w.body(0).pos - start, down) / (t * t) / a - 1.0);
}

}  // namespace

std::vector<AnalyticCase> analyticCases() {
    std::vector<AnalyticCase> cases = {
        {"Free fall", "|y − exact| after 2 s, m", 2.0, freeFallError},
        {"Bounce", "|third apex − e⁶·h|, m (h = 1 m, e = 0.8)", 3.0, bounceError},
        {"Head-on collision", "max |v − exact| after impact, m/s (e = 0.5, 1:3)", 1.0, headOnError},
        {"Slide to roll", "|x − exact| after 2 s, m (v0 = 5 m/s, μ = 0.3)", 2.0, slideError},
        {"Spin to roll", "|v/(2/7·ω0·r) − 1| after 3 s (ω0 = 10 rad/s, r = 0.5 m, μ = 0.3)", 3.0,
         spinError},
        {"Elastic gas", "|KE(30 s)/KE(0) − 1| of 64 spheres in a box (e = 1, μ = 0)", 30.0,
         gasError},
        {"Newton's cradle", "max |v − exact| after 1 s, m/s (striker at 2 m/s, row of 4, e = 1)",
         1.0, cradleError},
        {"Bowl", "max |E − E0| / swing energy over 10 periods (R = 1.5 m, r = 0.2 m, 20°, μ = 0)",
         23.0, bowlError},
        {"Ramp roll", "|a/(5/7·g·(sin θ − c·cos θ)) − 1| from the distance in 1 s (30°, c = 0.1)",
         1.0, [](const PhysicsSettings& s) { return rampError(s, 30.0f, 0.5f, 0.1f, true); }},
        {"Ramp slide", "|a/(g·(sin θ − μ·cos θ)) − 1| from the distance in 1 s (30°, μ = 0.1)", 1.0,
         [](const PhysicsSettings& s) { return rampError(s, 30.0f, 0.1f, 0.02f, false); }}};
    for (AnalyticCase& c : rigidAnalyticCases()) cases.push_back(std::move(c));
    return cases;
}

std::vector<Variant> reportVariants() {
    std::vector<Variant> out;
    const int rates[] = {60, 120, 240, 480};
    for (Integrator integrator : {Integrator::ExactGravity, Integrator::SymplecticEuler})
        for (int rate : rates) {
            PhysicsSettings s;
            s.dt = 1.0 / rate;
            s.integrator = integrator;
            out.push_back({integrator == Integrator::ExactGravity ? "dt (exact gravity)"
                                                                  : "dt (symplectic Euler)",
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
    // The method before impacts and curve following, at the default step, beside the new one.
    for (int rate : rates) {
        PhysicsSettings s;
        s.dt = 1.0 / rate;
        s.impacts = false;
        s.followCurves = false;
        out.push_back(
            {"dt (old: end-of-step bounce, step normals)", "dt = 1/" + std::to_string(rate), s});
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
