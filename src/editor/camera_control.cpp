// camera_control.cpp — the camera as a point on a sphere about its target.
#include "marchbox/editor/camera_control.h"

#include "marchbox/scene/camera.h"
#include "marchbox/scene/sdf.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace mb {

// offset = r·(cos p·sin y, sin p, cos p·cos y): yaw y about +y, pitch p above the horizon.
struct Spherical {
    float r, yaw, pitch;
};

static Spherical toSpherical(glm::vec3 offset) {
    float r = glm::length(offset);
    if (r <= 0.0f) return {0.0f, 0.0f, 0.0f};
    return {r, std::atan2(offset.x, offset.z), std::asin(std::clamp(offset.y / r, -1.0f, 1.0f))};
}

static glm::vec3 fromSpherical(const Spherical& s) {
    return s.r * glm::vec3(std::cos(s.pitch) * std::sin(s.yaw), std::sin(s.pitch),
                           std::cos(s.pitch) * std::cos(s.yaw));
}

void orbitCamera(Camera& c, glm::vec2 drag, const CameraControls& k) {
    Spherical s = toSpherical(c.pos - c.target);
    if (s.r <= 0.0f) return;
    // Lowering yaw moves the camera towards the view's left (right = forward × up), so the
    // scene turns with a drag to the right.
    s.yaw -= drag.x * k.orbitRadiansPerPixel;
    s.pitch = std::clamp(s.pitch + drag.y * k.orbitRadiansPerPixel, -k.maxPitch, k.maxPitch);
    c.pos = c.target + fromSpherical(s);
}

void panCamera(Camera& c, glm::vec2 drag, float viewHeight) {
    if (viewHeight <= 0.0f) return;
    CameraBasis b = cameraBasis(c);
    // At the target's distance the view is 2·d·tan(fov/2) metres tall.
    float d = glm::length(c.target - c.pos);
    float metresPerPixel = 2.0f * d * std::tan(glm::radians(c.fov) * 0.5f) / viewHeight;
    glm::vec3 right = glm::normalize(b.right), up = glm::normalize(b.up);
    glm::vec3 move = (-drag.x * right + drag.y * up) * metresPerPixel;
    c.pos += move;
    c.target += move;
}

void zoomCamera(Camera& c, float steps, const CameraControls& k) {
    glm::vec3 offset = c.pos - c.target;
    float r = glm::length(offset);
    if (r <= 0.0f) return;
    float next = std::clamp(r * std::pow(k.zoomPerWheelStep, steps), k.minDistance, k.maxDistance);
    c.pos = c.target + offset * (next / r);
}

void flyCamera(Camera& c, glm::vec3 move, float seconds, const CameraControls& k) {
    CameraBasis b = cameraBasis(c);
    glm::vec3 step =
        move.x * glm::normalize(b.right) + move.y * glm::vec3(0, 1, 0) + move.z * b.forward;
    step *= k.flySpeed * seconds;
    c.pos += step;
    c.target += step;
}

void previewOrbit(Camera& c, float seconds, const CameraControls& k) {
    Spherical s = toSpherical(c.pos - c.target);
    if (s.r <= 0.0f) return;
    s.yaw += k.previewRadiansPerSecond * seconds;
    c.pos = c.target + fromSpherical(s);
}

int solidAroundEye(const Scene& scene, glm::vec3 eye) {
    const SceneSample m = mapScene(makeSceneSdf(scene), eye);
    return m.d < 0.0f ? m.object : kHitNone;
}

// The tangents of half the view's angle across (x) and up (y): tan(fov/2) up, `aspect` times
// that across (cameraRay()).
static glm::vec2 halfTangents(const Camera& c, float aspect) {
    const float t = std::tan(glm::radians(c.fov) * 0.5f);
    return {aspect * t, t};
}

// How far (across, depth) lies inside the plane through the eye whose points have
// across = tangent · depth, on the side of smaller `across`.
static float insideEdge(float across, float depth, float tangent) {
    return (tangent * depth - across) / std::sqrt(1.0f + tangent * tangent);
}

