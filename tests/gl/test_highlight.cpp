// test_highlight.cpp — the editor's selection: an orange ring just outside the selected object,
// whose own pixels keep the colour they have unselected.
#include "golden.h"

#include "marchbox/gl/offscreen_context.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

using namespace mb;

namespace {

constexpr int kW = 320, kH = 180;

// Draws `s` with object `selected` outlined (-1: none), the way the editor's view does.
Image drawSelected(const Scene& s, int selected, RenderMode mode = RenderMode::Shaded) {
    OffscreenContext context;
    Renderer r;
    ColorTarget target;
    std::string error;
    RenderOptions options = test::options(mode);
    options.outline = true;  // as the editor draws
    EXPECT_TRUE(context.create(1, 1, &error) && r.init(&error) && r.setScene(s, options, &error))
        << error;
    EXPECT_TRUE(target.resize(kW, kH, GL_RGBA8));
    target.bind();
    glUseProgram(r.program()->id());
    glUniform1i(r.program()->uniform("uHighlight"), selected + 1);
    r.draw(kW, kH);
    return readFramebuffer(kW, kH);
}

// Each pixel's distance in 4-neighbour steps to the nearest pixel whose ray hits `object`
// (from the object-id view), capped at kFar.
constexpr int kFar = 1000;
std::vector<int> stepsToObject(const Image& ids, int object) {
    std::vector<int> d(size_t(kW) * kH, kFar);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            if (objectIdAt(ids, x, y) == object) d[size_t(y) * kW + size_t(x)] = 0;
    for (int pass = 0; pass < 2; ++pass)  // two sweeps give the exact city-block distance
        for (int k = 0; k < kW * kH; ++k) {
            int i = pass ? kW * kH - 1 - k : k, x = i % kW, dx = pass ? 1 : -1,
                dy = pass ? kW : -kW;
            if (x + dx >= 0 && x + dx < kW)
                d[size_t(i)] = std::min(d[size_t(i)], d[size_t(i + dx)] + 1);
            if (i + dy >= 0 && i + dy < kW * kH)
                d[size_t(i)] = std::min(d[size_t(i)], d[size_t(i + dy)] + 1);
        }
    return d;
}

int largestDifference(const uint8_t* a, const uint8_t* b) {
    return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

}  // namespace

TEST(Highlight, TheSelectionIsAnOrangeRingAndTheObjectKeepsItsColour) {
    Scene s = test::loadSceneOrDie("scenes/primitives.txt");
    s.render.aa = 1;         // one ray a pixel: each pixel is on the object or off it
    const int selected = 1;  // the green box: a tint made it look olive
    std::vector<int> steps = stepsToObject(drawSelected(s, -1, RenderMode::ObjectId), selected);
    Image plain = drawSelected(s, -1), outlined = drawSelected(s, selected);

    int own = 0, ownChanged = 0, ring = 0, ringOrange = 0, far = 0, farChanged = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const uint8_t *a = plain.pixel(x, y), *b = outlined.pixel(x, y);
            const int d = steps[size_t(y) * kW + size_t(x)];
            if (d == 0) own++, ownChanged += largestDifference(a, b) > 0;
            // Beside the object its rays pass within about a pixel of it, inside the 2-pixel
            // ring; kOutlineColor is (255, 153, 25.5) in 8 bits, rounded either way.
            const uint8_t orange[3] = {255, 153, 25};
            if (d == 1) ring++, ringOrange += largestDifference(b, orange) <= 1;
            // Five steps are at least 3.5 pixels away: past the ring's 2.
            if (d >= 5) far++, farChanged += largestDifference(a, b) > 0;
        }
    ASSERT_GT(own, 1000) << "the box must be in view";
    EXPECT_EQ(ownChanged, 0) << "the selected object's own pixels must keep their colour";
    EXPECT_GE(ringOrange, ring * 95 / 100)
        << ringOrange << " of the " << ring << " pixels beside the box are orange";
    EXPECT_EQ(farChanged, 0) << "pixels away from the box must not change";
}
