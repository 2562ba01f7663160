// pair_contact.h — one contact point of two bodies, as each pair's analytic routine gives it.
#pragma once

#include <glm/vec3.hpp>

namespace mb {

struct PairContact {
    glm::dvec3 point;   // midway between the two surfaces
    glm::dvec3 normal;  // unit, from a to b
    double separation;  // < 0 overlaps
    int feature;        // stable from step to step while the same features touch (0..254)
};

}  // namespace mb
