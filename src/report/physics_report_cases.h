// physics_report_cases.h — what the physics report measures: analytic cases run under each
// solver variant, and the stiff and extreme suite.
#pragma once

#include "marchbox/physics/physics.h"

#include <functional>
#include <string>
#include <vector>

namespace mb {

struct AnalyticCase {
    std::string name;                                   // "Free fall"
    std::string error;                                  // what the error is, with units
    double seconds;                                     // simulated time of one run
    std::function<double(const PhysicsSettings&)> run;  // one run: returns the error
};
std::vector<AnalyticCase> analyticCases();       // spheres, then rigidAnalyticCases()
std::vector<AnalyticCase> rigidAnalyticCases();  // bodies that turn

struct Variant {
    std::string series;  // the sweep it belongs to: one plot line
    std::string label;   // the swept value
    PhysicsSettings settings;
};
std::vector<Variant> reportVariants();

struct WorkPoint {
    double secondsPerSimSecond;  // run time per simulated second
    double error;
};
WorkPoint measureWork(const AnalyticCase& c, const PhysicsSettings& s);  // repeats for timing

struct ExtremeResult {
    std::string name;
    bool pass = false;
    double maxPenetration = 0.0;  // m, deepest contact overlap seen
    double energyDrift = 0.0;     // (E_end − E_0) / |E_0|, kinetic + potential
    double msPerStep = 0.0;
    std::string note;  // the pass criterion, or what was seen
};
std::vector<ExtremeResult> runExtremeSuite();

struct FlatLanding {
    double apexError;  // m, |first apex − e²·h|
    double spin;       // rad/s, the most the cube turned at before that apex
};
FlatLanding landFlat(const PhysicsSettings& s);  // "Box landing flat"

// Markdown: a rigid manifold's relax and bounce sweeps, each count's time and errors.
std::string sweepsTable();

}  // namespace mb
