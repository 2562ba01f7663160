// rigid_body.h — mass properties of every shape and the torque-free rotation of a rigid body.
//
// Pure maths for the rigid-body step: no world, no contacts. Each shape's local frame is its
// principal frame (every shape is symmetric about its local axes), so the inertia tensor is the
// diagonal `inertia` and a body's orientation q (body to world) carries it to the world.
#pragma once

#include "marchbox/scene/scene.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

namespace mb {

struct MassProperties {
    double mass;         // kg
    glm::dvec3 inertia;  // principal moments about the local x, y, z axes, kg·m²
};

// Uniform density and total mass o.mass, from each shape's closed form (rigid_body.cpp).
MassProperties massProperties(const Object& o);

// The free rigid body's rotation over h (no torque): orientation q (body to world, unit) and
// world angular velocity `spin`, for principal moments `inertia` (local axes, each > 0). Keeps
// the world angular momentum to rounding, and the kinetic energy to rounding where two moments
// are equal (the symmetric top's exact flow) or else to a tiny bound (a symmetric fourth-order
// splitting; rigid_body.cpp has both methods and the measured errors). q leaves normalised.
void rotateFree(glm::dquat& q, glm::dvec3& spin, const glm::dvec3& inertia, double h);

}  // namespace mb
