// test_converged.cpp — every example scene, as written, is close to its converged render
// (4096 steps, epsilon 1e-5): no sky where floor should be, no silhouettes that move when
// epsilon shrinks.
#include "golden.h"

#include <gtest/gtest.h>
#include <cmath>
#include <filesystem>

using namespace mb;

namespace {

double psnr(const Image& a, const Image& b) {
    double se = 0;
    for (size_t i = 0; i < a.rgba.size(); ++i)
        if (i % 4 != 3) se += std::pow(double(a.rgba[i]) - double(b.rgba[i]), 2.0);
    double mse = se / (3.0 * a.width * a.height);
    return mse > 0 ? 10 * std::log10(255.0 * 255.0 / mse) : 99.0;
}

std::vector<std::string> sceneNames() {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(test::sourcePath("scenes")))
        if (e.path().extension() == ".txt") names.push_back(e.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace

class Converged : public ::testing::TestWithParam<std::string> {};

// The bar, 36 dB; measured at 240x135 the lowest is reflections' 37.6 dB. With the
// ground marched instead of met (the renderer before the compiler) default scored 32 dB.
TEST_P(Converged, AsWrittenIsWithin36dBOfConverged) {
    Scene scene = test::loadSceneOrDie("scenes/" + GetParam() + ".txt");
    Image asWritten = test::renderOrDie(scene, {}, 240, 135);
    scene.render.steps = 4096;
    scene.render.epsilon = 1e-5f;
    Image converged = test::renderOrDie(scene, {}, 240, 135);
    double db = psnr(asWritten, converged);
    std::printf("[ measured ] %-13s %.1f dB\n", GetParam().c_str(), db);
    EXPECT_GE(db, 36.0) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Scenes, Converged, ::testing::ValuesIn(sceneNames()),
                         [](const auto& info) { return info.param; });
