// test_mesh.cpp — the mesher against closed forms: a sphere, a turned box and a carved cup come
// out closed, wound outward, every vertex within S/2 of the true surface, holding the volume
// they should; the run stops when asked, and refuses a grid too fine for the memory.
#include "mesh.h"

#include "marchbox/export/export.h"

#include "marchbox/scene/sdf.h"

#include <gtest/gtest.h>
#include <atomic>
#include <chrono>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <set>
#include <tuple>
#include <utility>

using namespace mb;
using glm::vec2;
using glm::vec3;

namespace {

constexpr double kPi = 3.14159265358979323846;

Object shape(ShapeType type, vec3 pos) {
    Object o;
    o.type = type;
    o.pos = pos;
    o.isStatic = true;
    return o;
}

Scene sceneOf(std::vector<Object> objects) {
    Scene scene;
    scene.materials.resize(2);
    scene.objects = std::move(objects);
    return scene;
}

TriangleMesh meshOf(const Scene& scene, double voxel) {
    MeshSettings settings;
    settings.voxel = voxel;
    TriangleMesh mesh;
    std::string why;
    EXPECT_EQ(meshSdf(makeSceneSdf(scene), settings, &mesh, &why), MeshStatus::Ok) << why;
    return mesh;
}

// Closed and consistently wound: each directed edge once, and its reverse once, so every edge
// has exactly two triangles, which cross it in opposite directions.
::testing::AssertionResult closedAndOriented(const TriangleMesh& m) {
    std::map<std::pair<unsigned, unsigned>, int> directed;
    for (const glm::uvec3& t : m.triangles) {
        if (t.x == t.y || t.y == t.z || t.z == t.x)
            return ::testing::AssertionFailure() << "a triangle repeats a corner";
        for (int c = 0; c < 3; ++c) ++directed[{t[c], t[(c + 1) % 3]}];
    }
    for (const auto& [edge, count] : directed) {
        auto reverse = directed.find({edge.second, edge.first});
        if (count != 1 || reverse == directed.end() || reverse->second != 1)
            return ::testing::AssertionFailure()
                   << "edge " << edge.first << "-" << edge.second << " runs " << count
                   << " times one way and " << (reverse == directed.end() ? 0 : reverse->second)
                   << " the other";
    }
    return ::testing::AssertionSuccess();
}

// V − E + F: 2 for a closed surface without handles, whatever its shape.
long eulerCharacteristic(const TriangleMesh& m) {
    return long(m.points.size()) - long(m.triangles.size()) * 3 / 2 + long(m.triangles.size());
}

// Outward: each triangle faces away from the solid, along the SDF's gradient at its centroid.
template <typename F>
size_t inwardTriangles(const TriangleMesh& m, F sdf) {
    size_t inward = 0;
    for (size_t t = 0; t < m.triangles.size(); ++t) {
        const glm::uvec3 tri = m.triangles[t];
        const vec3 c = (m.points[tri.x] + m.points[tri.y] + m.points[tri.z]) / 3.0f;
        const float h = 1e-3f;
        const vec3 grad(sdf(c + vec3(h, 0, 0)) - sdf(c - vec3(h, 0, 0)),
                        sdf(c + vec3(0, h, 0)) - sdf(c - vec3(0, h, 0)),
                        sdf(c + vec3(0, 0, h)) - sdf(c - vec3(0, 0, h)));
        if (glm::dot(faceNormal(m, t), grad) <= 0.0f) ++inward;
    }
    return inward;
}

// The distance from p to segment ab, in the plane.
float segmentDistance(vec2 p, vec2 a, vec2 b) {
    const vec2 ab = b - a;
    const float t = glm::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::length(p - (a + t * ab));
}

}  // namespace

// Tolerances. A vertex may be S/2 from the surface (the contract). The volume: triangles are
// chords of curved faces, whose corners lie in cells a 2x2x1 block apart at most (3S across),
// so a face of radius r sags inward by at most (3S)²/(8r), a relative volume of 3·(3S)²/(8r²)
// for a sphere; a sharp edge loses (convex) or gains (concave) at most the cells' corner along
// it, a right triangle of legs S: S²/2 per metre of edge.

