// report_template.h — a report's prose lives in src/report/templates/*.md as markdown with
// {{name}} placeholders; its generator measures, then fills each placeholder by name.
#pragma once

#include <map>
#include <string>

namespace mb {

using TemplateValues = std::map<std::string, std::string>;

// Reads src/report/templates/`file` under the source tree `root`; false with *error if it cannot.
bool readReportTemplate(const std::string& root, const std::string& file, std::string* text,
                        std::string* error);

// `text` with every {{name}} replaced by values[name]; the values are not read for placeholders
// again. False, with *error, where the two have drifted apart: a placeholder with no value, a
// value no placeholder asks for, or a "{{" with no "}}".
bool fillTemplate(const std::string& text, const TemplateValues& values, std::string* out,
                  std::string* error);

// One number through a printf format, for a table cell or a sentence: fmt("%.2fx", 1.234).
std::string fmt(const char* format, double v);

// fillTemplate, then the result written to `path`; false with *error ("NAME: why") if either fails.
bool writeReport(const std::string& path, const std::string& text, const TemplateValues& values,
                 std::string* error);

}  // namespace mb
