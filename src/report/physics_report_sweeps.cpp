// physics_report_sweeps.cpp — what a rigid manifold's relax and bounce sweeps buy: the time of
// a mixed pile's step beside the errors the sweeps are there to remove.
#include "physics_report_cases.h"

#include "marchbox/report/physics_scenes.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace mb {

namespace {

struct SweepPoint {
    int relax, bounce;
    double msPerStep = 1e300;  // mixed pile of 1000, first 1.5 s: the fastest round
    double overlap = 0.0;      // m, its deepest overlap, the mean over its steps
    double apexError = 0.0;    // m, a cube landing flat: |first apex − e²·h|
    double spin = 0.0;         // rad/s it picked up
    double drift = 0.0;        // m, the ten-box stack's top in 20 s once settled
};

PhysicsSettings settingsOf(const SweepPoint& p) {
    PhysicsSettings s;
    s.relaxSweeps = p.relax;
    s.bounceSweeps = p.bounce;
    return s;
}

void timePile(SweepPoint& p) {
    const PhysicsSettings s = settingsOf(p);
    PhysicsWorld w(mixedPileScene(1000, 7), s);
    const int steps = stepsFor(1.5, s);
    double busy = 0.0, overlap = 0.0;
    for (int i = 0; i < steps; ++i) {
        const auto start = std::chrono::steady_clock::now();
        w.step();
        busy += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        overlap += w.stats().maxPenetration;
    }
    p.overlap = overlap / steps;
    p.msPerStep = std::min(p.msPerStep, 1e3 * busy / steps);
}

void standStack(SweepPoint& p) {
    PhysicsSettings s = settingsOf(p);
    s.sleep = false;
    PhysicsWorld w(boxStackScene(10), s);
    for (int i = 0; i < stepsFor(1.0, s); ++i) w.step();
    const glm::dvec3 settled = w.rigid(9).pos;
    for (int i = 0; i < stepsFor(20.0, s); ++i) w.step();
    p.drift = glm::length(w.rigid(9).pos - settled);
}

// On the front: no other point is as fast and as accurate on every error, and better on one.
bool onFront(const SweepPoint& p, const std::vector<SweepPoint>& all) {
    for (const SweepPoint& q : all) {
        const double qs[] = {q.msPerStep, q.overlap, q.apexError, q.spin, q.drift};
        const double ps[] = {p.msPerStep, p.overlap, p.apexError, p.spin, p.drift};
        bool noWorse = true, better = false;
        for (int k = 0; k < 5; ++k) {
            noWorse = noWorse && qs[k] <= ps[k];
            better = better || qs[k] < ps[k];
        }
        if (noWorse && better) return false;
    }
    return true;
}

std::string row(const SweepPoint& p, bool front) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "| %d | %d | %.3g ms | %.3g m | %.2g m | %.2g rad/s | %.2g m | %s |\n", p.relax,
                  p.bounce, p.msPerStep, p.overlap, p.apexError, p.spin, p.drift,
                  front ? "yes" : "");
    return line;
}

}  // namespace

std::string sweepsTable() {
    const PhysicsSettings defaults;
    std::vector<SweepPoint> points;
    for (int relax : {1, 2, 4, 8}) points.push_back({relax, defaults.bounceSweeps});
    for (int bounce : {1, 4})
        if (bounce != defaults.bounceSweeps) points.push_back({defaults.relaxSweeps, bounce});
    // Three rounds, each point in turn, and the fastest of each point's three: a machine that
    // slows for a while slows one round of every point rather than every round of one.
    for (int round = 0; round < 3; ++round)
        for (SweepPoint& p : points) timePile(p);
    for (SweepPoint& p : points) {
        const FlatLanding landing = landFlat(settingsOf(p));
        p.apexError = landing.apexError;
        p.spin = landing.spin;
        standStack(p);
    }
    std::ostringstream md;
    md << "| relax sweeps | bounce sweeps | mixed pile of 1000: time per step "
          "| mean deepest overlap | cube landing flat: apex error | spin picked up "
          "| ten-box stack: top's drift in 20 s | on the front |\n"
          "| ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |\n";
    for (const SweepPoint& p : points) md << row(p, onFront(p, points));
    return md.str();
}

}  // namespace mb
