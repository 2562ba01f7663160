// device_report.h — the render report's section on the EGL device: `report render --backend
// egl` on a machine with a GPU measures that section alone and writes it into the report,
// leaving llvmpipe's figures as they are; `report render` keeps the section it finds.
#pragma once

#include <string>

namespace mb {

// The section, between its markers: frame times of a few example scenes at three sizes, the
// frames a second of a sequence written as PNGs, and every example scene against OSMesa's
// picture of it. Each a whole process of this executable with --backend egl, as a user runs
// it. `root`: the source tree; `device`: the EGL context's GL_RENDERER. "" where it cannot run
// (no executable path, no temporary folder).
std::string deviceSection(const std::string& root, const std::string& device);

// The section as `report` finds it in `report` (a report's text), markers included, or the
// placeholder that says it was not measured.
std::string keptDeviceSection(const std::string& report);

// `report` with its section replaced by `section` (appended where it has none).
std::string withDeviceSection(const std::string& report, const std::string& section);

}  // namespace mb
