// processes.h — the report's own executable and its neighbours, run as a user runs them.
#pragma once

#include <string>
#include <vector>

namespace mb {

// The path of the running executable; empty where /proc/self/exe cannot be read.
std::string executablePath();

// `name` in the running executable's folder (where the build puts the benchmarks).
std::string besideExecutable(const std::string& name);

// Runs args[0] with args[1..] (no shell), its output thrown away, and returns its wall time in
// seconds; negative where it cannot be started or does not exit with 0.
double timedRun(const std::vector<std::string>& args);

// The same, keeping its standard output in *out; false where it cannot be started or does not
// exit with 0.
bool runForOutput(const std::vector<std::string>& args, std::string* out);

}  // namespace mb
