// test_golden.cpp — every scene in scenes/ rendered off-screen and compared with its PNG.
#include "golden.h"

#include <gtest/gtest.h>

using namespace mb;

class Golden : public ::testing::TestWithParam<const char*> {};

TEST_P(Golden, MatchesCommittedImage) {
    std::string name = GetParam();
    Scene scene = test::loadSceneOrDie("scenes/" + name + ".txt");
    test::expectMatchesGolden(test::renderOrDie(scene), name);
}

INSTANTIATE_TEST_SUITE_P(Scenes, Golden,
                         ::testing::Values("default", "primitives", "csg", "shadows_hard",
                                           "shadows_soft", "reflections", "lights", "legacy",
                                           "extremes", "inside", "pile", "fog", "ao_aa", "sun",
                                           "fog_sun", "mixed_pile", "box_stack", "dominoes",
                                           "ring_on_peg", "vocabulary"),
                         [](const auto& info) { return std::string(info.param); });

// FXAA is a view setting, not a scene key: its golden is the default scene with the post pass.
TEST(GoldenPost, FxaaOnTheDefaultScene) {
    RenderOptions o;
    o.post = PostMode::Fxaa;
    test::expectMatchesGolden(test::renderOrDie(test::loadSceneOrDie("scenes/default.txt"), o),
                              "default_fxaa");
}
