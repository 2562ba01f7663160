// test_report_template.cpp — the reports' prose comes from src/report/templates/: placeholders
// are filled by name, and a template and its generator that drift apart say where.
#include "report_template.h"

#include <gtest/gtest.h>

using namespace mb;

namespace {

std::string filled(const std::string& text, const TemplateValues& values) {
    std::string out, error;
    EXPECT_TRUE(fillTemplate(text, values, &out, &error)) << error;
    return out;
}

std::string refusal(const std::string& text, const TemplateValues& values) {
    std::string out, error;
    EXPECT_FALSE(fillTemplate(text, values, &out, &error)) << out;
    return error;
}

}  // namespace

TEST(ReportTemplate, FillsEveryPlaceholderByName) {
    EXPECT_EQ(filled("at {{size}}, {{frames}} frames; {{size}} again\n",
                     {{"size", "480x270"}, {"frames", "9"}}),
              "at 480x270, 9 frames; 480x270 again\n");
    EXPECT_EQ(filled("no placeholders", {}), "no placeholders");
}

// A value is text, not more template: a table that happens to hold braces stays as it is.
TEST(ReportTemplate, DoesNotReadValuesForPlaceholders) {
    EXPECT_EQ(filled("{{table}}|{{b}}", {{"table", "{{b}}"}, {"b", "x"}}), "{{b}}|x");
}

TEST(ReportTemplate, RefusesATemplateAndValuesThatDisagree) {
    EXPECT_NE(refusal("{{size}} {{frames}}", {{"size", "1"}}).find("{{frames}}"),
              std::string::npos);
    EXPECT_NE(refusal("{{size}}", {{"size", "1"}, {"frames", "9"}}).find("{{frames}}"),
              std::string::npos);
    EXPECT_NE(refusal("{{size", {{"size", "1"}}).find("no }}"), std::string::npos);
}

// The generators read their templates before measuring anything; both are in the tree.
TEST(ReportTemplate, ReadsEachReportsTemplate) {
    for (const char* file : {"physics-report.md", "render-report.md"}) {
        std::string text, error;
        ASSERT_TRUE(readReportTemplate(MARCHBOX_SOURCE_DIR, file, &text, &error)) << error;
        EXPECT_EQ(text.rfind("# ", 0), 0u) << file << " starts with its title";
    }
    std::string text, error;
    EXPECT_FALSE(readReportTemplate(MARCHBOX_SOURCE_DIR, "no-such-report.md", &text, &error));
    EXPECT_NE(error.find("no-such-report.md"), std::string::npos) << error;
}