bool ballInView(const Camera& c, const Ball& b, const ViewWindow& w) {
    const CameraBasis basis = cameraBasis(c);
    const glm::vec3 d = b.centre - c.pos;
    const float z = glm::dot(d, basis.forward);
    const glm::vec2 across(glm::dot(d, glm::normalize(basis.right)),
                           glm::dot(d, glm::normalize(basis.up)));
    const glm::vec2 t = halfTangents(c, w.aspect);
    // Each edge of the window is a plane through the eye; the ball is inside when its centre is
    // at least its radius inside every one.
    for (int axis = 0; axis < 2; ++axis)
        if (insideEdge(across[axis], z, w.hi[axis] * t[axis]) < b.radius ||
            -insideEdge(across[axis], z, w.lo[axis] * t[axis]) < b.radius)
            return false;
    return z > 0.0f;
}

glm::vec3 viewRay(const Camera& c, float aspect, glm::vec2 at) {
    const CameraBasis b = cameraBasis(c);
    const glm::vec2 t = halfTangents(c, aspect);
    return b.forward + at.x * t.x * glm::normalize(b.right) + at.y * t.y * glm::normalize(b.up);
}

// The distance from the middle of the balls that fits them into a whole view whose half angles
// are the window's: ballInView's test solved for the eye's distance d from the target, a ball
// at (x, y, z) from it needing (d + z)·sin a ≥ |x|·cos a + r on each axis.
static float fittingDistance(const Camera& c, const std::vector<Ball>& balls, const ViewWindow& w,
                             float least) {
    const CameraBasis basis = cameraBasis(c);
    const glm::vec3 right = glm::normalize(basis.right), up = glm::normalize(basis.up);
    const glm::vec2 t = halfTangents(c, w.aspect) * (w.hi - w.lo) * 0.5f;
    float distance = least;
    for (const Ball& b : balls) {
        const glm::vec3 o = b.centre - c.target;
        const float z = glm::dot(o, basis.forward);
        for (int axis = 0; axis < 2; ++axis) {
            const float a = std::atan(t[axis]);
            const float across = std::abs(glm::dot(o, axis == 0 ? right : up));
            distance = std::max(distance, (across * std::cos(a) + b.radius) / std::sin(a) - z);
        }
    }
    return distance;
}

void frameBalls(Camera& c, const std::vector<Ball>& balls, const ViewWindow& w,
                const CameraControls& k) {
    if (balls.empty()) return;
    glm::vec3 lo = balls[0].centre, hi = lo;
    for (const Ball& b : balls) {
        lo = glm::min(lo, b.centre - b.radius);
        hi = glm::max(hi, b.centre + b.radius);
    }
    glm::vec3 back = c.pos - c.target;
    back = glm::length(back) > 0.0f ? glm::normalize(back) : glm::vec3(0.0f, 0.0f, -1.0f);
    const glm::vec3 middle = 0.5f * (lo + hi);
    c.target = middle;
    c.pos = c.target + back;
    const CameraBasis basis = cameraBasis(c);
    const glm::vec2 t = halfTangents(c, w.aspect), m = w.middle();
    // Moved sideways so that the middle shows at the window's middle, which keeps the balls in
    // the window only nearly (each is seen from a little aside): then back until all fit. 2%
    // back from touching the edges, so what is framed is seen whole, not grazed.
    float distance = fittingDistance(c, balls, w, k.minDistance) * 1.02f;
    for (int tries = 0; tries < 40; ++tries, distance *= 1.05f) {
        const float d = std::min(distance, k.maxDistance);
        c.target = middle - d * (m.x * t.x * glm::normalize(basis.right) +
                                 m.y * t.y * glm::normalize(basis.up));
        c.pos = c.target + back * d;
        const bool fits = std::all_of(balls.begin(), balls.end(),
                                      [&](const Ball& b) { return ballInView(c, b, w); });
        if (fits || d == k.maxDistance) return;
    }
}

}  // namespace mb
