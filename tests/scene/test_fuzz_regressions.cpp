// test_fuzz_regressions.cpp — replays tests/fuzz/regressions/ (inputs that once broke a fuzz
// target, and hand-made hard cases) and the fuzz seeds through both fuzz targets' checks, so
// the normal g++ build keeps every fuzzer finding fixed without needing clang.
#include "marchbox/scene/scene_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>

using namespace mb;
namespace fs = std::filesystem;

namespace {

const fs::path kFuzzDir = fs::path(MARCHBOX_SOURCE_DIR) / "tests" / "fuzz";

std::string readBytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

std::vector<fs::path> filesIn(const fs::path& dir) {
    std::vector<fs::path> files;
    if (fs::is_directory(dir))
        for (const auto& e : fs::directory_iterator(dir))
            if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

// What fuzz_scene_parse asserts: success with no errors, or errors in line order within the
// text, each with a message. Then what fuzz_scene_roundtrip asserts for a success.
void expectSaneParse(const fs::path& file) {
    SCOPED_TRACE(file.string());
    const std::string text = readBytes(file);
    Scene scene;
    std::vector<SceneError> errors;
    bool ok = parseScene(text, &scene, &errors);
    EXPECT_EQ(ok, errors.empty());
    const int lines = int(std::count(text.begin(), text.end(), '\n')) + 1;
    int last = 1;
    for (const SceneError& e : errors) {
        EXPECT_GE(e.line, last) << e.message;
        EXPECT_LE(e.line, lines) << e.message;
        EXPECT_FALSE(e.message.empty());
        EXPECT_EQ(e.message.find('\n'), std::string::npos) << "an error is one line";
        last = e.line;
    }
    if (!ok) return;
    const std::string saved = formatScene(scene);
    Scene again;
    ASSERT_TRUE(parseScene(saved, &again, nullptr)) << saved;
    EXPECT_EQ(again, scene);
    EXPECT_EQ(formatScene(again), saved);
}

}  // namespace

TEST(FuzzRegressions, EveryRegressionInputParsesSanely) {
    std::vector<fs::path> files = filesIn(kFuzzDir / "regressions");
    ASSERT_FALSE(files.empty()) << "tests/fuzz/regressions/ is missing";
    for (const fs::path& f : files) expectSaneParse(f);
    std::cout << "[          ] " << files.size() << " regression inputs\n";
}

TEST(FuzzRegressions, EverySeedParsesSanely) {
    std::vector<fs::path> files = filesIn(kFuzzDir / "seeds");
    ASSERT_FALSE(files.empty()) << "tests/fuzz/seeds/ is missing";
    for (const fs::path& f : files) expectSaneParse(f);
}
