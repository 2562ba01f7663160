// marchbox/report/render_report.h — `marchbox report render`: docs/render-report.md and its SVG
// plots.
#pragma once

#include "marchbox/gl/offscreen_context.h"

#include <string>

namespace mb {

int runRenderReport(const std::string& repoRoot, OffscreenBackend backend);

}  // namespace mb
