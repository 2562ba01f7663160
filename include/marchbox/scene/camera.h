// marchbox/scene/camera.h — the view: camera basis and primary rays, shared by the shader's
// uniforms, picking and the CPU/GPU agreement tests.
#pragma once

#include "marchbox/scene/scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace mb {

// As glm::lookAt builds it: right = forward × up, so a camera looking along +z sees +x on its
// left. right and up are scaled by tan(fov/2), so a ray is forward + u·right + v·up.
struct CameraBasis {
    glm::vec3 pos, forward, right, up;
};

CameraBasis cameraBasis(const Camera& camera);

// Unit direction through `pixel` of a width × height image. Pixels count from the bottom-left
// corner as gl_FragCoord does: the centre of the bottom-left pixel is (0.5, 0.5).
glm::vec3 cameraRay(const CameraBasis& basis, glm::vec2 pixel, glm::vec2 imageSize);

}  // namespace mb
