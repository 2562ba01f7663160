// rigid_probes.h — where a turning body can touch something: points of its shape, each the
// centre of a sphere (radius 0 for a corner) that the shape sweeps or holds.
//
// A probe at c with radius ρ meets a surface of signed distance f where f(c) < ρ, at the point
// c − ρ·∇f(c), with separation f(c) − ρ. That is exact for each shape's own geometry: a box's
// corners and edge points (ρ = 0), a capsule's segment (ρ = its radius), a torus's core circle
// (ρ = its tube), a sphere's centre. A cylinder's rims are probed at fixed points and, against
// each surface, at the rim's lowest point along that surface's normal (rimSupport), so that a
// rolling cylinder touches exactly where a real one does; a rim lying flat on it, at four.
#pragma once

#include "marchbox/scene/scene.h"

#include <glm/vec3.hpp>
#include <vector>

namespace mb {

struct Probe {
    glm::dvec3 local;  // centre, in the body's frame
    double radius;     // of the sphere about it that the shape holds
};

std::vector<Probe> probesOf(const Object& o);

// A cylinder's rims: centre (local) and the rim circle's radius; none for other shapes. They
// carry no fixed probes: a rolling rim would meet each as the corner of a polygon.
struct Rim {
    glm::dvec3 centre;
    double radius;
};
std::vector<Rim> rimsOf(const Object& o);

// Four points of the rim (world centre, world unit axis) a quarter turn apart. The first is the
// one furthest along −normal, where the rim first meets a surface facing `normal`; the others
// meet it too when the rim is tilted less than the contact's reach, so that a disc landing
// nearly flat stands on them rather than rocking from one lowest point to the next (at 1/30 s
// a pile pressed one 10 cm into the ground that way). Where the rim lies flat on the surface
// (rimLiesFlat: within kFlat of parallel, 0.6°) the four come from any direction across the
// axis, so a standing cylinder rests on a square.
constexpr double kFlat = 0.01;
std::vector<glm::dvec3> rimSupport(const glm::dvec3& centre, const glm::dvec3& axis, double radius,
                                   const glm::dvec3& normal);
bool rimLiesFlat(const glm::dvec3& axis, const glm::dvec3& normal);

}  // namespace mb