// Points placed at known distances from a sphere of radius 1: 0.2 outside, 0.3 inside, on it.
// The largest is the inside one, so an error taken without its sign's |·| would say 0.2.
TEST(Mesh, LargestVertexErrorIsTheFarthestPointEitherSide) {
    const vec3 centre(0.3f, 1.2f, -0.7f);
    Object ball = shape(ShapeType::Sphere, centre);
    ball.radius = 1.0f;
    TriangleMesh m;
    m.points = {centre + vec3(1.2f, 0, 0), centre + vec3(0, -0.7f, 0), centre + vec3(0, 0, 1)};
    m.triangles = {{0, 1, 2}};
    // float rounding of the points, a few ulps of 1
    EXPECT_NEAR(largestVertexError(makeSceneSdf(sceneOf({ball})), m), 0.3f, 1e-6f);
    m.points.erase(m.points.begin() + 1);  // the inside one
    EXPECT_NEAR(largestVertexError(makeSceneSdf(sceneOf({ball})), m), 0.2f, 1e-6f);
}

TEST(Mesh, SphereIsClosedOutwardNearItsRadiusAndHoldsItsVolume) {
    const vec3 centre(0.3f, 1.2f, -0.7f);  // off the grid's lattice
    Object ball = shape(ShapeType::Sphere, centre);
    ball.radius = 1.0f;
    const double voxel = 1.0 / 32;
    const TriangleMesh m = meshOf(sceneOf({ball}), voxel);
    ASSERT_GT(m.triangles.size(), 1000u);
    EXPECT_TRUE(closedAndOriented(m));
    EXPECT_EQ(eulerCharacteristic(m), 2);
    auto sdf = [&](vec3 p) { return sdSphere(p - centre, 1.0f); };
    const float worst = largestVertexError(m, sdf);
    EXPECT_LE(worst, voxel / 2);
    EXPECT_EQ(inwardTriangles(m, sdf), 0u);
    const double exact = 4.0 / 3.0 * kPi, volume = meshVolume(m);
    std::printf("sphere: %zu triangles, worst vertex %.3f S off, volume %.6f of %.6f\n",
                m.triangles.size(), worst / voxel, volume, exact);
    EXPECT_NEAR(volume, exact, 3.0 * 9.0 * voxel * voxel / 8.0 * exact);
}

// A bead of 1 mm radius at its default voxel, 7.8 µm: OpenVDB refuses a grid scaled under about
// 1e-5, and the export ended in an uncaught exception (an abort, no file). Planted: the grid
// scaled by the voxel again.
TEST(Mesh, ABeadOfAMillimetreIsMeshedAtItsDefaultVoxel) {
    const vec3 centre(0.3f, 1.2f, -0.7f);
    Object bead = shape(ShapeType::Sphere, centre);
    bead.radius = 1e-3f;
    const Scene scene = sceneOf({bead});
    const double voxel = defaultVoxel(makeSceneSdf(scene));
    ASSERT_LT(voxel, 1e-5);
    const TriangleMesh m = meshOf(scene, 0.0);
    ASSERT_GT(m.triangles.size(), 1000u);
    EXPECT_TRUE(closedAndOriented(m));
    auto sdf = [&](vec3 p) { return sdSphere(p - centre, 1e-3f); };
    EXPECT_LE(largestVertexError(m, sdf), voxel / 2);
    EXPECT_EQ(inwardTriangles(m, sdf), 0u);
}

TEST(Mesh, TurnedBoxIsClosedOutwardNearItsFacesAndHoldsItsVolume) {
    Object box = shape(ShapeType::Box, vec3(-1.1f, 0.4f, 2.3f));
    box.size = vec3(0.5f, 0.3f, 0.4f);
    box.rot = vec3(20, 30, 10);
    const double voxel = 1.0 / 64;
    const Scene scene = sceneOf({box});
    const SdfObject solid = makeSdfObject(box);
    const TriangleMesh m = meshOf(scene, voxel);
    EXPECT_TRUE(closedAndOriented(m));
    EXPECT_EQ(eulerCharacteristic(m), 2);
    auto sdf = [&](vec3 p) { return sdObject(solid, p); };  // exact for a box
    const float worst = largestVertexError(m, sdf);
    EXPECT_LE(worst, voxel / 2);
    EXPECT_EQ(inwardTriangles(m, sdf), 0u);
    const vec3 s = box.size;
    const double exact = 8.0 * s.x * s.y * s.z, volume = meshVolume(m);
    const double edges = 8.0 * (s.x + s.y + s.z);
    std::printf("box: %zu triangles, worst vertex %.3f S off, volume %.6f of %.6f\n",
                m.triangles.size(), worst / voxel, volume, exact);
    EXPECT_NEAR(volume, exact, edges * voxel * voxel / 2);
}

