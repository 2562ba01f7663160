// golden.cpp — golden-image helpers shared by the GL tests.
#include "golden.h"

#include "marchbox/scene/scene_io.h"

#include <gtest/gtest.h>
#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace mb::test {

// Tolerance: llvmpipe draws every golden bit-exactly run after run (0 difference measured over
// repeated runs), so the slack is near zero: it absorbs a last-bit change in a transcendental
// at a silhouette, never a shading change (halving a specular term moves p99 by over 10).
// Another driver (a GPU through --backend egl) needs its own stated tolerance, not this one.
constexpr double kMaxMeanDiff = 0.05;  // mean |a-b| per channel, in 0..255
constexpr double kMaxP99Diff = 2.0;    // 99th percentile of the per-pixel max channel difference

std::string sourcePath(const std::string& relative) {
    return std::string(MARCHBOX_SOURCE_DIR) + "/" + relative;
}

std::string outputPath(const std::string& name) {
    std::filesystem::path dir = std::filesystem::path(MARCHBOX_BINARY_DIR) / "test-output";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

std::vector<std::string> sceneNames() {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(sourcePath("scenes")))
        if (e.path().extension() == ".txt") names.push_back(e.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

Scene loadSceneOrDie(const std::string& relative) {
    Scene scene;
    std::vector<std::string> errors;
    bool ok = loadScene(sourcePath(relative), &scene, &errors);
    EXPECT_TRUE(ok) << (errors.empty() ? "" : errors[0]);
    return scene;
}

Scene parseSceneOrDie(const std::string& text) {
    Scene s;
    std::vector<SceneError> errors;
    EXPECT_TRUE(parseScene(text, &s, &errors))
        << (errors.empty() ? "" : std::to_string(errors[0].line) + ": " + errors[0].message);
    return s;
}

Image renderOrDie(const Scene& scene, const RenderOptions& options, int width, int height) {
    Image img;
    std::string error;
    bool ok = renderOffscreen(scene, options, width, height, &img, &error);
    EXPECT_TRUE(ok) << error;
    return img;
}

void expectMatchesGolden(const Image& actual, const std::string& name) {
    std::string goldenPath = sourcePath("tests/golden/" + name + ".png"), error;
    const char* update = std::getenv("MARCHBOX_UPDATE_GOLDEN");
    if (update && std::string(update) == "1") {
        ASSERT_TRUE(savePng(goldenPath, actual, &error)) << error;
        return;
    }
    Image golden;
    ASSERT_TRUE(loadPng(goldenPath, &golden, &error))
        << error << " (MARCHBOX_UPDATE_GOLDEN=1 writes it)";
    ASSERT_EQ(golden.width, actual.width);
    ASSERT_EQ(golden.height, actual.height);
    ImageDiff d = diffImages(actual, golden);
    if (d.meanAbs <= kMaxMeanDiff && d.p99 <= kMaxP99Diff) return;
    savePng(outputPath(name + ".actual.png"), actual, &error);
    savePng(outputPath(name + ".diff.png"), d.visual, &error);
    ADD_FAILURE() << name << ": mean diff " << d.meanAbs << " (max " << kMaxMeanDiff << "), p99 "
                  << d.p99 << " (max " << kMaxP99Diff << "); wrote "
                  << outputPath(name + ".actual.png") << " and .diff.png";
}

bool interior(const Image& ids, const ReferenceImage& ref, int x, int row) {
    int id = ref.objectAt(x, row);
    uint64_t region = ref.regionAt(x, row);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            if (objectIdAt(ids, x + dx, row + dy) != id || ref.objectAt(x + dx, row + dy) != id ||
                ref.regionAt(x + dx, row + dy) != region)
                return false;
    return true;
}

}  // namespace mb::test
