// test_features.cpp — each picture feature on against off, measured in the pixels.
#include "golden.h"

#include "marchbox/scene/camera.h"
#include "marchbox/gl/gpu_scene.h"
#include "marchbox/scene/sdf.h"

#include <gtest/gtest.h>
#include <cmath>

using namespace mb;
using glm::vec3;

namespace {

constexpr int kW = 240, kH = 135;

double luma(const Image& img, int x, int row) {
    const uint8_t* p = img.pixel(x, row);
    return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
}

double rowsStddev(const Image& img, int row0, int row1) {
    double sum = 0, sq = 0;
    int n = 0;
    for (int row = row0; row < row1; ++row)
        for (int x = 0; x < img.width; ++x, ++n) {
            double l = luma(img, x, row);
            sum += l, sq += l * l;
        }
    double mean = sum / n;
    return std::sqrt(std::max(0.0, sq / n - mean * mean));
}

// Image column and row of a world point, as the camera projects it.
glm::ivec2 project(const Camera& c, vec3 p, int w, int h) {
    CameraBasis b = cameraBasis(c);
    vec3 d = p - b.pos;
    float t = glm::dot(d, b.forward);
    float u = glm::dot(d, b.right) / glm::dot(b.right, b.right) / t;
    float v = glm::dot(d, b.up) / glm::dot(b.up, b.up) / t;
    return {int((u * h + w) * 0.5f), h - 1 - int((v * h + h) * 0.5f)};
}

Scene floorScene() {
    Scene s;
    s.materials.push_back({});
    s.camera = Camera{{0, 1.5f, -6}, {0, 1, 4}, 50};
    s.render.shadows = 0;
    s.render.reflections = 0;
    s.lights.push_back(Light{true, {0.2f, -1, 0.5f}, {1, 1, 1}, 1});
    return s;
}

// Mean squared difference of neighbouring pixels: stair-stepped edges jump by the full
// contrast every few rows, supersampled ones change a little in every row.
double gradientEnergy(const Image& img) {
    double sum = 0;
    for (int row = 0; row < img.height - 1; ++row)
        for (int x = 0; x < img.width - 1; ++x)
            sum += std::pow(luma(img, x + 1, row) - luma(img, x, row), 2) +
                   std::pow(luma(img, x, row + 1) - luma(img, x, row), 2);
    return sum / ((img.width - 1.0) * (img.height - 1.0));
}

}  // namespace

TEST(Features, FogLowersFarContrastAndKeepsNearContrast) {
    Scene clear = floorScene(), foggy = floorScene();
    foggy.render.fog = 0.04f;
    Image a = test::renderOrDie(clear, {}, kW, kH), b = test::renderOrDie(foggy, {}, kW, kH);
    int far = project(clear.camera, vec3(0, 0, 40), kW, kH).y;
    double farClear = rowsStddev(a, far - 3, far + 3), farFog = rowsStddev(b, far - 3, far + 3);
    double nearClear = rowsStddev(a, kH - 15, kH), nearFog = rowsStddev(b, kH - 15, kH);
    // exp²: at 40 m, exp(-(0.04·40)²) = 0.08 of the contrast is left; at 3 m, 0.99.
    EXPECT_LT(farFog, 0.3 * farClear) << farFog << " vs " << farClear;
    EXPECT_GT(nearFog, 0.85 * nearClear) << nearFog << " vs " << nearClear;
}

TEST(Features, SupersamplingAndFxaaSmoothSilhouettes) {
    Scene s = floorScene();
    s.world.ground = false;  // a slanted box edge against the plain sky
    Object box;
    box.type = ShapeType::Box;
    box.pos = {0, 1, 0};
    box.size = {0.8f, 0.8f, 0.8f};
    box.rot = {0, 0, 12};
    s.objects.push_back(box);
    Image plain = test::renderOrDie(s, {}, kW, kH);
    s.render.aa = 4;
    Image aa = test::renderOrDie(s, {}, kW, kH);
    s.render.aa = 1;
    RenderOptions fxaa;
    fxaa.post = PostMode::Fxaa;
    Image smoothed = test::renderOrDie(s, fxaa, kW, kH);
    double e0 = gradientEnergy(plain), e1 = gradientEnergy(aa), e2 = gradientEnergy(smoothed);
    EXPECT_LT(e1, 0.6 * e0) << "4x4 supersampling: " << e1 << " vs " << e0;
    EXPECT_LT(e2, 0.8 * e0) << "FXAA: " << e2 << " vs " << e0;
}

