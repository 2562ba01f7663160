// physics_report_plot.h — log-log line plots as standalone SVG, for the physics report.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace mb {

struct PlotSeries {
    std::string name;
    std::vector<std::pair<double, double>> points;  // (x, y), both > 0; others are dropped
};

// An SVG document: axes at whole decades, one coloured polyline with markers per series, legend.
std::string logLogPlotSvg(const std::string& title, const std::string& xLabel, const std::string& yLabel,
                          const std::vector<PlotSeries>& series);

}  // namespace mb
