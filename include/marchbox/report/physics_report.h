// marchbox/report/physics_report.h — `marchbox report physics`: the simulator's error against its
// run time.
#pragma once

#include <string>

namespace mb {

// Measures the analytic cases under every solver variant, runs the stiff and extreme suite and,
// when it was built, the Bullet comparison (src/report/bench/), then writes docs/physics-report.md
// and the work-precision plots docs/physics-*.svg under repoRoot. Returns a process exit code.
int runPhysicsReport(const std::string& repoRoot);

}  // namespace mb
