// report_plot.h — what the benchmark reports share: log-log SVG plots, the machine, files.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace mb {

struct PlotSeries {
    std::string name;
    std::vector<std::pair<double, double>> points;  // (x, y), both > 0; others are dropped
    bool line = true;                               // false: markers only (a scatter)
    std::vector<std::pair<double, double>>
        xSpread;  // per point, (min, max) of x: a whisker; may be empty
};

// An SVG document: axes at whole decades, one coloured polyline with markers per series, legend;
// horizontal whiskers where a series gives its points' x spread.
std::string logLogPlotSvg(const std::string& title, const std::string& xLabel,
                          const std::string& yLabel, const std::vector<PlotSeries>& series);

std::string machineDescription();  // CPU model and core count, for "measured on"
bool writeTextFile(const std::string& path, const std::string& text);
bool readTextFile(const std::string& path, std::string* text);  // false where it cannot
// The example scenes, `root`/scenes/*.txt, sorted by name.
std::vector<std::filesystem::path> exampleSceneFiles(const std::string& root);

}  // namespace mb
