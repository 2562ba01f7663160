// marchbox/physics/overlap.h — how deeply spheres overlap each other and the static scene.
#pragma once

#include "marchbox/scene/scene.h"

#include <glm/vec3.hpp>
#include <vector>

namespace mb {

// The deepest overlap among spheres (centres, radii) and between them and the scene's static
// colliders, measured afresh: the same yardstick for this simulator and for Bullet.
double deepestOverlap(const Scene& scene, const std::vector<glm::dvec3>& centres,
                      const std::vector<double>& radii);

}  // namespace mb
