// warm_starts.h — last step's impulses of the rigid contacts, found by the contact's key.
//
// Each step's contacts start from the impulses their keys held a step before. A pile of 4000
// bodies has some 20,000 contacts and their manifolds looked up in height order, which is
// random order for keys: a binary search over a sorted list missed the cache at every level.
// The keys sit in an open-addressing table (linear probing, at most half full), rebuilt each
// step; each slot holds its impulses' place in a list kept in the order they were put, last
// step's height order. A lookup reads the table at random, but lands in the list near the
// last one: bodies keep their heights from one step to the next.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace mb {

struct WarmImpulses {
    double normal = 0.0, tangent[2] = {0.0, 0.0}, twist = 0.0;
    double roll[2] = {0.0, 0.0};  // about the tangents
    int sweeps = 0;               // a manifold's relax sweeps (RigidManifold::sweeps)
};

class WarmStarts {
public:
    void clear(size_t count);                                   // room for `count` keys
    void put(std::uint64_t key, const WarmImpulses& impulses);  // key ≠ 0, each once a step
    const WarmImpulses* find(std::uint64_t key) const;          // null where last step had none
    // Asks the cache for key's slot ahead of its find: the lookups land at random in the table.
    void prefetch(std::uint64_t key) const {
        if (!keys_.empty()) __builtin_prefetch(&keys_[slotOf(key)]);
    }

private:
    size_t slotOf(std::uint64_t key) const;
    std::vector<std::uint64_t> keys_;     // 0: an empty slot
    std::vector<std::uint32_t> places_;   // the slot's key's place in impulses_
    std::vector<WarmImpulses> impulses_;  // in the order they were put
    size_t mask_ = 0;
};

}  // namespace mb
