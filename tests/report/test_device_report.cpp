// test_device_report.cpp — `report render --backend egl` replaces the device's section of the
// render report and nothing else; `report render` keeps the section it finds.
#include "device_report.h"

#include <gtest/gtest.h>

using namespace mb;

namespace {

const std::string kBefore = "# Render report\n\nOSMesa's figures.\n";

std::string section(const std::string& device) {
    // deviceSection's shape without its measurements: the markers around a heading.
    const std::string placeholder = keptDeviceSection("");
    const size_t heading = placeholder.find("## ");
    return placeholder.substr(0, heading) + "## On " + device + "\n" +
           placeholder.substr(placeholder.find("<!-- end"));
}

}  // namespace

TEST(DeviceSection, AReportWithoutOneSaysItWasNotMeasured) {
    const std::string kept = keptDeviceSection(kBefore);
    EXPECT_NE(kept.find("Not measured here"), std::string::npos);
    EXPECT_NE(kept.find("--backend egl"), std::string::npos);
}

TEST(DeviceSection, IsAddedOnceThenReplacedAloneAndKept) {
    const std::string once = withDeviceSection(kBefore, section("GPU A"));
    EXPECT_EQ(once.rfind(kBefore, 0), 0u) << "the report before the section changed";
    const std::string twice = withDeviceSection(once + "Later prose.\n", section("GPU B"));
    EXPECT_EQ(twice.find("GPU A"), std::string::npos);
    EXPECT_NE(twice.find("## On GPU B\n"), std::string::npos);
    EXPECT_NE(twice.find("Later prose.\n"), std::string::npos);
    EXPECT_EQ(twice.rfind(kBefore, 0), 0u);
    EXPECT_EQ(keptDeviceSection(twice), section("GPU B"));
    // An OSMesa run writes the section it found back in place: the same text.
    EXPECT_EQ(withDeviceSection(twice, keptDeviceSection(twice)), twice);
}
