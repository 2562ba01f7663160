// render_report.h — `marchbox report render`: docs/render-report.md and its SVG plots.
#pragma once

#include <string>

namespace mb {

int runRenderReport(const std::string& repoRoot);

}  // namespace mb
