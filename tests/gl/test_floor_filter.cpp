// test_floor_filter.cpp — the floor's checkers averaged over each sample's footprint
// (docs/shading-model.md §3): far squares blend to grey, so every example scene as written
// comes close to its supersampled converged render and the horizon holds still as the camera
// moves.
#include "golden.h"

#include "marchbox/gl/quality_preset.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace mb;

namespace {

constexpr int kWidth = 240, kHeight = 135;

// What more samples tend to: converged marching, aa 4 at twice the size, box-filtered down to
// 8x8 samples a pixel, as the render report's aliasing reference.
Image supersampledConverged(const Scene& scene) {
    Scene c = converged(scene);
    c.render.aa = 4;
    return boxDownsample(test::renderOrDie(c, {}, 2 * kWidth, 2 * kHeight), 2);
}

// An empty floor under a level camera 1 m up, 160x90 at fov 40: the horizon is the middle row,
// and the k-th row below it sees floor 247/(2k + 1) m away, through a pixel 33 m (row 1) to
// 1.7 m (row 8) deep: each spans one square or many.
Scene emptyFloor(float x, float z) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "scene version:1\ncamera pos:%g,1,%g target:%g,1,%g fov:40\n"
                  "render shadows:0 reflections:0\nlight dir:-0.3,-1,0.5\n",
                  x, z, x, z + 10.0f);
    return test::parseSceneOrDie(text);
}

// Mean |a − b| of the red channel over rows first..last of two pictures, in 0..255.
double meanRowDifference(const Image& a, const Image& b, int first, int last) {
    double sum = 0;
    for (int y = first; y <= last; ++y)
        for (int x = 0; x < a.width; ++x) sum += std::abs(a.pixel(x, y)[0] - b.pixel(x, y)[0]);
    return sum / double((last - first + 1) * a.width);
}

}  // namespace

class FloorFilter : public ::testing::TestWithParam<std::string> {};

// The bar, 31 dB at 240x135. Point-sampled checkers scored 24.1 (extremes.txt) to 29.1 dB on
// the scenes at aa 1, and extremes.txt's floor is most of its picture; filtered, the lowest is
// chair_topples' 31.4 dB and extremes.txt's 33.8 dB.
TEST_P(FloorFilter, AsWrittenIsWithin31dBOfItsSupersampledConvergedRender) {
    Scene scene = test::loadSceneOrDie("scenes/" + GetParam() + ".txt");
    double db = psnr(test::renderOrDie(scene, {}, kWidth, kHeight), supersampledConverged(scene));
    std::printf("[ measured ] %-13s %.1f dB\n", GetParam().c_str(), db);
    EXPECT_GE(db, 31.0) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Scenes, FloorFilter, ::testing::ValuesIn(test::sceneNames()),
                         [](const auto& info) { return info.param; });

// A step of 0.37 m forward and 0.23 m aside moves every far square by a fraction of its own
// size, so point samples flip between grey 0.80 and 0.35 (115 levels apart) at random: the
// rows changed by 20.4 levels on average. Filtered they change by 1.2.
TEST(FloorFilterHorizon, HoldsStillAsTheCameraMoves) {
    const int w = 160, h = 90, horizon = h / 2;
    Image before = test::renderOrDie(emptyFloor(0, 0), {}, w, h);
    Image after = test::renderOrDie(emptyFloor(0.23f, 0.37f), {}, w, h);
    double change = meanRowDifference(before, after, horizon + 1, horizon + 8);
    std::printf("[ measured ] far floor changes by %.2f levels\n", change);
    EXPECT_LT(change, 4.0);
}