// A domino of dominoes.txt, 4.6 voxels thick at the scene's default voxel and off the grid's
// lattice: volumeToMesh put a vertex 0.56 S from its surface near an edge, past the S/2 every
// vertex is promised. Each of the six thicknesses and offsets tried must keep it.
TEST(Mesh, ThinBoxesKeepEveryVertexWithinHalfAVoxel) {
    const double voxel = 0.0175;
    for (int k = 0; k < 6; ++k) {
        Object domino = shape(ShapeType::Box, vec3(0.2f * k + 0.013f * k, 0.3f, 0.0071f * k));
        domino.size = vec3(0.04f + 0.003f * k, 0.3f, 0.15f);
        const SdfObject solid = makeSdfObject(domino);
        const TriangleMesh m = meshOf(sceneOf({domino}), voxel);
        EXPECT_TRUE(closedAndOriented(m)) << k;
        auto sdf = [&](vec3 p) { return sdObject(solid, p); };
        EXPECT_LE(largestVertexError(m, sdf), voxel / 2) << "domino " << k;
        EXPECT_EQ(inwardTriangles(m, sdf), 0u) << k;
    }
}

// A cup as the scene format's example has it: a cylinder carved by a narrower one raised 6 cm,
// both members of a group, so the hole stops 6 cm above the bottom.
TEST(Mesh, CarvedCupHasItsHole) {
    Scene scene;
    scene.materials.resize(1);
    Group cup;
    cup.name = "cup";
    cup.pos = vec3(0.2f, 0.9f, -0.1f);
    cup.isStatic = true;
    scene.groups.push_back(cup);
    Object wall = shape(ShapeType::Cylinder, vec3(0.0f));
    wall.radius = 0.5f;
    wall.height = 0.8f;
    wall.isStatic = false;
    wall.group = 0;
    Object hole = wall;
    hole.pos = vec3(0, 0.06f, 0);
    hole.radius = 0.44f;
    hole.op = CsgOp::Subtract;
    scene.objects = {wall, hole};
    const double voxel = 1.0 / 128;
    const TriangleMesh m = meshOf(scene, voxel);
    EXPECT_TRUE(closedAndOriented(m));
    EXPECT_EQ(eulerCharacteristic(m), 2);  // a hole that does not go through: no handle
    // The exact distance: the cup is the cross-section below turned about its axis.
    auto distance = [&](vec3 p) {
        const vec3 q = p - cup.pos;
        const vec2 r(glm::length(vec2(q.x, q.z)), q.y);
        const vec2 outline[] = {{0, -0.4f},    {0.5f, -0.4f},   {0.5f, 0.4f},
                                {0.44f, 0.4f}, {0.44f, -0.34f}, {0, -0.34f}};
        float d = 1e30f;
        for (int i = 0; i + 1 < 6; ++i)
            d = std::min(d, segmentDistance(r, outline[i], outline[i + 1]));
        return d;
    };
    const float worst = largestVertexError(m, distance);
    EXPECT_LE(worst, voxel / 2);
    const SceneSdf sdf = makeSceneSdf(scene);
    EXPECT_EQ(inwardTriangles(m, [&](vec3 p) { return mapObjects(sdf, p).d; }), 0u);
    // The wall's inside: vertices at the hole's radius, from its floor up to the rim.
    size_t inner = 0;
    for (const vec3& p : m.points) {
        const vec3 q = p - cup.pos;
        if (std::abs(glm::length(vec2(q.x, q.z)) - 0.44f) < voxel && q.y > -0.3f && q.y < 0.35f)
            ++inner;
    }
    EXPECT_GT(inner, 1000u);
    const double exact = kPi * (0.5 * 0.5 * 0.8 - 0.44 * 0.44 * 0.74), volume = meshVolume(m);
    const double edges = 2 * kPi * (0.5 + 0.5 + 0.44 + 0.44);
    const double sag = 3.0 * 9.0 * voxel * voxel / 8.0 / 0.44;  // of the curved walls' area
    const double walls = 2 * kPi * (0.5 * 0.8 + 0.44 * 0.74);
    std::printf(
        "cup: %zu triangles, worst vertex %.3f S off, volume %.6f of %.6f (uncarved %.6f)\n",
        m.triangles.size(), worst / voxel, volume, exact, kPi * 0.2);
    EXPECT_NEAR(volume, exact, edges * voxel * voxel / 2 + walls * sag);
}

