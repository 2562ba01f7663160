// manifold_points.h — which of a touching pair's candidate points its manifold keeps.
#pragma once

#include <algorithm>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace mb {

constexpr int kMaxManifold = 4;

// Up to four of the candidates: the deepest, the one furthest from it, the one spanning the
// largest triangle with those, and the one furthest from all three. Each is a candidate not yet
// kept (where the rest lie on the kept points, a score ties at 0 and the first would be kept
// twice: one probe, two rows). Ties go to the first.
// `most` above four keeps the deepest of the rest too, up to `most`: a group resting on a face
// of many points (a chair on its back) is deepest at one corner one step and at another the
// next, by a tenth of a millimetre; with four, the four kept changed with it, and the points
// they left out sank, and it rocked in place. With the deepest eight, every point it rests on
// stays whichever comes first.
// Candidate: any type with a `point` (glm::dvec3) and a `separation` (double).
template <class Candidate>
void reduceManifold(std::vector<Candidate>& all, int most = kMaxManifold) {
    if (all.size() <= size_t(std::max(most, kMaxManifold))) return;
    std::vector<Candidate> kept;
    std::vector<char> taken(all.size(), 0);
    auto keep = [&](auto score) {
        size_t at = all.size();
        for (size_t i = 0; i < all.size(); ++i)
            if (!taken[i] && (at == all.size() || score(all[i]) > score(all[at]))) at = i;
        taken[at] = 1;
        kept.push_back(all[at]);
        return all[at].point;
    };
    const glm::dvec3 p0 = keep([](const Candidate& c) { return -c.separation; });
    const glm::dvec3 p1 = keep([&](const Candidate& c) { return glm::length(c.point - p0); });
    const glm::dvec3 p2 =
        keep([&](const Candidate& c) { return glm::length(glm::cross(p1 - p0, c.point - p0)); });
    keep([&](const Candidate& c) {
        return std::min(
            {glm::length(c.point - p0), glm::length(c.point - p1), glm::length(c.point - p2)});
    });
    while (int(kept.size()) < most) keep([](const Candidate& c) { return -c.separation; });
    all = kept;
}

}  // namespace mb
