// mesh.cpp — the narrow band, sampled top-down over blocks in parallel, and OpenVDB's mesher.
#include "mesh.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/SignedFloodFill.h>
#include <openvdb/tools/VolumeToMesh.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <functional>
#include <memory>
#include <unordered_map>
#include <unistd.h>

namespace mb {

//-----------------------------------------------------------------------------
// [SECTION] The mesh
//-----------------------------------------------------------------------------
glm::vec3 faceNormal(const TriangleMesh& m, size_t t) {
    const glm::uvec3 tri = m.triangles[t];
    const glm::vec3 a = m.points[tri.x], b = m.points[tri.y], c = m.points[tri.z];
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float len = glm::length(n);
    return len > 0.0f ? n / len : glm::vec3(0.0f);
}

std::vector<glm::vec3> pointNormals(const TriangleMesh& m) {
    std::vector<glm::vec3> n(m.points.size(), glm::vec3(0.0f));
    for (const glm::uvec3& tri : m.triangles) {
        const glm::vec3 a = m.points[tri.x], b = m.points[tri.y], c = m.points[tri.z];
        const glm::vec3 w = glm::cross(b - a, c - a);  // twice the area, along the normal
        n[tri.x] += w, n[tri.y] += w, n[tri.z] += w;
    }
    for (glm::vec3& v : n) {
        const float len = glm::length(v);
        v = len > 0.0f ? v / len : glm::vec3(0, 1, 0);
    }
    return n;
}

// V = Σ a·(b × c) / 6 over the triangles, about the mesh's first point so that a mesh far from
// the origin keeps its digits.
double meshVolume(const TriangleMesh& m) {
    if (m.points.empty()) return 0.0;
    const glm::dvec3 o(m.points[0]);
    double v = 0.0;
    for (const glm::uvec3& tri : m.triangles) {
        const glm::dvec3 a = glm::dvec3(m.points[tri.x]) - o, b = glm::dvec3(m.points[tri.y]) - o,
                         c = glm::dvec3(m.points[tri.z]) - o;
        v += glm::dot(a, glm::cross(b, c));
    }
    return v / 6.0;
}

float largestVertexError(const TriangleMesh& m, const std::function<float(glm::vec3)>& distance) {
    float largest = 0.0f;
    for (const glm::vec3& p : m.points) largest = std::max(largest, std::abs(distance(p)));
    return largest;
}

float largestVertexError(const SceneSdf& sdf, const TriangleMesh& m) {
    return largestVertexError(m, [&](glm::vec3 p) { return mapObjects(sdf, p).d; });
}

//-----------------------------------------------------------------------------
// [SECTION] Meshing an SDF
//-----------------------------------------------------------------------------
float defaultVoxel(const SceneSdf& sdf) {
    const Box b = objectBounds(sdf);
    if (b.empty()) return 0.0f;
    const glm::vec3 side = b.hi - b.lo;
    return std::max({side.x, side.y, side.z}) / 256.0f;
}

namespace {

using openvdb::Coord;
using FloatLeaf = openvdb::FloatTree::LeafNodeType;
constexpr int kLeafSide = int(FloatLeaf::DIM);  // 8

// What one stored leaf costs at the peak, all told: its 8³ floats and masks (2.1 KiB), the
// mesher's grids of the same topology, and the mesh it yields (about 64 surface cells, each a
// point and a quad, then two triangles and a file's bytes). Measured on scenes/default.txt:
// see the export commit.
constexpr size_t kBytesPerLeaf = 16 * 1024;
// Voxel indices stay far inside int32, whatever the scene's size against the voxel.
constexpr double kMaxVoxelsPerSide = double(1 << 26);
// Blocks this large (in voxels) or larger split across threads; smaller ones run where they are.
constexpr int kParallelBlock = 64;

// The band: SDF values at voxel centres, voxel (0,0,0)'s centre at `origin`.
struct Band {
    const SceneSdf& sdf;
    glm::dvec3 origin;
    double voxel;
    float width;  // kBandVoxels · voxel: the level set's background value