// Shapes with a handle: a torus, and a box with a round hole bored through it. Each mesh is
// closed and oriented with the Euler characteristic of genus 1 (0), every vertex within S/2,
// and its volume within 1% of the closed form.
TEST(Mesh, TorusHasOneHandleAndHoldsItsVolume) {
    Object ring = shape(ShapeType::Torus, vec3(0.1f, 0.7f, -0.3f));
    ring.radius = 0.8f;
    ring.minor = 0.25f;
    ring.rot = vec3(30, 0, 10);
    const double voxel = 1.0 / 64;
    const TriangleMesh m = meshOf(sceneOf({ring}), voxel);
    EXPECT_TRUE(closedAndOriented(m));
    EXPECT_EQ(eulerCharacteristic(m), 0);
    const SdfObject solid = makeSdfObject(ring);
    EXPECT_LE(largestVertexError(m, [&](vec3 p) { return sdObject(solid, p); }), voxel / 2);
    const double exact = 2.0 * kPi * kPi * 0.8 * 0.25 * 0.25;
    EXPECT_NEAR(meshVolume(m), exact, 0.01 * exact);
}

// A torus of a 0.1 m tube at S = 5 mm, where volumeToMesh gave 8 pairs of vertices one position
// each: no two vertices share a position, so a tool that joins an STL's vertices by position
// sees the same closed surface. Planted: the pairs left apart (16 triangles flat by position,
// and their edges shared three ways).
TEST(Mesh, NoTwoVerticesShareAPosition) {
    Object ring = shape(ShapeType::Torus, vec3(0.0f));
    ring.radius = 0.5f;
    ring.minor = 0.1f;
    const TriangleMesh m = meshOf(sceneOf({ring}), 0.005);
    EXPECT_TRUE(closedAndOriented(m));
    std::set<std::tuple<float, float, float>> places;
    for (const vec3& p : m.points) places.insert({p.x, p.y, p.z});
    EXPECT_EQ(places.size(), m.points.size()) << "vertices at one position";
}

TEST(Mesh, HoledBoxHasOneHandleAndHoldsItsVolume) {
    Object box = shape(ShapeType::Box, vec3(0.3f, 0.6f, 0.1f));
    box.size = vec3(0.5f, 0.4f, 0.5f);
    Object bore = shape(ShapeType::Cylinder, box.pos);
    bore.radius = 0.2f;
    bore.height = 1.2f;  // through the box's 0.8 m and out both sides
    bore.op = CsgOp::Subtract;
    const double voxel = 1.0 / 64;
    const Scene scene = sceneOf({box, bore});
    const TriangleMesh m = meshOf(scene, voxel);
    EXPECT_TRUE(closedAndOriented(m));
    EXPECT_EQ(eulerCharacteristic(m), 0);
    const SceneSdf sdf = makeSceneSdf(scene);  // a bound: |f| is at most the distance
    EXPECT_LE(largestVertexError(sdf, m), voxel / 2);
    const double exact = 1.0 * 0.8 * 1.0 - kPi * 0.2 * 0.2 * 0.8;
    EXPECT_NEAR(meshVolume(m), exact, 0.01 * exact);
}

TEST(Mesh, DefaultVoxelIsTheLongestSideOver256) {
    Object box = shape(ShapeType::Box, vec3(1, 2, 3));
    box.size = vec3(0.5f, 2.0f, 1.0f);
    const SceneSdf sdf = makeSceneSdf(sceneOf({box}));
    const Box b = objectBounds(sdf);
    EXPECT_FLOAT_EQ(defaultVoxel(sdf), (b.hi.y - b.lo.y) / 256.0f);
    EXPECT_EQ(defaultVoxel(makeSceneSdf(sceneOf({}))), 0.0f);
}

TEST(Mesh, NothingToMeshGivesAnEmptyMesh) {
    EXPECT_TRUE(meshOf(sceneOf({}), 0.1).empty());
    Object grain = shape(ShapeType::Sphere, vec3(0.05f));
    grain.radius = 0.01f;
    EXPECT_TRUE(meshOf(sceneOf({grain}), 1.0).empty());  // thinner than a voxel
}

TEST(Mesh, StopsWhenAsked) {
    Object ball = shape(ShapeType::Sphere, vec3(0));
    MeshSettings settings;
    settings.voxel = 1.0 / 256;
    std::atomic<int> polls{0};  // polled from the sampling threads
    settings.stop = [&] { return ++polls > 3; };
    TriangleMesh mesh;
    std::string why;
    EXPECT_EQ(meshSdf(makeSceneSdf(sceneOf({ball})), settings, &mesh, &why), MeshStatus::Stopped);
    EXPECT_TRUE(mesh.empty());
}

