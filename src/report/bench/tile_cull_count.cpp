// tile_cull_count.cpp — whether screen tiles would pay for the primary rays of plain members:
// the candidates a ray tests walking their grid (shaders/intersect.glsl's hitPlainMembers),
// against those its 16x16 tile would list (each member whose bounding sphere's screen box
// touches the tile), in full and front to back with an early end.
//
//   tile_cull_count SCENE.txt [WIDTH HEIGHT]     (default 480 270)
//
// Balls and boxes are met exactly, other shapes by their bounding spheres: a count, not a picture.
#include "marchbox/gl/plain_members.h"
#include "marchbox/scene/camera.h"
#include "marchbox/scene/scene_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace {

using namespace mb;

constexpr int kTile = 16;
constexpr float kFar = 1e30f;

// Where the ray enters the ball of radius r at c: -1 for a miss.
float hitBall(glm::vec3 ro, glm::vec3 rd, glm::vec3 c, float r) {
    glm::vec3 oc = ro - c;
    float b = glm::dot(oc, rd), h = b * b - glm::dot(oc, oc) + r * r;
    if (h < 0.0f || -b + std::sqrt(h) < 0.0f) return -1.0f;
    return std::max(-b - std::sqrt(h), 0.0f);
}

// 1 / v with no infinity, as the shader's safeInverse.
glm::vec3 safeInverse(glm::vec3 v) {
    glm::vec3 sign(v.x >= 0 ? 1 : -1, v.y >= 0 ? 1 : -1, v.z >= 0 ? 1 : -1);
    return 1.0f / (sign * glm::max(glm::abs(v), glm::vec3(1e-20f)));
}

float hit(const SdfObject& o, glm::vec3 ro, glm::vec3 rd) {
    if (o.type != ShapeType::Box)
        return hitBall(ro, rd, o.pos, o.type == ShapeType::Sphere ? o.radius : o.bound);
    glm::vec3 q = o.toLocal * (ro - o.pos), inv = safeInverse(o.toLocal * rd);
    glm::vec3 a = (-o.size - q) * inv, b = (o.size - q) * inv, lo = glm::min(a, b),
              hi = glm::max(a, b);
    float enter = std::max({lo.x, lo.y, lo.z}), exit = std::min({hi.x, hi.y, hi.z});
    return enter > exit || exit < 0.0f ? -1.0f : std::max(enter, 0.0f);
}

struct WalkCount {
    int cells = 0, tested = 0;
};

// The shader's walk (Amanatides & Woo 1987) up to far: cells visited and candidates tested
// until a cell holds the hit.
WalkCount gridCandidates(const SceneSdf& sdf, const ObjectGrid& g, glm::vec3 ro, glm::vec3 rd,
                         float far) {
    glm::vec3 size = glm::vec3(g.dims) * g.cellSize, inv = safeInverse(rd);
    glm::vec3 a = (g.origin - ro) * inv, b = (g.origin + size - ro) * inv;
    float enter = std::max(glm::max(glm::min(a, b).x, glm::min(a, b).y), glm::min(a, b).z);
    float exit = std::min(glm::min(glm::max(a, b).x, glm::max(a, b).y), glm::max(a, b).z);
    enter = std::max(enter, 0.0f), exit = std::min(exit, far);
    if (enter > exit) return {};
    glm::ivec3 cell = glm::clamp(glm::ivec3(glm::floor((ro + rd * enter - g.origin) / g.cellSize)),
                                 glm::ivec3(0), g.dims - 1);
    glm::ivec3 stepDir(rd.x >= 0 ? 1 : -1, rd.y >= 0 ? 1 : -1, rd.z >= 0 ? 1 : -1);
    glm::vec3 tDelta = glm::abs(g.cellSize * inv);
    glm::vec3 tNext = (g.origin + (glm::vec3(cell) + glm::step(0.0f, rd)) * g.cellSize - ro) * inv;
    WalkCount n;
    float best = kFar;
    for (int i = 0; i < g.dims.x + g.dims.y + g.dims.z; ++i, ++n.cells) {
        int c = (cell.z * g.dims.y + cell.y) * g.dims.x + cell.x;
        for (uint32_t k = g.cellStart[size_t(c)]; k < g.cellStart[size_t(c) + 1]; ++k, ++n.tested) {
            float t = hit(sdf.objects[g.items[k]], ro, rd);
            if (t >= 0.0f) best = std::min(best, t);
        }
        float cellExit = std::min({tNext.x, tNext.y, tNext.z});
        if (best <= cellExit || cellExit >= exit) break;
        glm::ivec3 move = glm::ivec3(glm::lessThanEqual(tNext, glm::vec3(cellExit)));
        cell += move * stepDir;
        tNext += glm::vec3(move) * tDelta;
        if (glm::any(glm::lessThan(cell, glm::ivec3(0))) ||
            glm::any(glm::greaterThanEqual(cell, g.dims)))
            break;
    }
    ++n.cells;  // the cell the loop left in
    return n;
}

struct Tiles {
    int across, down;
    std::vector<std::vector<int>> lists;  // members, nearest bounding sphere first
};

