// test_progressive.cpp — the editor's view refines a frame while showing it: samples added in
// bands as a running mean end where the one-go supersampled render does; a renderer sharing
// the context with another draws its own scene once it binds its buffers again.
#include "golden.h"

#include "marchbox/gl/offscreen_context.h"

#include <gtest/gtest.h>

#include <cstdlib>

using namespace mb;

namespace {

constexpr int kW = 240, kH = 135;

struct Context {
    OffscreenContext context;
    std::string error;
    void start() { ASSERT_TRUE(context.create(1, 1, &error)) << error; }
};

// Mean and largest absolute difference per channel, in 1/255 steps; how many channels differ
// by more than one step.
void compare(const Image& a, const Image& b, double* mean, int* largest, int* overOne = nullptr) {
    ASSERT_EQ(a.rgba.size(), b.rgba.size());
    long sum = 0;
    *largest = 0;
    int over = 0;
    for (size_t i = 0; i < a.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        int d = std::abs(int(a.rgba[i]) - int(b.rgba[i]));
        sum += d;
        *largest = std::max(*largest, d);
        over += d > 1;
    }
    *mean = double(sum) / double(a.rgba.size() / 4 * 3);
    if (overOne) *overOne = over;
}

Image read(const ColorTarget& target) {
    target.bind();
    return readFramebuffer(target.width(), target.height());
}

}  // namespace

// With the checkerboard (the editor at draft quality) the samples go to the half-width target
// and the seed is squeezed into it.
class Progressive : public ::testing::TestWithParam<bool> {};

TEST_P(Progressive, BandsOfSamplesEndWhereTheSupersampledRenderDoes) {
    Scene s = test::loadSceneOrDie("scenes/primitives.txt");
    s.render.aa = 2;
    RenderOptions o;
    o.quality.checkerboard = GetParam();
    Image reference = test::renderOrDie(s, o, kW, kH);  // TiledRender: all four samples at once

    Context c;
    ASSERT_NO_FATAL_FAILURE(c.start());
    Renderer r;
    ASSERT_TRUE(r.init(&c.error) && r.setScene(s, o, &c.error)) << c.error;
    ColorTarget seed, shown;
    ASSERT_TRUE(seed.resize(kW / 4, kH / 4, GL_RGBA8) && shown.resize(kW, kH, GL_RGBA8));
    seed.bind();
    glClearColor(0, 1, 0, 1);  // a green preview: any pixel no sample reaches stays green
    glClear(GL_COLOR_BUFFER_BIT);

    ASSERT_TRUE(r.beginFrame(kW, kH, true, &c.error)) << c.error;
    r.seedFrame(seed);
    const glm::vec2 grid[4] = {{0.25f, 0.25f}, {0.75f, 0.25f}, {0.25f, 0.75f}, {0.75f, 0.75f}};
    const int bands[][2] = {{100, 35}, {40, 60}, {0, 40}};  // y, rows: top down, uneven
    for (int k = 0; k < 4; ++k)
        for (const auto& b : bands) {
            r.drawSample(0, b[0], kW, b[1], grid[k], 1.0f / float(k + 1));
            if (k == 0 && b[0] == 100) {  // one band in: below it the preview still shows
                r.resolveFrame(shown, 0, 0, kW, kH);
                Image partial = read(shown);
                const uint8_t* below = partial.pixel(kW / 2, kH - 20);
                EXPECT_TRUE(below[0] == 0 && below[1] == 255 && below[2] == 0) << int(below[1]);
                r.resumeFrame();
            }
        }
    r.resolveFrame(shown, 0, 0, kW, kH);
    double mean = 0;
    int largest = 0, overOne = 0;
    ASSERT_NO_FATAL_FAILURE(compare(read(shown), reference, &mean, &largest, &overOne));
    // Half-float sums against half-float running means: each rounds by up to 2^-11 a step,
    // far below one 8-bit step, so only a pixel on a rounding boundary may differ, by one. With
    // the checkerboard such a rounding may also flip a near tie between the fill's two pairs:
    // a handful of filled-in pixels then take the other pair's mean (2 channels measured).
    EXPECT_LE(mean, 0.05) << "largest " << largest;
    EXPECT_LE(overOne, GetParam() ? 12 : 0) << "largest " << largest;
}

INSTANTIATE_TEST_SUITE_P(Checkerboard, Progressive, ::testing::Bool(), [](const auto& info) {
    return info.param ? "checkerboard" : "every_pixel";
});

TEST(Progressive, ARendererBindsItsOwnSceneAgainAfterAnother) {
    Scene red = test::loadSceneOrDie("scenes/primitives.txt"), blue = red;
    for (Material& m : blue.materials) m.color = {0.1f, 0.2f, 0.9f};
    Image reference = test::renderOrDie(red, {}, kW, kH);

    Context c;
    ASSERT_NO_FATAL_FAILURE(c.start());
    Renderer window, dialog;  // the editor's view and File > Render...'s
    ASSERT_TRUE(window.init(&c.error) && window.setScene(red, {}, &c.error)) << c.error;
    ASSERT_TRUE(dialog.init(&c.error) && dialog.setScene(blue, {}, &c.error)) << c.error;
    ColorTarget target;
    ASSERT_TRUE(target.resize(kW, kH, GL_RGBA8));
    target.bind();
    window.rebind();
    window.draw(kW, kH);
    double mean = 0;
    int largest = 0;
    ASSERT_NO_FATAL_FAILURE(compare(read(target), reference, &mean, &largest));
    EXPECT_LE(mean, 0.05) << "the window drew the dialog's materials; largest " << largest;
}
