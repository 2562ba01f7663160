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

// Half the view's angle across (x) and up (y): tan of the vertical half angle is tan(fov/2),
// the horizontal one's is `aspect` times that (cameraRay()).
static glm::vec2 halfAngles(const Camera& c, float aspect) {
    float t = std::tan(glm::radians(c.fov) * 0.5f);
    return {std::atan(aspect * t), std::atan(t)};
}

bool ballInView(const Camera& c, const Ball& b, float aspect) {
    CameraBasis basis = cameraBasis(c);
    glm::vec3 d = b.centre - c.pos;
    float z = glm::dot(d, basis.forward);
    float x = glm::dot(d, glm::normalize(basis.right)), y = glm::dot(d, glm::normalize(basis.up));
    glm::vec2 a = halfAngles(c, aspect);
    // Each side of the view is a plane through the eye at angle a from the forward axis; the
    // ball is inside when its centre is at least its radius inside every one.
    auto inside = [&](float across, float half) {
        return std::abs(across) * std::cos(half) + b.radius <= z * std::sin(half);
    };
    return inside(x, a.x) && inside(y, a.y);
}

void frameBalls(Camera& c, const std::vector<Ball>& balls, float aspect, const CameraControls& k) {
    if (balls.empty()) return;
    glm::vec3 lo = balls[0].centre, hi = lo;
    for (const Ball& b : balls) {
        lo = glm::min(lo, b.centre - b.radius);
        hi = glm::max(hi, b.centre + b.radius);
    }
    glm::vec3 back = c.pos - c.target;
    back = glm::length(back) > 0.0f ? glm::normalize(back) : glm::vec3(0.0f, 0.0f, -1.0f);
    c.target = 0.5f * (lo + hi);
    c.pos = c.target + back;
    const CameraBasis basis = cameraBasis(c);
    const glm::vec3 right = glm::normalize(basis.right), up = glm::normalize(basis.up);
    const glm::vec2 a = halfAngles(c, aspect);
    // ballInView's test solved for the eye's distance d from the target: a ball at (x, y, z)
    // from the target in the view's frame needs (d + z)·sin a ≥ |x|·cos a + r on each axis.
    float distance = k.minDistance;
    for (const Ball& b : balls) {
        const glm::vec3 o = b.centre - c.target;
        const float z = glm::dot(o, basis.forward);
        for (int axis = 0; axis < 2; ++axis) {
            const float across = std::abs(glm::dot(o, axis == 0 ? right : up));
            const float need = (across * std::cos(a[axis]) + b.radius) / std::sin(a[axis]) - z;
            distance = std::max(distance, need);
        }
    }
    // 2% back from touching the edges, so what is framed is seen whole, not grazed.
    c.pos = c.target + back * std::min(distance * 1.02f, k.maxDistance);
}

}  // namespace mb
