// test_physics_broadphase.cpp — the grid and its kept list find exactly the pairs a brute-force test finds.
#include "marchbox/broadphase.h"

#include <gtest/gtest.h>
#include <algorithm>
#include <cstdint>

using namespace mb;

TEST(PhysicsBroadphase, MatchesBruteForceWithMixedSizesAndMotion) {
    std::uint32_t state = 12345;
    auto next = [&] { return float((state = state * 1664525u + 1013904223u) >> 8) / float(1u << 24); };
    std::vector<glm::dvec3> centres;
    std::vector<double> extents;
    for (int i = 0; i < 600; ++i) {
        centres.emplace_back(10 * next(), 10 * next(), 10 * next());
        extents.push_back(i % 97 == 0 ? 3.0 : 0.1 + 0.2 * next());  // a few boulders
    }
    Broadphase bp;
    // Later rounds reuse the sorted cells, and the list of pairs while every sphere stays within its
    // skin: moves of 5 mm keep it, growing every extent by half or moving 0.3 m must not.
    const double moves[6] = {0.0, 0.005, 0.0, 0.005, 0.3, 0.005};
    for (int round = 0; round < 6; ++round) {
        if (round == 2)
            for (double& e : extents) e *= 1.5;
        for (glm::dvec3& c : centres) c += moves[round] * glm::dvec3(next() - 0.5, -0.7, 0.3);
        std::vector<std::pair<int, int>> pairs, brute;
        bp.findPairs(centres, extents, pairs);
        for (int i = 0; i < 600; ++i)
            for (int j = i + 1; j < 600; ++j) {
                const double reach = extents[i] + extents[j];
                const glm::dvec3 d = centres[j] - centres[i];
                if (d.x * d.x + d.y * d.y + d.z * d.z < reach * reach) brute.emplace_back(i, j);
            }
        std::sort(pairs.begin(), pairs.end());
        EXPECT_EQ(pairs, brute) << "round " << round;
    }
}
