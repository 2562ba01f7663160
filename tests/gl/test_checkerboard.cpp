// test_checkerboard.cpp — draft's checkerboard: the fill (shaders/checkerboard.frag) on
// synthetic pictures, half the pixels given, packed as the march packs them; tiles that pack
// their own columns; object ids left whole.
#include "golden.h"

#include "marchbox/gl/checkerboard.h"
#include "marchbox/gl/offscreen_context.h"
#include "marchbox/gl/renderer.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>

using namespace mb;

namespace {

constexpr int kW = 16, kH = 12;
using Picture = std::function<float(int x, int y)>;  // grey, 0..1; y from the bottom

// Packs the pixels with x + y even as the march does, fills in the rest and reads it back.
// A packed column past the right border holds picture(w, y), as the march shades it there.
Image fill(const Picture& picture, int w = kW, int h = kH) {
    std::string error;
    OffscreenContext context;
    EXPECT_TRUE(context.create(1, 1, &error)) << error;
    ScreenQuad quad;
    EXPECT_TRUE(quad.init(&error)) << error;
    const int half = CheckerboardFill::packedWidth(w);
    std::vector<float> packed;
    for (int y = 0; y < h; ++y)
        for (int i = 0; i < half; ++i) {
            float g = picture(2 * i + (y & 1), y);
            packed.insert(packed.end(), {g, g, g, 1.0f});
        }
    ColorTarget in, out;
    EXPECT_TRUE(in.resize(half, h, GL_RGBA32F) && out.resize(w, h, GL_RGBA8));
    in.bindTexture(0);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, half, h, 0, GL_RGBA, GL_FLOAT,
                 packed.data());  // re-specified with data: resize allocated none
    out.bind();
    glViewport(0, 0, w, h);
    CheckerboardFill checkerboard;
    EXPECT_TRUE(checkerboard.prepare(&error)) << error;
    checkerboard.draw(in, w, h, quad);
    return readFramebuffer(w, h);
}

// The largest difference from the picture, in 1/255 steps, over the pixels `margin` or more
// from the border.
int largestError(const Picture& picture, int margin = 0) {
    Image image = fill(picture);
    int largest = 0;
    for (int y = margin; y < kH - margin; ++y)
        for (int x = margin; x < kW - margin; ++x) {
            int expected = int(picture(x, y) * 255.0f + 0.5f);
            largest = std::max(largest, std::abs(int(image.pixel(x, kH - 1 - y)[0]) - expected));
        }
    return largest;
}

}  // namespace

// Across an edge the two neighbours differ; along it they agree, and the fill takes theirs.
// Where the edge meets the border only the pair across is whole: those pixels are left out.
TEST(Checkerboard, EdgesComeBackExactly) {
    EXPECT_EQ(largestError([](int x, int) { return x < 7 ? 40 / 255.0f : 220 / 255.0f; }, 1), 0)
        << "vertical";
    EXPECT_EQ(largestError([](int, int y) { return y < 5 ? 200 / 255.0f : 30 / 255.0f; }, 1), 0)
        << "horizontal";
}

// Inside, either pair's mean is exact on a ramp; on the border the pair inside is taken, and in
// the corners the mean of the two neighbours there is half a ramp step off.
TEST(Checkerboard, ARampComesBackWithinOneStep) {
    EXPECT_LE(largestError([](int x, int y) { return float(6 * x + 4 * y) / 255.0f; }), 1);
}

// A tile's packed columns start at half its x: the picture does not depend on the tiling.
TEST(Checkerboard, TilesPackTheirOwnColumns) {
    Scene scene = test::loadSceneOrDie("scenes/primitives.txt");
    scene.render.aa = 2;
    RenderOptions o;
    o.quality.checkerboard = true;
    std::string error;
    OffscreenContext context;
    ASSERT_TRUE(context.create(1, 1, &error)) << error;
    Renderer r;
    ASSERT_TRUE(r.init(&error) && r.setScene(scene, o, &error)) << error;
    auto render = [&](int tile) {
        TiledRender tiles(r, 600, 150, tile);
        EXPECT_TRUE(tiles.start(&error)) << error;
        while (!tiles.done()) tiles.step();
        return tiles.finish();
    };
    Image whole = render(1024), tiled = render(64);
    EXPECT_EQ(whole.rgba, tiled.rgba);
    EXPECT_NE(whole.rgba, test::renderOrDie(scene, {}, 600, 150).rgba);  // it is on
}

// Odd sizes and pictures one pixel wide or high: every pixel is filled from pixels inside the
// picture, never from the one past the right border that the march shades to fill a column
// (a picture one pixel wide once took it into its last row's corner) nor from past the packed
// columns. Grey inside and white outside, so any mean that reads outside shows.
TEST(Checkerboard, OddSizesReadOnlyPixelsInside) {
    for (auto [w, h] : {std::pair{15, 11}, {1, 8}, {1, 7}, {8, 1}, {7, 1}, {3, 2}, {1, 1}}) {
        Image image = fill([w](int x, int) { return x < w ? 100 / 255.0f : 1.0f; }, w, h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                EXPECT_EQ(image.pixel(x, y)[0], 100) << w << "x" << h << " at " << x << "," << y;
    }
}

// A frame ends as it began: a setScene that turns the checkerboard off before endFrame (the
// editor's program swapped mid-frame) still fills the half the frame shaded, rather than
// resolving a full-size target nothing drew.
// A setScene between beginFrame and endFrame (an edit while a tiled frame is under way) leaves
// the frame as it began: its layout, and how it is resolved.
TEST(Checkerboard, AFrameKeepsTheLayoutItBeganWith) {
    Scene scene = test::loadSceneOrDie("scenes/csg.txt");
    RenderOptions draft;
    draft.quality.checkerboard = true;
    RenderOptions smoothed = draft;
    smoothed.post = PostMode::Fxaa;
    std::string error;
    OffscreenContext context;
    ASSERT_TRUE(context.create(1, 1, &error)) << error;
    Renderer r;
    ColorTarget target;
    ASSERT_TRUE(r.init(&error) && target.resize(kW * 8, kH * 8, GL_RGBA8)) << error;
    target.bind();
    for (const RenderOptions& changed : {RenderOptions{}, smoothed}) {
        ASSERT_TRUE(r.setScene(scene, draft, &error)) << error;
        r.draw(kW * 8, kH * 8);
        Image whole = readFramebuffer(kW * 8, kH * 8);
        ASSERT_TRUE(r.beginFrame(kW * 8, kH * 8, false, &error)) << error;
        r.drawRegion(0, 0, kW * 8, kH * 8);
        ASSERT_TRUE(r.setScene(scene, changed, &error)) << error;
        r.endFrame();
        EXPECT_EQ(readFramebuffer(kW * 8, kH * 8).rgba, whole.rgba) << "post " << int(changed.post);
    }
}

// Ids do not average: the id view shades every pixel whatever the quality asks.
TEST(Checkerboard, ObjectIdsStayWhole) {
    Scene scene = test::loadSceneOrDie("scenes/csg.txt");
    RenderOptions o = test::options(RenderMode::ObjectId);
    Image every = test::renderOrDie(scene, o);
    o.quality.checkerboard = true;
    EXPECT_EQ(test::renderOrDie(scene, o).rgba, every.rgba);
}
