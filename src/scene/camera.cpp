// camera.cpp — camera basis and primary rays; twin of cameraRay() in shaders/march.frag.
#include "marchbox/scene/camera.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace mb {

CameraBasis cameraBasis(const Camera& c) {
    glm::vec3 forward = c.target - c.pos;
    forward = glm::length(forward) > 0 ? glm::normalize(forward) : glm::vec3(0, 0, 1);
    // Looking straight up or down, world up is parallel to the view: take +z instead.
    glm::vec3 up = std::abs(forward.y) > 0.999f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    glm::vec3 right = glm::normalize(glm::cross(forward, up));
    up = glm::cross(right, forward);
    float s = std::tan(glm::radians(c.fov) * 0.5f);
    return {c.pos, forward, right * s, up * s};
}

glm::vec3 cameraRay(const CameraBasis& b, glm::vec2 pixel, glm::vec2 size) {
    glm::vec2 uv = (2.0f * pixel - size) / size.y;
    return glm::normalize(b.forward + uv.x * b.right + uv.y * b.up);
}

}  // namespace mb
