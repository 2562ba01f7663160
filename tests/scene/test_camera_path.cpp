// test_camera_path.cpp — the camera path against closed forms: it passes through every key,
// holds outside them, reproduces a path quadratic in t, and has no kink at any key.
#include "marchbox/scene/camera_path.h"

#include <gtest/gtest.h>
#include <cmath>

using namespace mb;
using glm::vec3;

namespace {

Keyframe key(float t, vec3 pos, vec3 target, float fov) {
    Keyframe k;
    k.t = t, k.pos = pos, k.target = target, k.fov = fov;
    return k;
}

// Unevenly spaced keys that turn back and forth: a kink anywhere would show.
std::vector<Keyframe> zigzag() {
    return {key(0.5f, vec3(0.5f, 2, -6), vec3(0, 1, 0.2f), 52),
            key(1.0f, vec3(3, 2.5f, -4), vec3(0.5f, 1, 0), 40),
            key(2.5f, vec3(-2, 3, -5), vec3(0, 0.5f, 1), 60),
            key(3.0f, vec3(1, 1, -3), vec3(-1, 1, 0), 45),
            key(4.5f, vec3(0, 4, -7), vec3(0, 1, 0.5f), 55)};
}

// The seven numbers the path moves, as one list.
std::vector<float> numbers(const Camera& c) {
    return {c.pos.x, c.pos.y, c.pos.z, c.target.x, c.target.y, c.target.z, c.fov};
}
std::vector<float> numbers(const Keyframe& k) { return numbers(Camera{k.pos, k.target, k.fov}); }

void expectSame(const Camera& a, const Keyframe& k) {
    EXPECT_EQ(a.pos, k.pos);
    EXPECT_EQ(a.target, k.target);
    EXPECT_EQ(a.fov, k.fov);
}

}  // namespace

TEST(CameraPath, NoKeysIsTheCameraRecord) {
    Camera rest{vec3(1, 2, 3), vec3(4, 5, 6), 33};
    for (double t : {0.0, 1.0, 100.0}) {
        Camera c = cameraAt({}, rest, t);
        EXPECT_EQ(c.pos, rest.pos);
        EXPECT_EQ(c.target, rest.target);
        EXPECT_EQ(c.fov, rest.fov);
    }
}

TEST(CameraPath, OneKeyIsThatKeyAtEveryTime) {
    std::vector<Keyframe> keys{key(2, vec3(1, 1, 1), vec3(0, 0, 1), 70)};
    for (double t : {0.0, 2.0, 5.0}) expectSame(cameraAt(keys, Camera{}, t), keys[0]);
}

TEST(CameraPath, PassesThroughEveryKey) {
    std::vector<Keyframe> keys = zigzag();
    for (const Keyframe& k : keys) expectSame(cameraAt(keys, Camera{}, k.t), k);
}

TEST(CameraPath, HoldsBeforeTheFirstKeyAndAfterTheLast) {
    std::vector<Keyframe> keys = zigzag();
    for (double t : {0.0, 0.25, 0.4999}) expectSame(cameraAt(keys, Camera{}, t), keys.front());
    for (double t : {4.5001, 6.0, 3600.0}) expectSame(cameraAt(keys, Camera{}, t), keys.back());
}

// Keys on p(t) = a + b·t + c·t², unevenly spaced: the tangent at an inner key is the slope of
// the parabola through it and its neighbours, which is p'(t) itself, and a cubic Hermite
// segment with exact values and slopes at both ends is p. The end keys' tangents are zero, so
// only segments between inner keys follow p.
TEST(CameraPath, FollowsAQuadraticPathExactlyBetweenInnerKeys) {
    auto p = [](double t, double a, double b, double c) { return float(a + b * t + c * t * t); };
    auto onPath = [&](double t) {
        return key(float(t), vec3(p(t, 1, 2, -0.5), p(t, 2, -1, 0.25), p(t, -6, 0.5, 0.1)),
                   vec3(p(t, 0, 1, 0.3), p(t, 1, 0, -0.2), p(t, 0, -2, 0.4)), p(t, 40, 5, -1));
    };
    std::vector<Keyframe> keys;
    for (double t : {0.0, 0.5, 1.75, 2.0, 3.5, 4.0}) keys.push_back(onPath(t));
    for (double t = 0.5; t <= 3.5; t += 0.125) {
        std::vector<float> got = numbers(cameraAt(keys, Camera{}, t)), want = numbers(onPath(t));
        // The keys are floats: their rounding (a few 1e-7 relative) is all that may differ.
        for (size_t c = 0; c < got.size(); ++c)
            EXPECT_NEAR(got[c], want[c], 2e-5f * std::max(1.0f, std::abs(want[c])))
                << "number " << c << " at t " << t;
    }
}

// C¹: at every key (the ends included, where the path meets its hold) the slope just before
// equals the slope just after. Each side is a one-sided difference of second order,
// (3·p(t) − 4·p(t∓h) + p(t∓2h)) / ±2h, off a cubic's slope by h²·|p‴|/3 (< 1e-3 here) plus the
// float rounding of the camera's numbers, 2·ulp/h (fov near 50: 0.008); so the sides of a smooth
// path differ by less than 0.02, and a corner of these keys makes them differ by 1 or more.
TEST(CameraPath, SlopeIsContinuousAtEveryKey) {
    std::vector<Keyframe> keys = zigzag();
    const double h = 1e-3;
    auto at = [&](double t) { return numbers(cameraAt(keys, Camera{}, t)); };
    for (const Keyframe& k : keys) {
        std::vector<float> b2 = at(k.t - 2 * h), b1 = at(k.t - h), p = at(k.t), a1 = at(k.t + h),
                           a2 = at(k.t + 2 * h);
        for (size_t c = 0; c < p.size(); ++c) {
            double left = (3.0 * p[c] - 4.0 * b1[c] + b2[c]) / (2 * h);
            double right = (-3.0 * p[c] + 4.0 * a1[c] - a2[c]) / (2 * h);
            EXPECT_NEAR(left, right, 0.05) << "number " << c << " at key t " << k.t;
        }
    }
}