TEST(Features, AmbientOcclusionDarkensTheContactNotTheOpenFloor) {
    Scene s = floorScene();
    s.camera = Camera{{0, 2.2f, -4}, {0, 0.3f, 0}, 45};
    Object ball;
    ball.pos = {0, 0.5f, 0};
    s.objects.push_back(ball);
    Image off = test::renderOrDie(s, {}, kW, kH);
    s.render.ao = true;
    Image on = test::renderOrDie(s, {}, kW, kH);
    SceneSdf sdf = makeSceneSdf(s);
    CameraBasis b = cameraBasis(s.camera);
    double darkestContact = 1, darkestOpen = 1;
    for (int row = 0; row < kH; ++row)
        for (int x = 0; x < kW; ++x) {
            vec3 dir = cameraRay(b, {x + 0.5f, kH - 1 - row + 0.5f}, {kW, kH});
            RayHit hit = castRay(sdf, b.pos, dir, 256, 1e-3f, 100);
            if (hit.object != kHitGround) continue;
            vec3 p = b.pos + dir * hit.t;
            float fromAxis = glm::length(glm::vec2(p.x, p.z));
            double ratio = luma(on, x, row) / std::max(1.0, luma(off, x, row));
            if (fromAxis < 0.45f) darkestContact = std::min(darkestContact, ratio);
            if (fromAxis > 2.0f) darkestOpen = std::min(darkestOpen, ratio);
        }
    // IQ's AO samples 0.01..0.13 m along the normal: only floor under the ball sees occluders.
    EXPECT_LT(darkestContact, 0.8) << "the floor beside the ball's base";
    EXPECT_GT(darkestOpen, 0.98) << "open floor, over 2 m from the ball";
}

TEST(Features, SoftShadowsWidenTheShadowEdge) {
    Scene s = test::loadSceneOrDie("scenes/shadows_hard.txt");
    auto penumbra = [](const Image& img) {
        int n = 0;
        for (int row = 0; row < img.height; ++row)
            for (int x = 0; x < img.width; ++x)
                n += luma(img, x, row) > 20 && luma(img, x, row) < 235;
        return n;
    };
    Image hard = test::renderOrDie(s, test::options(RenderMode::Shadow), kW, kH);
    s.render.shadows = 2;
    Image soft = test::renderOrDie(s, test::options(RenderMode::Shadow), kW, kH);
    int h = penumbra(hard), p = penumbra(soft);
    EXPECT_GT(p, 300) << "soft shadows have penumbrae";
    EXPECT_GT(p, 4 * h) << "hard: " << h << " partly lit pixels, soft: " << p;
}

TEST(Features, NormalViewIsTheNormalTimesHalfPlusHalf) {
    Scene s = test::loadSceneOrDie("scenes/primitives.txt");
    Image img = test::renderOrDie(s, test::options(RenderMode::Normals), kW, kH);
    SceneSdf sdf = makeSceneSdf(s);
    CameraBasis b = cameraBasis(s.camera);
    int checked = 0, close = 0;
    for (int row = 2; row < kH - 2; row += 3)
        for (int x = 2; x < kW - 2; x += 3) {
            vec3 dir = cameraRay(b, {x + 0.5f, kH - 1 - row + 0.5f}, {kW, kH});
            RayHit hit =
                castRay(sdf, b.pos, dir, s.render.steps, s.render.epsilon, maxRayDistance(s));
            if (!hit.hit) continue;
            vec3 expected = sceneNormal(sdf, b.pos + dir * hit.t) * 0.5f + 0.5f;
            const uint8_t* p = img.pixel(x, row);
            vec3 got(p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f);
            ++checked;
            close += glm::length(got - expected) < 0.03f;
        }
    ASSERT_GT(checked, 500);
    EXPECT_GE(close, 0.95 * checked) << close << " of " << checked << " within 0.03";
}

// A shadow ray ends at its point light: an object beyond the light, however large, casts no
// shadow towards it. Both shadow kinds, since each bounds its own march.
TEST(Features, ObjectsBeyondAPointLightCastNoShadow) {
    Scene s = floorScene();
    s.lights = {Light{false, {0, 2, 2}, {1, 1, 1}, 1}};
    s.camera = Camera{{0, 3.5f, 1.9f}, {0, 0, 2}, 50};  // looking down, under the roof
    for (int kind : {1, 2}) {
        s.render.shadows = kind;
        s.objects.clear();
        Image open = test::renderOrDie(s, test::options(RenderMode::Shaded), kW, kH);
        Object roof;  // a slab above the light, wider than all the floor in view
        roof.type = ShapeType::Box;
        roof.pos = {0, 5, 2};
        roof.size = {30, 0.5f, 30};
        s.objects.push_back(roof);
        Image roofed = test::renderOrDie(s, test::options(RenderMode::Shaded), kW, kH);
        ImageDiff d = diffImages(open, roofed);
        EXPECT_EQ(d.maxAbs, 0.0) << "shadows " << kind
                                 << ": the roof above the light darkened the floor";
    }
}
