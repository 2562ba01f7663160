// test_physics_broadphase.cpp — the grid and its kept list find exactly the pairs a brute-force
// test finds.
#include "broadphase.h"

#include <gtest/gtest.h>
#include <algorithm>
#include <cstdint>

using namespace mb;

namespace {

struct Spheres {
    std::vector<glm::dvec3> centres;
    std::vector<double> extents;
};

// 600 spheres in a 10 m box, some boulders among them; next() draws from [0, 1).
template <class Next>
Spheres scattered(Next& next) {
    Spheres s;
    for (int i = 0; i < 600; ++i) {
        s.centres.emplace_back(10 * next(), 10 * next(), 10 * next());
        s.extents.push_back(i % 97 == 0 ? 3.0 : 0.1 + 0.2 * next());
    }
    return s;
}

std::vector<std::pair<int, int>> bruteForce(const Spheres& s) {
    std::vector<std::pair<int, int>> pairs;
    for (size_t i = 0; i < s.centres.size(); ++i)
        for (size_t j = i + 1; j < s.centres.size(); ++j) {
            const double reach = s.extents[i] + s.extents[j];
            const glm::dvec3 d = s.centres[j] - s.centres[i];
            if (d.x * d.x + d.y * d.y + d.z * d.z < reach * reach)
                pairs.emplace_back(int(i), int(j));
        }
    return pairs;
}

}  // namespace

TEST(PhysicsBroadphase, MatchesBruteForceWithMixedSizesAndMotion) {
    std::uint32_t state = 12345;
    auto next = [&] {
        return float((state = state * 1664525u + 1013904223u) >> 8) / float(1u << 24);
    };
    auto [centres, extents] = scattered(next);
    Broadphase bp;
    // Later rounds reuse the sorted cells, and the list of pairs while every sphere stays within
    // its skin: moves of 5 mm keep it, growing every extent by half or moving 0.3 m must not.
    const double moves[6] = {0.0, 0.005, 0.0, 0.005, 0.3, 0.005};
    for (int round = 0; round < 6; ++round) {
        if (round == 2)
            for (double& e : extents) e *= 1.5;
        for (glm::dvec3& c : centres) c += moves[round] * glm::dvec3(next() - 0.5, -0.7, 0.3);
        std::vector<std::pair<int, int>> pairs;
        bp.findPairs(centres, extents, pairs);
        std::sort(pairs.begin(), pairs.end());
        EXPECT_EQ(pairs, bruteForce({centres, extents})) << "round " << round;
    }
}

// A few spheres at a time past their skin (boulders among them, and some grown) while the rest
// drift together: the list is refreshed for those alone, and must still hold every pair.
TEST(PhysicsBroadphase, RefreshingTheMovedSpheresKeepsEveryPair) {
    std::uint32_t state = 777;
    auto next = [&] {
        return float((state = state * 1664525u + 1013904223u) >> 8) / float(1u << 24);
    };
    Spheres s = scattered(next);
    Broadphase bp;
    for (int round = 0; round < 40; ++round) {
        for (size_t i = 0; i < s.centres.size(); ++i) {
            s.centres[i] +=
                glm::dvec3(0.0, -0.05, 0.01);  // the common move, beside which moves count
            if (next() < 0.04)
                s.centres[i] += 0.4 * glm::dvec3(next() - 0.5, next() - 0.5, next() - 0.5);
            if (next() < 0.01) s.extents[i] *= 1.3;
        }
        std::vector<std::pair<int, int>> pairs;
        bp.findPairs(s.centres, s.extents, pairs);
        std::sort(pairs.begin(), pairs.end());
        ASSERT_EQ(pairs, bruteForce(s)) << "round " << round;
    }
}

// Two spheres of extent 0.1 grow to 0.15 in the list (a skin of half the extent): a pair listed
// when first found 0.2985 apart, in the last 1 % of the grown reach 0.3, must stay listed, since
// two moves of 0.0494 (inside the skin: the list is kept) bring them to overlap at 0.1997.
TEST(PhysicsBroadphase, APairJustInsideTheGrownReachIsKept) {
    Spheres s{{{0, 0, 0}, {0.2985, 0, 0}}, {0.1, 0.1}};
    Broadphase bp;
    std::vector<std::pair<int, int>> pairs;
    bp.findPairs(s.centres, s.extents, pairs);
    ASSERT_TRUE(pairs.empty()) << "0.2985 apart, they do not touch yet";
    s.centres[0].x += 0.0494;
    s.centres[1].x -= 0.0494;
    bp.findPairs(s.centres, s.extents, pairs);
    EXPECT_EQ(pairs, bruteForce(s)) << "the kept list lost a pair it had found inside its skin";
}

// Two spheres just outside each other's grown reach (0.30005 apart) each move 0.05005 towards
// the other: 5e-5 past their skin, so the list no longer covers them and must be refreshed; a
// tolerance of even 1e-3 of the extent on that test keeps the old list and misses the pair.
TEST(PhysicsBroadphase, ASphereJustPastItsSkinIsRefreshed) {
    Spheres s{{{0, 0, 0}, {0.30005, 0, 0}}, {0.1, 0.1}};
    Broadphase bp;
    std::vector<std::pair<int, int>> pairs;
    bp.findPairs(s.centres, s.extents, pairs);
    ASSERT_TRUE(pairs.empty());
    s.centres[0].x += 0.05005;
    s.centres[1].x -= 0.05005;
    bp.findPairs(s.centres, s.extents, pairs);
    EXPECT_EQ(pairs, bruteForce(s)) << "a sphere past its skin kept its stale pairs";
}
