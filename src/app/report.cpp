// report.cpp — `marchbox report physics|render|export`: benchmarks that write docs/*.md.
#include "commands.h"
#include "marchbox/report/export_report.h"
#include "marchbox/report/physics_report.h"
#include "marchbox/report/render_report.h"

#include <iostream>

namespace mb {

int runReport(const Args& a) {
    if (a.positional.size() == 1 && a.positional[0] == "physics")
        return runPhysicsReport(MARCHBOX_SOURCE_DIR);
    if (a.positional.size() == 1 && a.positional[0] == "export")
        return runExportReport(MARCHBOX_SOURCE_DIR);
    OffscreenBackend backend;
    if (!offscreenBackend(a, &backend)) return kExitUsage;
    if (a.positional.size() == 1 && a.positional[0] == "render")
        return runRenderReport(MARCHBOX_SOURCE_DIR, backend);
    std::cerr << "usage: marchbox report physics|render|export\n";
    return kExitUsage;
}

}  // namespace mb
