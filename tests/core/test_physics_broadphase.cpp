// test_physics_broadphase.cpp — the grid finds exactly the pairs a brute-force test finds.
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
    for (int round = 0; round < 3; ++round) {  // later rounds reuse the sorted cells
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
        for (glm::dvec3& c : centres) c += glm::dvec3(0.3 * next() - 0.15, -0.2, 0.1);
    }
}