    // The SDF at the centre of the size³ block of voxels from o, and how far that centre is
    // from the block's farthest voxel centre, plus the band: a block whose |f| is at least this
    // has no voxel within the band, and one sign throughout.
    float atCentre(const Coord& o, int size) const {
        const double h = 0.5 * (size - 1);
        const glm::dvec3 p = origin + voxel * (glm::dvec3(o.x(), o.y(), o.z()) + h);
        return mapObjects(sdf, glm::vec3(p)).d;
    }
    float reach(int size) const { return float(std::sqrt(3.0) * 0.5 * (size - 1) * voxel) + width; }
};

// Phase 1: the leaves the band may touch, found top-down. Stops early past `maxLeaves`.
class LeafFinder {
public:
    LeafFinder(const Band& band, size_t maxLeaves, const std::function<bool()>& stop)
        : band_(band), maxLeaves_(maxLeaves), stop_(stop) {}

    void visit(const Coord& o, int size) {
        if (found_ > maxLeaves_ || stopped_) return;
        if (size >= kParallelBlock && stop_ && stop_()) {
            stopped_ = true;
            return;
        }
        if (std::abs(band_.atCentre(o, size)) >= band_.reach(size)) return;
        if (size == kLeafSide) {
            leaves_.local().push_back(o);
            ++found_;
            return;
        }
        const int h = size / 2;
        auto child = [&](int i) {
            visit(o.offsetBy((i & 1) * h, (i >> 1 & 1) * h, (i >> 2) * h), h);
        };
        if (size >= kParallelBlock) tbb::parallel_for(0, 8, child);
        else
            for (int i = 0; i < 8; ++i) child(i);
    }

