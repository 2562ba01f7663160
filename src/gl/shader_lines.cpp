// shader_lines.cpp — mapping a driver's log from assembled lines back to files.
#include "marchbox/gl/shader_lines.h"

#include <algorithm>
#include <regex>
#include <sstream>

namespace mb {

LineMap linesOf(const std::string& file, const std::string& text) {
    LineMap lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back({file, int(lines.size()) + 1});
    return lines;
}

LineMap withPrefix(const std::string& prefix, const LineMap& body) {
    LineMap lines = linesOf("<defines>", prefix);
    lines.insert(lines.end(), body.begin(), body.end());
    return lines;
}

// The location is source string 0 (the only one sent), then `:L` or `(L)`.
static std::string rewriteLine(const std::string& line, const LineMap& lines) {
    static const std::regex location(R"(^((?:ERROR|WARNING): )?0(?::(\d{1,9})|\((\d{1,9})\)))");
    std::smatch m;
    if (!std::regex_search(line, m, location)) return line;
    size_t n = std::stoul(m[2].matched ? m[2].str() : m[3].str());
    if (n < 1 || n > lines.size()) return line;
    const LineOrigin& o = lines[n - 1];
    return m[1].str() + o.file + ':' + std::to_string(o.line) + m.suffix().str();
}

std::string rewriteShaderLog(const std::string& log, const LineMap& lines) {
    std::string out;
    for (size_t at = 0; at < log.size();) {
        size_t end = std::min(log.find('\n', at), log.size());
        out += rewriteLine(log.substr(at, end - at), lines);
        if (end < log.size()) out += '\n';
        at = end + 1;
    }
    return out;
}

}  // namespace mb
