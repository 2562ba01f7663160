// rigid_body.h — mass properties of every shape and the torque-free rotation of a rigid body.
//
// Pure maths for the rigid-body step: no world, no contacts. Every shape is symmetric about its
// local axes, so its principal axes are its own and the inertia tensor is the diagonal
// `inertia`; a body's orientation q (body to world) carries it to the world. Its centre of mass
// is its origin but for a cone (a frustum's lies towards its base), which is where the body's
// frame stands (MassProperties::centre).
#pragma once

#include "mass_moments.h"

#include "marchbox/scene/scene.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <span>

namespace mb {

// Uniform density and total mass o.mass, from each shape's closed form (rigid_body.cpp); a
// rounded shape, or a shelled ellipsoid, by integration over its SDF (mass_moments.h), made
// symmetric as the shape is. `axes` is always the identity.
MassProperties massProperties(const Object& o);

// The free rigid body's rotation over h (no torque): orientation q (body to world, unit) and
// world angular velocity `spin`, for principal moments `inertia` (local axes, each > 0). Keeps
// the world angular momentum to rounding, and the kinetic energy to rounding where two moments
// are equal (the symmetric top's exact flow) or else to a tiny bound (a symmetric fourth-order
// splitting; rigid_body.cpp has both methods and the measured errors). q leaves normalised.
void rotateFree(glm::dquat& q, glm::dvec3& spin, const glm::dvec3& inertia, double h);
// The same for many bodies at once, each as alone; each turn a different body's.
struct FreeTurn {
    glm::dquat* q;
    glm::dvec3* spin;
    const glm::dvec3* inertia;
};
void rotateFree(std::span<const FreeTurn> turns, double h);

// The orientation that turns `from`'s y axis to q's by the least turn: q less its twist about
// its own y axis since `from` (the swing of a swing-twist split); q itself where the axis
// turned right round, which has no least turn.
glm::dquat untwist(const glm::dquat& q, const glm::dquat& from);

}  // namespace mb
