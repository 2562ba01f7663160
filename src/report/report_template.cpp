// report_template.cpp — reading a report's template and filling in its placeholders.
#include "report_template.h"

#include "report_plot.h"

#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

namespace mb {

bool readReportTemplate(const std::string& root, const std::string& file, std::string* text,
                        std::string* error) {
    const std::string path = root + "/src/report/templates/" + file;
    if (readTextFile(path, text)) return true;
    *error = "cannot read the report template " + path;
    return false;
}

bool fillTemplate(const std::string& text, const TemplateValues& values, std::string* out,
                  std::string* error) {
    std::string filled;
    std::set<std::string> used;
    size_t at = 0;
    for (size_t open; (open = text.find("{{", at)) != std::string::npos;) {
        const size_t close = text.find("}}", open + 2);
        if (close == std::string::npos) {
            *error = "a {{ with no }} in the template";
            return false;
        }
        const std::string name = text.substr(open + 2, close - open - 2);
        const auto value = values.find(name);
        if (value == values.end()) {
            *error = "no value for the template's {{" + name + "}}";
            return false;
        }
        filled += text.substr(at, open - at) + value->second;
        used.insert(name);
        at = close + 2;
    }
    for (const auto& [name, value] : values)
        if (!used.count(name)) {
            *error = "the template has no {{" + name + "}}";
            return false;
        }
    *out = filled + text.substr(at);
    return true;
}

bool writeReport(const std::string& path, const std::string& text, const TemplateValues& values,
                 std::string* error) {
    std::string filled, why;
    if (!fillTemplate(text, values, &filled, &why)) {
        *error = path.substr(path.find_last_of('/') + 1) + ": " + why;
        return false;
    }
    if (!writeTextFile(path, filled)) {
        *error = "cannot write " + path;
        return false;
    }
    return true;
}

std::string fmt(const char* format, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

}  // namespace mb
