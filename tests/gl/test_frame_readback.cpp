// test_frame_readback.cpp — frames of a sequence queued in the ring of pack buffers come back
// in the order they went in, each the bytes a frame read back at once has.
#include "golden.h"

#include "marchbox/gl/frame_readback.h"
#include "marchbox/gl/offscreen_context.h"

#include <gtest/gtest.h>

using namespace mb;

namespace {

// Frame k of a camera that steps sideways; odd frames are smaller, so a slot is reused at
// another size.
struct Shot {
    Scene scene;
    int width, height;
};

Shot shot(const Scene& base, int k) {
    Shot s{base, k % 2 ? 64 : 96, k % 2 ? 36 : 54};
    s.scene.camera.pos.x += 0.4f * float(k);
    return s;
}

}  // namespace

TEST(FrameReadback, FramesComeBackInOrderAsAFrameReadAtOnce) {
    OffscreenContext context;
    Renderer renderer;
    std::string error;
    ASSERT_TRUE(context.create(1, 1, &error) && renderer.init(&error)) << error;
    const Scene base = test::loadSceneOrDie("tests/scenes/motion.txt");
    const int frames = 8;  // more than the ring holds
    std::vector<Image> atOnce(frames);
    for (int k = 0; k < frames; ++k) {
        Shot s = shot(base, k);
        ASSERT_TRUE(
            renderFrame(renderer, s.scene, {}, s.width, s.height, &atOnce[size_t(k)], &error))
            << error;
    }
    FrameReadback ring(3);
    int expected = 0;
    auto takeOne = [&] {
        ReadFrame f;
        ASSERT_TRUE(ring.take(&f, &error)) << error;
        EXPECT_EQ(f.frame, expected);
        EXPECT_EQ(f.image.width, atOnce[size_t(expected)].width);
        EXPECT_TRUE(f.image.rgba == atOnce[size_t(expected)].rgba) << "frame " << expected;
        ++expected;
    };
    for (int k = 0; k < frames; ++k) {
        if (ring.full()) takeOne();
        Shot s = shot(base, k);
        ASSERT_TRUE(renderFrame(renderer, s.scene, {}, s.width, s.height, ring, k, &error))
            << error;
    }
    while (!ring.empty()) takeOne();
    EXPECT_EQ(expected, frames);
}