    bool over() const { return found_ > maxLeaves_; }
    bool stopped() const { return stopped_; }
    size_t found() const { return found_; }
    // In a fixed order, whichever thread found them, so the rest of the run is reproducible.
    std::vector<Coord> leaves() {
        std::vector<Coord> all;
        for (const std::vector<Coord>& part : leaves_)
            all.insert(all.end(), part.begin(), part.end());
        std::sort(all.begin(), all.end());
        return all;
    }

private:
    const Band& band_;
    size_t maxLeaves_;
    const std::function<bool()>& stop_;
    std::atomic<size_t> found_{0};
    std::atomic<bool> stopped_{false};
    tbb::enumerable_thread_specific<std::vector<Coord>> leaves_;
};

// Phase 2: one leaf's voxels. A block that the band misses takes ±width, inactive, at once;
// the others split down to single voxels, which keep their value, active.
void fillBlock(const Band& band, FloatLeaf& leaf, const Coord& o, int size) {
    const float f = band.atCentre(o, size);
    if (std::abs(f) >= band.reach(size)) {
        if (f < 0.0f)  // the leaf starts outside (+width); only the inside needs writing
            for (int x = 0; x < size; ++x)
                for (int y = 0; y < size; ++y)
                    for (int z = 0; z < size; ++z)
                        leaf.setValueOff(o.offsetBy(x, y, z), -band.width);
        return;
    }
    if (size == 1) {
        leaf.setValueOn(o, f);
        return;
    }
    const int h = size / 2;
    for (int i = 0; i < 8; ++i)
        fillBlock(band, leaf, o.offsetBy((i & 1) * h, (i >> 1 & 1) * h, (i >> 2) * h), h);
}

size_t physicalMemory() {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? size_t(pages) * size_t(page) : size_t(8) << 30;
}

std::string gib(double bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GiB", bytes / double(1 << 30));
    return text;
}

std::string tooLarge(double voxel, double bytes, size_t budget) {
    char v[32];
    std::snprintf(v, sizeof v, "%g", voxel);
    return std::string("a voxel of ") + v + " m is too small for this scene: its grid would need " +
           (bytes > 0 ? "about " + gib(bytes) : "more memory than there is") + ", and " +
           gib(double(budget)) + " is the limit (half the memory)";
}

// volumeToMesh's quads, each split along its shorter diagonal, and its triangles; its points
// are in voxels from voxel (0,0,0)'s centre, `origin`.
void collectTriangles(const std::vector<openvdb::Vec3s>& points,
                      const std::vector<openvdb::Vec3I>& tris,
                      const std::vector<openvdb::Vec4I>& quads, const glm::dvec3& origin,
                      double voxel, TriangleMesh* out) {
    out->points.resize(points.size());
    for (size_t i = 0; i < points.size(); ++i)
        out->points[i] =
            glm::vec3(origin + voxel * glm::dvec3(points[i].x(), points[i].y(), points[i].z()));
    out->triangles.reserve(tris.size() + 2 * quads.size());
    // OpenVDB winds its polygons clockwise seen from outside; the mesh's are counter-clockwise.
    for (const openvdb::Vec3I& t : tris) out->triangles.emplace_back(t[0], t[2], t[1]);
    for (const openvdb::Vec4I& q : quads) {
        const glm::vec3 a = out->points[q[0]], b = out->points[q[1]], c = out->points[q[2]],
                        d = out->points[q[3]];
        if (glm::distance(a, c) <= glm::distance(b, d)) {
            out->triangles.emplace_back(q[0], q[2], q[1]);
            out->triangles.emplace_back(q[0], q[3], q[2]);
        } else {
            out->triangles.emplace_back(q[0], q[3], q[1]);
            out->triangles.emplace_back(q[1], q[3], q[2]);
        }
    }
}

// volumeToMesh puts each vertex at the mean of its voxel's edge crossings, which beside an edge
// or a corner can lie past S/2 from the surface (0.56 S on a domino of dominoes.txt). Such a
// vertex is pulled along the gradient toward the surface, a Newton step of the distance at a
// time (a bound's step falls short, hence up to four), until within 0.45 S; the rest stay.
void pullNearSurface(const SceneSdf& sdf, double voxel, TriangleMesh* m) {
    const float limit = 0.45f * float(voxel), h = 0.05f * float(voxel);
    const auto f = [&](glm::vec3 p) { return mapObjects(sdf, p).d; };
    tbb::parallel_for(size_t(0), m->points.size(), [&](size_t i) {
        glm::vec3& p = m->points[i];
        for (int step = 0; step < 4; ++step) {
            const float d = f(p);
            if (std::abs(d) <= limit) return;
            const glm::vec3 g(f(p + glm::vec3(h, 0, 0)) - f(p - glm::vec3(h, 0, 0)),
                              f(p + glm::vec3(0, h, 0)) - f(p - glm::vec3(0, h, 0)),
                              f(p + glm::vec3(0, 0, h)) - f(p - glm::vec3(0, 0, h)));
            const float length = glm::length(g);
            if (!(length > 0.0f)) return;
            p -= d * g / length;
        }
    });
}

// volumeToMesh can give two vertices one position (16 triangles of a torus of 0.1 m tube at
// S = 5 mm spanned such a pair). Tools that join an STL's vertices by position then find those
// triangles flat and their edges shared three ways. Each such pair becomes one vertex, and the
// triangles it collapses are dropped: the surface about them closes, as it does by position.
void weldCoincidentPoints(TriangleMesh* m) {
    struct Hash {
        size_t operator()(const glm::vec3& p) const {
            const std::hash<float> h;
            return h(p.x) ^ (h(p.y) * 0x9e3779b97f4a7c15ull) ^ (h(p.z) * 0xc2b2ae3d27d4eb4full);
        }
    };
    std::unordered_map<glm::vec3, unsigned, Hash> placed;
    std::vector<glm::vec3> points;
    std::vector<unsigned> to(m->points.size());
    for (size_t i = 0; i < m->points.size(); ++i) {
        const auto [at, fresh] = placed.emplace(m->points[i], unsigned(points.size()));
        if (fresh) points.push_back(m->points[i]);
        to[i] = at->second;
    }
    m->points = std::move(points);
    for (glm::uvec3& t : m->triangles) t = glm::uvec3(to[t.x], to[t.y], to[t.z]);
    std::erase_if(m->triangles,
                  [](const glm::uvec3& t) { return t.x == t.y || t.y == t.z || t.z == t.x; });
}

}  // namespace

MeshStatus meshSdf(const SceneSdf& sdf, const MeshSettings& settings, TriangleMesh* out,
                   std::string* why) {
    *out = TriangleMesh{};
    const Box bounds = objectBounds(sdf);
    const double voxel = settings.voxel > 0.0 ? settings.voxel : defaultVoxel(sdf);
    if (bounds.empty() || !(voxel > 0.0)) return MeshStatus::Ok;
    const size_t budget = settings.memoryBudget ? settings.memoryBudget : physicalMemory() / 2;
    const size_t maxLeaves = budget / kBytesPerLeaf;

    // The grid: the bounds, padded by the band and one voxel, in a cube of 2^k voxels.
    const double pad = kBandVoxels + 1.0;
    const glm::dvec3 lo = glm::dvec3(bounds.lo) - pad * voxel;
    const glm::dvec3 side = (glm::dvec3(bounds.hi) - glm::dvec3(bounds.lo)) / voxel + 2.0 * pad;
    const double longest = std::max({side.x, side.y, side.z});
    if (!(longest < kMaxVoxelsPerSide)) {
        *why = tooLarge(voxel, 0.0, budget);
        return MeshStatus::TooLarge;
    }
    int root = kLeafSide;
    while (root < longest) root *= 2;

    const Band band{sdf, lo, voxel, float(kBandVoxels * voxel)};
    LeafFinder finder(band, maxLeaves, settings.stop);
    finder.visit(Coord(0, 0, 0), root);
    if (finder.stopped()) return MeshStatus::Stopped;
    if (finder.over()) {
        *why = tooLarge(voxel, 0.0, budget);
        return MeshStatus::TooLarge;
    }
    const std::vector<Coord> origins = finder.leaves();

    // Phase 2, in a hundred slices for the progress line; the stop flag is polled every leaf.
    std::vector<std::unique_ptr<FloatLeaf>> leaves(origins.size());
    constexpr size_t kSlices = 100;
    for (size_t s = 0; s < kSlices; ++s) {
        if (settings.stop && settings.stop()) return MeshStatus::Stopped;
        tbb::parallel_for(tbb::blocked_range<size_t>(s * origins.size() / kSlices,
                                                     (s + 1) * origins.size() / kSlices),
                          [&](const tbb::blocked_range<size_t>& r) {
                              for (size_t i = r.begin(); i < r.end(); ++i) {
                                  if (settings.stop && settings.stop()) return;
                                  auto leaf = std::make_unique<FloatLeaf>(origins[i], band.width);
                                  fillBlock(band, *leaf, origins[i], kLeafSide);
                                  if (!leaf->isEmpty()) leaves[i] = std::move(leaf);
                              }
                          });
        if (settings.progress) settings.progress(double(s + 1) / kSlices);
    }

    // The grid's own transform is the identity: OpenVDB refuses a scale under about 1e-5 (a
    // 2 mm bead's default voxel threw, uncaught), so its points come back in voxels and are
    // placed in the world here.
    openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(band.width);
    grid->setGridClass(openvdb::GRID_LEVEL_SET);
    for (std::unique_ptr<FloatLeaf>& leaf : leaves)
        if (leaf) grid->tree().addLeaf(leaf.release());
    leaves.clear();
    // The inside, away from the band, takes −width: the band's signs spread into the tiles.
    openvdb::tools::signedFloodFill(grid->tree());

    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec3I> tris;
    std::vector<openvdb::Vec4I> quads;
    if (settings.stop && settings.stop()) return MeshStatus::Stopped;  // the mesher cannot stop
    openvdb::tools::volumeToMesh(*grid, points, tris, quads, 0.0, 0.0);
    grid.reset();
    collectTriangles(points, tris, quads, lo, voxel, out);
    pullNearSurface(sdf, voxel, out);
    weldCoincidentPoints(out);
    return MeshStatus::Ok;
}

//-----------------------------------------------------------------------------
// [SECTION] Materials on the surface
//-----------------------------------------------------------------------------
int materialAt(const Scene& scene, const SceneSdf& sdf, glm::vec3 p) {
    const SceneSample s = mapObjects(sdf, p);
    if (s.object < 0 || size_t(s.object) >= scene.objects.size()) return -1;
    const int m = scene.objects[size_t(s.object)].material;
    return m >= 0 && size_t(m) < scene.materials.size() ? m : -1;
}

std::vector<int> pointMaterials(const Scene& scene, const SceneSdf& sdf, const TriangleMesh& m) {
    std::vector<int> out(m.points.size());
    tbb::parallel_for(size_t(0), out.size(),
                      [&](size_t i) { out[i] = materialAt(scene, sdf, m.points[i]); });
    return out;
}

std::vector<int> triangleMaterials(const Scene& scene, const SceneSdf& sdf, const TriangleMesh& m) {
    std::vector<int> out(m.triangles.size());
    tbb::parallel_for(size_t(0), out.size(), [&](size_t i) {
        const glm::uvec3 t = m.triangles[i];
        out[i] = materialAt(scene, sdf, (m.points[t.x] + m.points[t.y] + m.points[t.z]) / 3.0f);
    });
    return out;
}

}  // namespace mb
