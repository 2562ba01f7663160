// overlap.cpp — the deepest overlap in a set of spheres, measured without the simulator's state.
#include "marchbox/physics/overlap.h"

#include "broadphase.h"
#include "static_collider.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace mb {

double deepestOverlap(const Scene& scene, const std::vector<glm::dvec3>& centres,
                      const std::vector<double>& radii) {
    StaticCollider statics(scene);
    double deepest = 0.0;
    for (size_t i = 0; i < centres.size(); ++i)
        deepest = std::max(deepest, radii[i] - statics.distance(centres[i]));
    Broadphase broadphase;
    std::vector<std::pair<int, int>> pairs;
    broadphase.findPairs(centres, radii, pairs);  // exactly the overlapping pairs
    for (auto [a, b] : pairs)
        deepest = std::max(deepest, radii[a] + radii[b] - glm::length(centres[b] - centres[a]));
    return deepest;
}

}  // namespace mb
