// island.cpp — union-find islands for sleep.
#include "marchbox/island.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <limits>

namespace mb {

namespace {

int findRoot(std::vector<int>& parent, int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];  // path halving
    return i;
}

bool slow(const PhysicsBody& b, double speed) {
    return glm::length(b.vel) < speed && glm::length(b.spin) * b.radius < speed;
}

}  // namespace

void updateSleep(std::vector<PhysicsBody>& bodies, const std::vector<Contact>& contacts,
                 const PhysicsSettings& settings, std::vector<int>& parent,
                 std::vector<double>& islandTime) {
    const int n = int(bodies.size()) - 1;  // the static body joins no island
    for (int i = 0; i < n; ++i)
        if (bodies[i].awake)
            bodies[i].sleepTime = slow(bodies[i], settings.sleepSpeed) ? bodies[i].sleepTime + settings.dt
                                                                       : 0.0;
    if (!settings.sleep) return;
    // An island sleeps once its least settled body is ready: with no body ready, none sleeps.
    auto ready = [&](const PhysicsBody& b) { return b.awake && b.sleepTime >= settings.timeToSleep; };
    if (std::none_of(bodies.begin(), bodies.begin() + n, ready)) return;
    parent.resize(n);
    for (int i = 0; i < n; ++i) parent[i] = i;
    // Every contact between two spheres links them, touching or only within speculative reach:
    // the same reach at which an awake sphere wakes a sleeping one, so neighbours that would
    // wake each other sleep together.
    for (const Contact& c : contacts)
        if (c.a < n) parent[findRoot(parent, c.a)] = findRoot(parent, c.b);
    // The island's readiness is its least settled body: the minimum timer, kept at the root.
    islandTime.assign(size_t(n), std::numeric_limits<double>::infinity());
    for (int i = 0; i < n; ++i) {
        double& t = islandTime[findRoot(parent, i)];
        t = std::min(t, bodies[i].awake ? bodies[i].sleepTime : 0.0);
    }
    for (int i = 0; i < n; ++i) {
        PhysicsBody& b = bodies[i];
        const int root = findRoot(parent, i);
        if (!b.awake || islandTime[root] < settings.timeToSleep) continue;
        b.awake = false;
        b.vel = b.spin = glm::dvec3(0.0);
        b.island = root;
    }
}

void wakeIslands(std::vector<PhysicsBody>& bodies, std::vector<int>& islands) {
    if (islands.empty()) return;
    std::sort(islands.begin(), islands.end());
    for (PhysicsBody& b : bodies) {
        if (b.awake || !std::binary_search(islands.begin(), islands.end(), b.island)) continue;
        b.awake = true;
        b.sleepTime = 0.0;
        b.island = -1;
    }
    islands.clear();
}

}  // namespace mb
