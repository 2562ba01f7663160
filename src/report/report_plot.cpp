// report_plot.cpp — a small log-log SVG plotter.
#include "report_plot.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <thread>

namespace mb {

namespace {

constexpr double kWidth = 640, kHeight = 420, kLeft = 80, kRight = 200, kTop = 40, kBottom = 60;
const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};

struct Decades {
    double lo, hi;  // log10 of the axis ends, whole numbers
    double map(double v, double from, double to) const {
        return from + (std::log10(v) - lo) / (hi - lo) * (to - from);
    }
};

Decades decadesOf(const std::vector<PlotSeries>& series, bool useX) {
    double lo = 1e300, hi = -1e300;
    for (const PlotSeries& s : series)
        for (auto [x, y] : s.points) {
            const double v = useX ? x : y;
            if (v <= 0.0 || !std::isfinite(v)) continue;
            lo = std::min(lo, std::floor(std::log10(v)));
            hi = std::max(hi, std::ceil(std::log10(v)));
        }
    if (lo > hi) lo = 0, hi = 1;
    if (lo == hi) hi = lo + 1;
    return {lo, hi};
}

void drawAxes(std::ostringstream& svg, const Decades& x, const Decades& y) {
    const double x0 = kLeft, x1 = kWidth - kRight, y0 = kHeight - kBottom, y1 = kTop;
    svg << "<rect x='" << x0 << "' y='" << y1 << "' width='" << x1 - x0 << "' height='" << y0 - y1
        << "' fill='none' stroke='#333'/>\n";
    for (double d = x.lo; d <= x.hi; ++d) {
        const double px = x.map(std::pow(10.0, d), x0, x1);
        svg << "<line x1='" << px << "' y1='" << y0 << "' x2='" << px << "' y2='" << y1
            << "' stroke='#ddd'/><text x='" << px << "' y='" << y0 + 18
            << "' text-anchor='middle'>1e" << d << "</text>\n";
    }
    for (double d = y.lo; d <= y.hi; ++d) {
        const double py = y.map(std::pow(10.0, d), y0, y1);
        svg << "<line x1='" << x0 << "' y1='" << py << "' x2='" << x1 << "' y2='" << py
            << "' stroke='#ddd'/><text x='" << x0 - 6 << "' y='" << py + 4
            << "' text-anchor='end'>1e" << d << "</text>\n";
    }
}

void drawSeries(std::ostringstream& svg, const PlotSeries& s, const char* colour, int index,
                const Decades& x, const Decades& y) {
    const double x0 = kLeft, x1 = kWidth - kRight, y0 = kHeight - kBottom, y1 = kTop;
    std::ostringstream line;
    for (size_t i = 0; i < s.points.size(); ++i) {
        auto [vx, vy] = s.points[i];
        if (vx <= 0.0 || vy <= 0.0) continue;
        const double px = x.map(vx, x0, x1), py = y.map(vy, y0, y1);
        if (i < s.xSpread.size() && s.xSpread[i].first > 0.0) {
            const double lo = x.map(s.xSpread[i].first, x0, x1),
                         hi = x.map(s.xSpread[i].second, x0, x1);
            svg << "<path d='M" << lo << ',' << py - 3 << "v6M" << lo << ',' << py << "H" << hi
                << "M" << hi << ',' << py - 3 << "v6' stroke='" << colour << "' fill='none'/>\n";
        }
        line << px << ',' << py << ' ';
        svg << "<circle cx='" << px << "' cy='" << py << "' r='3.5' fill='" << colour << "'/>\n";
    }
    if (s.line)
        svg << "<polyline points='" << line.str() << "' fill='none' stroke='" << colour << "'/>\n";
    const double ly = kTop + 16 + 20 * index;
    svg << "<line x1='" << x1 + 12 << "' y1='" << ly - 4 << "' x2='" << x1 + 32 << "' y2='"
        << ly - 4 << "' stroke='" << colour << "' stroke-width='2'/><text x='" << x1 + 38 << "' y='"
        << ly << "'>" << s.name << "</text>\n";
}

}  // namespace

std::string logLogPlotSvg(const std::string& title, const std::string& xLabel,
                          const std::string& yLabel, const std::vector<PlotSeries>& series) {
    const Decades x = decadesOf(series, true), y = decadesOf(series, false);
    std::ostringstream svg;
    svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << kWidth << "' height='" << kHeight
        << "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' "
           "fill='white'/>\n";
    svg << "<text x='" << kLeft << "' y='24' font-size='15'>" << title << "</text>\n";
    drawAxes(svg, x, y);
    for (size_t i = 0; i < series.size(); ++i)
        drawSeries(svg, series[i], kColours[i % 6], int(i), x, y);
    svg << "<text x='" << (kLeft + kWidth - kRight) / 2 << "' y='" << kHeight - 20
        << "' text-anchor='middle'>" << xLabel << "</text>\n";
    svg << "<text transform='translate(20," << (kTop + kHeight - kBottom) / 2
        << ") rotate(-90)' text-anchor='middle'>" << yLabel << "</text>\n</svg>\n";
    return svg.str();
}

std::string machineDescription() {
    std::ifstream in("/proc/cpuinfo");
    std::string cpu = "unknown CPU";
    for (std::string line; std::getline(in, line);)
        if (line.rfind("model name", 0) == 0) {
            cpu = line.substr(line.find(':') + 2);
            break;
        }
    return cpu + ", " + std::to_string(std::thread::hardware_concurrency()) + " hardware threads";
}

std::vector<std::filesystem::path> exampleSceneFiles(const std::string& root) {
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(root + "/scenes"))
        if (e.path().extension() == ".txt") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

bool readTextFile(const std::string& path, std::string* text) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    if (!(in && s << in.rdbuf())) return false;
    *text = s.str();
    return true;
}

bool writeTextFile(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    return bool(out.flush());
}

}  // namespace mb
