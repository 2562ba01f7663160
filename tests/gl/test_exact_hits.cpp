// test_exact_hits.cpp — every shape with an exact ray hit (include/marchbox/scene/shapes.h)
// draws where marching its SDF draws it: through the compiled scene's straight-line hits and
// through the plain members' grid (shaders/intersect.glsl's hitShape), against the object loop,
// which marches everything.
//
// Planted in a copy of shaders/ read through MARCHBOX_SHADERS, and caught: the frustum's slant
// leaning the wrong way ((r1 - r2) / height: 200 pixels of another object in lines, 658 through
// the grid), the nappe beyond the cone's apex chosen (202 pixels drawn by marching alone, away
// from any edge, through the grid, whose more turns send rays there), the ellipsoid's span left
// unscaled (sqrt(h) for sqrt(h / d·d): 91 and 280 normals turned).
#include "golden.h"

#include "marchbox/scene/shapes.h"

#include <gtest/gtest.h>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

using namespace mb;

namespace {

constexpr int kW = 320, kH = 180;
// Of 255, on a normal's components each drawn as ×0.5 + 0.5. Inside a face the two normals agree
// to 1; beside a box's edge a pixel may take the normal from either side of the crease (by
// finite differences, ε from two different points): measured 3 such pixels of 6,600.
constexpr int kNormalTolerance = 3;
constexpr double kMaxTurnedShare = 0.001;

// Each type that has a hit, a frustum and a pointed cone among them, `rows` times, each object
// turned its own way, nine to a row across the view.
Scene shapesWithHits(int rows) {
    Scene s;
    s.materials.push_back({});
    s.world.ground = false;
    s.camera = {{0.0f, 0.0f, 9.0f}, {0.0f, 0.0f, 0.0f}, 50.0f};
    int n = 0;
    for (int row = 0; row < rows; ++row)
        for (const ShapeRow& shape : kShapes) {
            if (!shape.hit) continue;
            for (float top : shape.type == ShapeType::Cone ? std::vector<float>{0.15f, 0.0f}
                                                           : std::vector<float>{0.0f}) {
                Object o;
                o.type = shape.type;
                o.radius = shape.type == ShapeType::Torus ? 0.3f : 0.4f;
                o.minor = 0.12f, o.height = 0.8f, o.top = top;
                o.size = {0.45f, 0.3f, 0.2f};
                o.pos = {-6.0f + 1.5f * float(n % 9), 1.2f - 1.2f * float(n / 9), 0.0f};
                o.rot = {37.0f * float(n % 5), 23.0f * float(n % 7), 11.0f * float(n % 3)};
                o.isStatic = true;
                s.objects.push_back(o);
                ++n;
            }
        }
    return s;
}

// Whether object id shows in ids within one pixel of (x, y).
bool besides(const Image& ids, int x, int y, int id) {
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int u = x + dx, v = y + dy;
            if (u >= 0 && v >= 0 && u < kW && v < kH && objectIdAt(ids, u, v) == id) return true;
        }
    return false;
}

// Whether the 3x3 block about (x, y) shows one object in ids.
bool inside(const Image& ids, int x, int y) {
    const int id = objectIdAt(ids, x, y);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int u = x + dx, v = y + dy;
            if (u < 0 || v < 0 || u >= kW || v >= kH || objectIdAt(ids, u, v) != id) return false;
        }
    return id >= 0;
}

int channelDifference(const Image& a, const Image& b, int x, int y) {
    int most = 0;
    for (int c = 0; c < 3; ++c)
        most = std::max(most, std::abs(a.pixel(x, y)[c] - b.pixel(x, y)[c]));
    return most;
}

// Where the exact hits draw an object, marching draws the same one, and inside it the same
// normals: the normal at a hit off the surface (a wrong root) turns. Marching alone may draw
// an object in a pixel the exact hit leaves empty, where the ray grazes its silhouette: it
// stops within epsilon of the surface, or runs out of steps there. Measured: 13 such pixels of
// 2,200 (8 objects), each beside the object's own pixels.
void expectHitsAsMarched(const Scene& s, int grid, const char* how) {
    RenderOptions exact = test::options(RenderMode::ObjectId), marched = exact;
    exact.quality.grid = grid;
    marched.quality.grid = 0;  // the object loop: every object marched
    marched.uber = true;
    const Image a = test::renderOrDie(s, exact, kW, kH), b = test::renderOrDie(s, marched, kW, kH);
    exact.mode = marched.mode = RenderMode::Normals;
    const Image na = test::renderOrDie(s, exact, kW, kH),
                nb = test::renderOrDie(s, marched, kW, kH);
    int drawn = 0, differ = 0, away = 0, grazing = 0, turned = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const int p = objectIdAt(a, x, y), q = objectIdAt(b, x, y);
            drawn += p >= 0;
            if (p >= 0 && q != p) ++differ;
            else if (p < 0 && q >= 0) ++(besides(a, x, y, q) ? grazing : away);
            else if (inside(a, x, y)) turned += channelDifference(na, nb, x, y) > kNormalTolerance;
        }
    std::printf(
        "%s: %zu objects, %d pixels drawn exactly, %d of them marched otherwise; %d "
        "marched alone, %d of them away from the object's edge; %d normals turned\n",
        how, s.objects.size(), drawn, differ, grazing + away, away, turned);
    EXPECT_GT(drawn, 1000) << how;
    EXPECT_EQ(differ, 0) << how;
    EXPECT_EQ(away, 0) << how;
    EXPECT_LE(turned, kMaxTurnedShare * drawn) << how;
}

}  // namespace

TEST(ExactHits, EveryShapeMetExactlyDrawsAsMarchedInLines) {
    expectHitsAsMarched(shapesWithHits(1), 0, "compiled");
}

TEST(ExactHits, EveryShapeMetExactlyDrawsAsMarchedThroughTheGrid) {
    expectHitsAsMarched(shapesWithHits(3), 1, "grid");
}
