// Which candidate points a manifold keeps (manifold_points.h).
#include "manifold_points.h"

#include <gtest/gtest.h>

namespace mb {
namespace {

struct Point {
    glm::dvec3 point;
    double separation;
    int probe = 0;
};

// Eight candidates, seven of them (different probes) at one spot and one apart: four different
// probes are kept. Picking by score alone keeps the first probe again where every score ties at
// 0, and one probe's two rows double its push.
TEST(ManifoldPoints, KeepsNoCandidateTwice) {
    std::vector<Point> all;
    for (int k = 0; k < 8; ++k) all.push_back({glm::dvec3(k == 5 ? 1.0 : 0.0, 0, 0), -0.01, k});
    reduceManifold(all);
    ASSERT_EQ(all.size(), size_t(kMaxManifold));
    for (size_t i = 0; i < all.size(); ++i)
        for (size_t j = i + 1; j < all.size(); ++j)
            EXPECT_NE(all[i].probe, all[j].probe) << "probe " << all[i].probe << " kept twice";
}

// A face's many candidates: its four corners are the ones kept, the deepest first.
TEST(ManifoldPoints, KeepsTheCornersOfAFace) {
    std::vector<Point> all;
    for (int x = 0; x <= 2; ++x)
        for (int z = 0; z <= 2; ++z)
            all.push_back({glm::dvec3(x, 0, z), -0.01 * (x + z), 3 * x + z});
    reduceManifold(all);
    ASSERT_EQ(all.size(), size_t(kMaxManifold));
    EXPECT_EQ(all[0].point, glm::dvec3(2, 0, 2));
    for (const Point& p : all) {
        EXPECT_TRUE(p.point.x != 1.0 && p.point.z != 1.0) << p.point.x << ", " << p.point.z;
    }
}

}  // namespace
}  // namespace mb
