// export_report.cpp — writes docs/export-report.md: each example scene exported as STL.
#include "marchbox/report/export_report.h"

#include "marchbox/export/export.h"
#include "marchbox/report/median.h"
#include "marchbox/scene/scene_io.h"
#include "marchbox/scene/sdf.h"

#include "report_plot.h"
#include "report_template.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <unistd.h>
#include <vector>

namespace mb {

namespace {

constexpr int kRuns = 3;                // the time quoted is their median
constexpr double kDefaultTarget = 5.0;  // s: scenes/default.txt on the 2-core machine

struct ExportRow {
    std::string name;
    double seconds = 0.0;  // median wall time of exportScene
    size_t triangles = 0;
    double voxel = 0.0;  // m
    double error = 0.0;  // m, largest |f| over the vertices
};

// The median of kRuns exports to `stl`; false with *why where one fails.
bool timeExport(const Scene& scene, const std::string& stl, ExportRow* row, std::string* why) {
    std::vector<double> seconds;
    for (int i = 0; i < kRuns; ++i) {
        const auto start = std::chrono::steady_clock::now();
        const ExportResult r = exportScene(scene, stl, ExportSettings());
        seconds.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        if (r.status != ExportResult::Written) {
            *why = r.error;
            return false;
        }
        row->triangles = r.triangles;
        row->voxel = r.voxel;
    }
    row->seconds = median(seconds);
    return true;
}

std::string table(const std::vector<ExportRow>& rows) {
    std::ostringstream md;
    md << "| scene | time | triangles | voxel S | largest vertex error | error / S |\n"
          "| --- | ---: | ---: | ---: | ---: | ---: |\n";
    for (const ExportRow& r : rows)
        md << "| " << r.name << " | " << fmt("%.2f s", r.seconds) << " | "
           << fmt("%.0f", double(r.triangles)) << " | " << fmt("%.3g m", r.voxel) << " | "
           << fmt("%.3g m", r.error) << " | " << fmt("%.3f", r.error / r.voxel) << " |\n";
    return md.str();
}

}  // namespace

int runExportReport(const std::string& repoRoot) {
    std::string text, error;
    if (!readReportTemplate(repoRoot, "export-report.md", &text, &error)) {
        std::cerr << error << '\n';
        return 1;
    }
    const std::vector<std::filesystem::path> files = exampleSceneFiles(repoRoot);

    std::error_code ec;
    const std::filesystem::path tmp = std::filesystem::temp_directory_path() /
                                      ("marchbox-export-report-" + std::to_string(getpid()));
    std::filesystem::create_directories(tmp, ec);
    std::vector<ExportRow> rows;
    std::string skipped;
    for (const std::filesystem::path& file : files) {
        Scene scene;
        std::vector<std::string> errors;
        const std::string name = file.stem().string();
        if (!loadScene(file.string(), &scene, &errors)) {
            std::cerr << "export report: " << name << " does not load\n";
            return 1;
        }
        if (objectBounds(makeSceneSdf(scene)).empty()) {
            skipped += (skipped.empty() ? "" : ", ") + name;
            continue;
        }
        std::cerr << "export report: " << name << '\n';
        ExportRow row;
        row.name = name;
        std::string why;
        if (!timeExport(scene, (tmp / (name + ".stl")).string(), &row, &why)) {
            std::cerr << "export report: " << name << ": " << why << '\n';
            std::filesystem::remove_all(tmp, ec);
            return 1;
        }
        row.error = exportVertexError(scene, row.voxel);
        rows.push_back(row);
    }
    std::filesystem::remove_all(tmp, ec);

    const auto byName = [&](const std::string& n) {
        return std::find_if(rows.begin(), rows.end(),
                            [&](const ExportRow& r) { return r.name == n; });
    };
    const auto deflt = byName("default");
    if (deflt == rows.end()) {
        std::cerr << "export report: scenes/default.txt has no solids\n";
        return 1;
    }
    const auto worst =
        std::max_element(rows.begin(), rows.end(), [](const ExportRow& a, const ExportRow& b) {
            return a.error / a.voxel < b.error / b.voxel;
        });
    std::string over;  // the scenes past S/2
    for (const ExportRow& r : rows)
        if (r.error > r.voxel / 2) over += (over.empty() ? "" : ", ") + r.name;
    TemplateValues v = {
        {"machine", machineDescription()},
        {"compiler", __VERSION__},
        {"runs", std::to_string(kRuns)},
        {"table", table(rows)},
        {"skipped", skipped.empty() ? "none" : skipped},
        {"target", fmt("%g s", kDefaultTarget)},
        {"default_time", fmt("%.2f s", deflt->seconds)},
        {"default_verdict", deflt->seconds <= kDefaultTarget ? "within it" : "**over it**"},
        {"worst_scene", worst->name},
        {"worst_fraction", fmt("%.3f", worst->error / worst->voxel)},
        {"promise_verdict", over.empty() ? "every scene keeps it" : "**broken** in " + over},
    };
    const std::string out = repoRoot + "/docs/export-report.md";
    if (!writeReport(out, text, v, &error)) {
        std::cerr << error << '\n';
        return 1;
    }
    std::cerr << "wrote " << out << '\n';
    return 0;
}

}  // namespace mb
