// test_bounded_march.cpp — rays meet the ground analytically and march only where objects can
// be, so the picture does not depend on how many steps open floor would have needed.
#include "golden.h"

#include <gtest/gtest.h>

using namespace mb;

namespace {

int countDifferentIds(const Image& a, const Image& b) {
    int n = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            n += a.pixel(x, y)[0] != b.pixel(x, y)[0] || a.pixel(x, y)[1] != b.pixel(x, y)[1];
    return n;
}

}  // namespace

// Marched, the floor near the horizon needs hundreds of steps and showed sky with too few.
TEST(BoundedMarch, TheHorizonShowsFloorWithFewSteps) {
    Scene s = test::loadSceneOrDie("scenes/default.txt");
    s.objects.clear();  // open floor to the horizon
    s.render.steps = 4;
    Image few = test::renderOrDie(s, test::options(RenderMode::ObjectId), 160, 90);
    s.render.steps = 4096;
    Image many = test::renderOrDie(s, test::options(RenderMode::ObjectId), 160, 90);
    EXPECT_EQ(countDifferentIds(few, many), 0);
    const uint8_t* belowHorizon = few.pixel(80, 45);  // the camera looks down: floor there
    EXPECT_EQ(int(belowHorizon[0]), 1) << "id view: 1 is the ground, 0 the sky";
}

// Steps spent only inside the objects' box: the same scene with its objects far apart takes
// no more steps per ray over the empty space between them and the camera.
TEST(BoundedMarch, StepsAreSpentWhereObjectsAre) {
    Scene s = test::loadSceneOrDie("scenes/default.txt");
    s.render.steps = 64;
    Image ids64 = test::renderOrDie(s, test::options(RenderMode::ObjectId), 160, 90);
    s.render.steps = 4096;
    Image ids4096 = test::renderOrDie(s, test::options(RenderMode::ObjectId), 160, 90);
    EXPECT_LE(countDifferentIds(ids64, ids4096), 160 * 90 / 200)
        << "64 steps converge but for a few grazing silhouettes";
}
