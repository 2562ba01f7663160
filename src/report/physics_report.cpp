// physics_report.cpp — writes docs/physics-report.md with work-precision plots.
#include "marchbox/report/physics_report.h"

#include "physics_report_cases.h"
#include "processes.h"
#include "report_plot.h"
#include "report_template.h"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace mb {

namespace {

constexpr double kZeroErrorDrawnAt = 1e-16;  // a log plot has no 0

std::string slug(const std::string& name) {
    std::string s;
    for (char c : name)
        s += std::isalnum(static_cast<unsigned char>(c)) ? char(std::tolower(c)) : '-';
    return s;
}

// One analytic case: a table row per variant and a plot with one line per sweep.
std::string workPrecision(const AnalyticCase& c, const std::string& docs) {
    std::ostringstream md;
    md << "### " << c.name << "\n\nError: " << c.error << ".\n\n![" << c.name << "](physics-"
       << slug(c.name)
       << ".svg)\n\n| sweep | setting | run time per simulated s | error |\n| --- | --- | ---: | "
          "---: |\n";
    std::map<std::string, PlotSeries> series;
    std::vector<std::string> order;
    for (const Variant& v : reportVariants()) {
        const WorkPoint p = measureWork(c, v.settings);
        md << "| " << v.series << " | " << v.label << " | "
           << fmt("%.3g µs", 1e6 * p.secondsPerSimSecond) << " | " << fmt("%.3g", p.error)
           << " |\n";
        if (!series.count(v.series)) order.push_back(v.series);
        series[v.series].name = v.series;
        const double drawn = std::max(p.error, kZeroErrorDrawnAt);
        series[v.series].points.emplace_back(p.secondsPerSimSecond, drawn);
    }
    std::vector<PlotSeries> plot;
    for (const std::string& name : order) plot.push_back(series[name]);
    writeTextFile(docs + "/physics-" + slug(c.name) + ".svg",
                  logLogPlotSvg(c.name, "run time per simulated second (s)", "error", plot));
    return md.str() + "\n";
}

std::string extremeTable() {
    std::ostringstream md;
    md << "| case | result | max penetration | energy drift | time per step | criterion |\n"
          "| --- | --- | ---: | ---: | ---: | --- |\n";
    for (const ExtremeResult& r : runExtremeSuite())
        md << "| " << r.name << " | " << (r.pass ? "pass" : "**FAIL**") << " | "
           << fmt("%.3g m", r.maxPenetration) << " | " << fmt("%+.2e", r.energyDrift) << " | "
           << fmt("%.3g ms", r.msPerStep) << " | " << r.note << " |\n";
    return md.str();
}

// The markdown a benchmark that src/report/bench/ builds beside this executable prints, or why
// there is none (`unbuilt`: where it was not built).
std::string benchSection(const std::string& name, const std::string& unbuilt) {
    const std::string exe = besideExecutable(name);
    if (exe.empty()) return name + " not run: cannot locate the executable.\n";
    if (access(exe.c_str(), X_OK) != 0) return unbuilt;
    std::string out;
    if (!runForOutput({exe}, &out)) out += "\n(" + name + " exited with an error)\n";
    return out;
}

std::string counted(int n, const char* what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

// The defaults the prose describes, from the settings themselves.
void describeSettings(TemplateValues* v) {
    const PhysicsSettings defaults;
    (*v)["dt"] = "1/" + fmt("%.0f", 1.0 / defaults.dt);
    (*v)["substeps"] = counted(defaults.substeps, "substep");
    (*v)["iterations"] = counted(defaults.iterations, "iteration");
    (*v)["slop"] = fmt("%g mm", 1000 * defaults.linearSlop);
    (*v)["zero_error"] = fmt("%g", kZeroErrorDrawnAt);
}

}  // namespace

int runPhysicsReport(const std::string& repoRoot) {
    const std::string docs = repoRoot + "/docs";
    std::string text, error;
    if (!readReportTemplate(repoRoot, "physics-report.md", &text, &error)) {
        std::cerr << error << '\n';
        return 1;
    }
    std::error_code ec;
    std::filesystem::create_directories(docs, ec);
    TemplateValues v = {{"machine", machineDescription()}, {"compiler", __VERSION__}};
    describeSettings(&v);
    std::cerr << "physics report: work precision\n";
    std::string& cases = v["work_precision"];
    for (const AnalyticCase& c : analyticCases()) cases += workPrecision(c, docs);
    std::cerr << "physics report: group mass properties\n";
    v["group_mass"] = benchSection("group_mass_bench", "group_mass_bench not built.\n");
    std::cerr << "physics report: stiff and extreme suite\n";
    v["extreme_table"] = extremeTable();
    std::cerr << "physics report: sweeps\n";
    v["sweeps"] = sweepsTable();
    std::cerr << "physics report: Bullet\n";
    v["bullet"] = benchSection("bullet_bench",
                               "Bullet comparison not built (needs libbullet-dev, found through "
                               "pkg-config `bullet`).\n");
    if (!writeReport(docs + "/physics-report.md", text, v, &error)) {
        std::cerr << error << '\n';
        return 1;
    }
    std::cerr << "wrote " << docs << "/physics-report.md\n";
    return 0;
}

}  // namespace mb