// A voxel a millionth of the scene would need a band of ~10¹³ voxels: refused at once, with
// what it would take, before any grid is allocated.
TEST(Mesh, RefusesAGridTooLargeForTheMemory) {
    Object ball = shape(ShapeType::Sphere, vec3(0));
    for (double voxel : {1e-6, 1e-4}) {
        MeshSettings settings;
        settings.voxel = voxel;
        settings.memoryBudget = size_t(64) << 20;  // 64 MiB: 1e-4 needs ~2 GiB
        TriangleMesh mesh;
        std::string why;
        const auto start = std::chrono::steady_clock::now();
        EXPECT_EQ(meshSdf(makeSceneSdf(sceneOf({ball})), settings, &mesh, &why),
                  MeshStatus::TooLarge);
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                  5.0);
        EXPECT_NE(why.find("too small"), std::string::npos) << why;
        EXPECT_EQ(why.find('\n'), std::string::npos) << why;
    }
}

TEST(Mesh, MaterialsAreTheObjectsTheRendererShades) {
    Object red = shape(ShapeType::Sphere, vec3(-0.4f, 0, 0));
    red.material = 0;
    Object blue = shape(ShapeType::Box, vec3(0.4f, 0, 0));
    blue.material = 1;
    Object carve = shape(ShapeType::Sphere, vec3(0.4f, 0.5f, 0));  // carves blue, shown in red
    carve.radius = 0.3f;
    carve.op = CsgOp::Subtract;
    carve.material = 0;
    const Scene scene = sceneOf({red, blue, carve});
    const SceneSdf sdf = makeSceneSdf(scene);
    const TriangleMesh m = meshOf(scene, 1.0 / 64);
    const std::vector<int> materials = triangleMaterials(scene, sdf, m);
    const std::vector<int> points = pointMaterials(scene, sdf, m);
    ASSERT_EQ(materials.size(), m.triangles.size());
    ASSERT_EQ(points.size(), m.points.size());
    // Independently of mapObjects: the union shows the nearer solid; the carved face of the box
    // shows the carving sphere's material. Triangles within a millimetre of a tie are left out.
    size_t checked = 0;
    for (size_t t = 0; t < m.triangles.size(); ++t) {
        const glm::uvec3 tri = m.triangles[t];
        const vec3 c = (m.points[tri.x] + m.points[tri.y] + m.points[tri.z]) / 3.0f;
        const float dRed = sdSphere(c - red.pos, 0.5f), dBox = sdBox(c - blue.pos, vec3(0.5f)),
                    dCarve = -sdSphere(c - carve.pos, 0.3f), dBlue = std::max(dBox, dCarve);
        if (std::abs(dRed - dBlue) < 1e-3f || std::abs(dBox - dCarve) < 1e-3f) continue;
        const int want = dRed < dBlue ? 0 : dCarve > dBox ? 0 : 1;
        ASSERT_EQ(materials[t], want) << "triangle at " << c.x << "," << c.y << "," << c.z;
        ++checked;
    }
    EXPECT_GT(checked, m.triangles.size() * 9 / 10);
    for (size_t i = 0; i < m.points.size(); ++i)
        ASSERT_EQ(points[i], materialAt(scene, sdf, m.points[i]));
}

// The editor's estimate, told before an export runs, is 3·area/S² for the solids' bounding
// spheres (3/2 voxel faces crossed a voxel's area, on average over a sphere's directions, two
// triangles each): a sphere's own, 12π/S². The mesher's count is within a tenth of it.
TEST(Mesh, TheEstimateCountsASpheresTriangles) {
    Object ball = shape(ShapeType::Sphere, vec3(0.3f, 1.2f, -0.7f));
    ball.radius = 1.0f;
    const double voxel = 1.0 / 32;
    const Scene scene = sceneOf({ball});
    const ExportEstimate e = estimateExport(scene, voxel);
    EXPECT_EQ(e.voxel, voxel);
    EXPECT_NEAR(e.triangles, 12.0 * kPi / (voxel * voxel), 1.0);
    const double made = double(meshOf(scene, voxel).triangles.size());
    EXPECT_NEAR(made / e.triangles, 1.0, 0.1);
    EXPECT_GT(e.bytes, 0.0);
}
