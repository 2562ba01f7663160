// marchbox/report/export_report.h — `marchbox report export`: what exporting each example scene
// as STL costs, and how far its vertices lie from the surface.
#pragma once

#include <string>

namespace mb {

// Exports every example scene with solids (scenes/*.txt) at its default voxel to an STL in a
// temporary folder, three times, then writes docs/export-report.md under repoRoot. Returns a
// process exit code.
int runExportReport(const std::string& repoRoot);

}  // namespace mb
