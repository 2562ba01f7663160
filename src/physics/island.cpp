// island.cpp — union-find islands for sleep.
#include "island.h"

#include <algorithm>
#include <glm/geometric.hpp>

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
                 const PhysicsSettings& settings, std::vector<int>& parent) {
    const int n = int(bodies.size()) - 1;  // the static body joins no island
    for (int i = 0; i < n; ++i)
        if (bodies[i].awake)
            bodies[i].sleepTime =
                slow(bodies[i], settings.sleepSpeed) ? bodies[i].sleepTime + settings.dt : 0.0;
    if (!settings.sleep) return;
    // An island sleeps once its least settled body is ready: with no body ready, none sleeps.
    auto ready = [&](const PhysicsBody& b) {
        return b.awake && b.sleepTime >= settings.timeToSleep;
    };
    if (std::none_of(bodies.begin(), bodies.begin() + n, ready)) return;
    // Node n stands for every body not ready (asleep already, or not settled): they start in its
    // set, and an island joined to it stays awake. Unions point to the larger root, so n stays
    // its set's root and a contact between two of its bodies is passed over without a search.
    parent.resize(size_t(n) + 1);
    for (int i = 0; i < n; ++i) parent[i] = ready(bodies[i]) ? i : n;
    parent[n] = n;
    // Every contact between two spheres links them, touching or only within speculative reach:
    // the same reach at which an awake sphere wakes a sleeping one, so neighbours that would
    // wake each other sleep together.
    for (const Contact& c : contacts) {
        if (c.a >= n || (parent[c.a] == n && parent[c.b] == n)) continue;
        const int ra = findRoot(parent, c.a), rb = findRoot(parent, c.b);
        parent[std::min(ra, rb)] = std::max(ra, rb);
    }
    for (int i = 0; i < n; ++i) {
        PhysicsBody& b = bodies[i];
        const int root = findRoot(parent, i);
        if (root == n) continue;
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
