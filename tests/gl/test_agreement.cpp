// test_agreement.cpp — the C++ SDF mirror and the shader agree on what each pixel sees.
#include "golden.h"

#include "marchbox/camera.h"
#include "marchbox/gl/gpu_scene.h"
#include "marchbox/sdf.h"

#include <gtest/gtest.h>

using namespace mb;

namespace {

constexpr int kWidth = 160, kHeight = 90;

int gpuObjectAt(const Image& img, int x, int row) {
    const uint8_t* p = img.pixel(x, row);
    return int(p[0]) + 256 * int(p[1]) - 2;  // MODE 6 writes id + 2: 0 miss, 1 ground
}

// Silhouette pixels may go either way between float pipelines; compare interiors only.
bool interior(const Image& img, int x, int row) {
    int id = gpuObjectAt(img, x, row);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            if (gpuObjectAt(img, x + dx, row + dy) != id) return false;
    return true;
}

}  // namespace

class Agreement : public ::testing::TestWithParam<const char*> {};

TEST_P(Agreement, CpuAndGpuHitTheSameObject) {
    Scene scene = test::loadSceneOrDie(std::string("scenes/") + GetParam() + ".txt");
    Image ids = test::renderOrDie(scene, test::options(RenderMode::ObjectId), kWidth, kHeight);
    ASSERT_EQ(ids.width, kWidth);
    SceneSdf sdf = makeSceneSdf(scene);
    CameraBasis basis = cameraBasis(scene.camera);
    float far = maxRayDistance(scene);
    int compared = 0, agreed = 0, objectPixels = 0;
    for (int row = 1; row < kHeight - 1; row += 3)
        for (int x = 1; x < kWidth - 1; x += 3) {
            if (!interior(ids, x, row)) continue;
            glm::vec2 pixel(x + 0.5f, kHeight - 1 - row + 0.5f);
            glm::vec3 dir = cameraRay(basis, pixel, glm::vec2(kWidth, kHeight));
            RayHit hit = castRay(sdf, basis.pos, dir, scene.render.steps, scene.render.epsilon, far);
            int gpu = gpuObjectAt(ids, x, row);
            ++compared;
            agreed += hit.object == gpu;
            objectPixels += gpu >= 0;
        }
    EXPECT_GT(objectPixels, 50) << "the sample must cover objects, not only floor and sky";
    EXPECT_GE(agreed, compared * 0.99) << agreed << " of " << compared << " sampled pixels agree";
}

INSTANTIATE_TEST_SUITE_P(Scenes, Agreement,
                         ::testing::Values("primitives", "csg", "default", "lights", "legacy", "pile"),
                         [](const auto& info) { return std::string(info.param); });