// Each member goes into every tile its bounding sphere's screen box touches: the box of its
// axis-aligned bounding box's corners, or every tile when one is behind the camera.
Tiles buildTiles(const SceneSdf& sdf, const std::vector<bool>& plain, const CameraBasis& cam, int w,
                 int h) {
    Tiles tiles{(w + kTile - 1) / kTile, (h + kTile - 1) / kTile, {}};
    tiles.lists.resize(size_t(tiles.across * tiles.down));
    std::vector<int> order;
    for (int i = 0; i < int(sdf.objects.size()); ++i)
        if (plain[size_t(i)]) order.push_back(i);
    auto nearest = [&](int i) {
        return glm::length(sdf.objects[size_t(i)].pos - cam.pos) - sdf.objects[size_t(i)].bound;
    };
    std::sort(order.begin(), order.end(), [&](int a, int b) { return nearest(a) < nearest(b); });
    for (int i : order) {
        const SdfObject& o = sdf.objects[size_t(i)];
        glm::vec2 lo(1e30f), hi(-1e30f);
        for (int corner = 0; corner < 8; ++corner) {
            glm::vec3 sign(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
            glm::vec3 v = o.pos + sign * o.bound - cam.pos;
            float z = glm::dot(v, cam.forward);
            if (z <= 1e-3f) {
                lo = glm::vec2(-1e30f), hi = glm::vec2(1e30f);
                break;
            }
            glm::vec2 uv(glm::dot(v, cam.right) / glm::dot(cam.right, cam.right) / z,
                         glm::dot(v, cam.up) / glm::dot(cam.up, cam.up) / z);
            glm::vec2 pixel = (uv * float(h) + glm::vec2(w, h)) * 0.5f;
            lo = glm::min(lo, pixel), hi = glm::max(hi, pixel);
        }
        glm::ivec2 a = glm::clamp(glm::ivec2(glm::floor(lo / float(kTile))), glm::ivec2(0),
                                  glm::ivec2(tiles.across - 1, tiles.down - 1));
        glm::ivec2 b = glm::clamp(glm::ivec2(glm::floor(hi / float(kTile))), glm::ivec2(0),
                                  glm::ivec2(tiles.across - 1, tiles.down - 1));
        if (hi.x < 0 || hi.y < 0 || lo.x > w || lo.y > h) continue;
        for (int y = a.y; y <= b.y; ++y)
            for (int x = a.x; x <= b.x; ++x) tiles.lists[size_t(y * tiles.across + x)].push_back(i);
    }
    return tiles;
}

// Front to back: the list ends once the hit is nearer than the next bounding sphere can be.
int tileCandidates(const SceneSdf& sdf, const std::vector<int>& list, const CameraBasis& cam,
                   glm::vec3 rd) {
    float best = kFar;
    int tested = 0;
    for (int i : list) {
        const SdfObject& o = sdf.objects[size_t(i)];
        if (glm::length(o.pos - cam.pos) - o.bound > best) break;
        ++tested;
        float t = hit(o, cam.pos, rd);
        if (t >= 0.0f) best = std::min(best, t);
    }
    return tested;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2 && argc != 4) {
        std::fprintf(stderr, "usage: tile_cull_count SCENE.txt [WIDTH HEIGHT]\n");
        return 2;
    }
    Scene scene;
    std::vector<std::string> errors;
    if (!loadScene(argv[1], &scene, &errors)) {
        std::fprintf(stderr, "tile_cull_count: %s\n", errors.empty() ? argv[1] : errors[0].c_str());
        return 1;
    }
    int w = argc == 4 ? std::atoi(argv[2]) : 480, h = argc == 4 ? std::atoi(argv[3]) : 270;
    SceneSdf sdf = makeSceneSdf(scene);
    std::vector<bool> plain = plainMembers(scene);
    PlainGrid grid = buildPlainGrid(sdf, plain);
    CameraBasis cam = cameraBasis(scene.camera);
    Tiles tiles = buildTiles(sdf, plain, cam, w, h);
    // llvmpipe shades 4x4 pixels as one SIMD group, which runs until its slowest lane is done.
    const int kGroup = 4;
    std::vector<WalkCount> walk(size_t(w) * h);
    std::vector<int> listed(walk.size()), frontToBack(walk.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            glm::vec3 rd = cameraRay(cam, {x + 0.5f, y + 0.5f}, {w, h});
            float ground =
                rd.y < 0.0f && scene.world.ground ? (cam.pos.y - scene.world.floor) / -rd.y : kFar;
            const std::vector<int>& list =
                tiles.lists[size_t(y / kTile * tiles.across + x / kTile)];
            size_t i = size_t(y) * w + x;
            walk[i] = gridCandidates(sdf, grid.grid, cam.pos, rd, ground);
            listed[i] = int(list.size());
            frontToBack[i] = tileCandidates(sdf, list, cam, rd);
        }
    double sum[4] = {}, groupMax[4] = {};
    for (int gy = 0; gy < h; gy += kGroup)
        for (int gx = 0; gx < w; gx += kGroup) {
            double most[4] = {};
            for (int y = gy; y < std::min(gy + kGroup, h); ++y)
                for (int x = gx; x < std::min(gx + kGroup, w); ++x) {
                    size_t i = size_t(y) * w + x;
                    const double v[4] = {double(walk[i].cells), double(walk[i].tested),
                                         double(listed[i]), double(frontToBack[i])};
                    for (int k = 0; k < 4; ++k) sum[k] += v[k], most[k] = std::max(most[k], v[k]);
                }
            for (int k = 0; k < 4; ++k) groupMax[k] += most[k] * kGroup * kGroup;
        }
    double n = double(w) * h;
    std::printf(
        "members %ld, grid %dx%dx%d. Per primary ray (mean; slowest of its 4x4 group): "
        "grid cells %.2f; %.2f, grid candidates %.2f; %.2f, tile list %.2f; %.2f, "
        "tile front to back %.2f; %.2f\n",
        long(std::count(plain.begin(), plain.end(), true)), grid.grid.dims.x, grid.grid.dims.y,
        grid.grid.dims.z, sum[0] / n, groupMax[0] / n, sum[1] / n, groupMax[1] / n, sum[2] / n,
        groupMax[2] / n, sum[3] / n, groupMax[3] / n);
    return 0;
}
