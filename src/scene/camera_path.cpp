// camera_path.cpp — cubic Hermite segments between keyframes, parabolic tangents at inner keys.
#include "marchbox/scene/camera_path.h"

#include <algorithm>
#include <array>

namespace mb {

namespace {

// What moves along the path, in double precision: pos xyz, target xyz, fov.
using Pose = std::array<double, 7>;

Pose poseOf(const Keyframe& k) {
    return {k.pos.x, k.pos.y, k.pos.z, k.target.x, k.target.y, k.target.z, k.fov};
}

// dp/dt at key i. Inner keys: the parabola through keys i-1, i, i+1 has there the slope
//   (s0·h1 + s1·h0) / (h0 + h1),  s0, s1 the chords' slopes before and after, h0, h1 their spans.
// End keys: zero, so the path meets the hold beyond them without a kink.
Pose tangentAt(const std::vector<Keyframe>& keys, size_t i) {
    Pose m{};
    if (i == 0 || i + 1 == keys.size()) return m;
    const Pose p0 = poseOf(keys[i - 1]), p1 = poseOf(keys[i]), p2 = poseOf(keys[i + 1]);
    const double h0 = double(keys[i].t) - keys[i - 1].t, h1 = double(keys[i + 1].t) - keys[i].t;
    for (size_t c = 0; c < m.size(); ++c) {
        double s0 = (p1[c] - p0[c]) / h0, s1 = (p2[c] - p1[c]) / h1;
        m[c] = (s0 * h1 + s1 * h0) / (h0 + h1);
    }
    return m;
}

Camera cameraOf(const Pose& p) {
    Camera c;
    c.pos = glm::vec3(float(p[0]), float(p[1]), float(p[2]));
    c.target = glm::vec3(float(p[3]), float(p[4]), float(p[5]));
    // A tangent can carry fov a little past a key near its limits; keep it a valid camera.
    c.fov = std::clamp(float(p[6]), 1.0f, 179.0f);
    return c;
}

}  // namespace

Camera cameraAt(const std::vector<Keyframe>& keys, const Camera& rest, double t) {
    if (keys.empty()) return rest;
    // The first key later than t: t lies in the segment that ends there.
    auto later = std::upper_bound(keys.begin(), keys.end(), t,
                                  [](double time, const Keyframe& k) { return time < k.t; });
    if (later == keys.begin()) return cameraOf(poseOf(keys.front()));
    if (later == keys.end()) return cameraOf(poseOf(keys.back()));
    const size_t i = size_t(later - keys.begin()) - 1;
    const double h = double(keys[i + 1].t) - keys[i].t, u = (t - keys[i].t) / h;
    const Pose p0 = poseOf(keys[i]), p1 = poseOf(keys[i + 1]);
    const Pose m0 = tangentAt(keys, i), m1 = tangentAt(keys, i + 1);
    // The Hermite basis: values at u = 0 and 1, and slopes (per second, hence the factor h).
    const double u2 = u * u, u3 = u2 * u;
    const double a0 = 2 * u3 - 3 * u2 + 1, b0 = u3 - 2 * u2 + u, a1 = 3 * u2 - 2 * u3, b1 = u3 - u2;
    Pose p;
    for (size_t c = 0; c < p.size(); ++c)
        p[c] = a0 * p0[c] + b0 * h * m0[c] + a1 * p1[c] + b1 * h * m1[c];
    return cameraOf(p);
}

}  // namespace mb
