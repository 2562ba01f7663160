// warm_starts.h — last step's impulses of the rigid contacts, found by the contact's key.
//
// Each step's contacts start from the impulses their keys held a step before. A pile of 4000
// bodies has some 14,000 contacts and 5,000 manifolds looked up in height order, which is
// random order for keys: a binary search over a sorted list missed the cache at every level.
// This is an open-addressing table (linear probing, at most half full), rebuilt each step.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace mb {

struct WarmImpulses {
    double normal = 0.0, tangent[2] = {0.0, 0.0}, twist = 0.0;
    double roll[2] = {0.0, 0.0};  // about the tangents
};

class WarmStarts {
public:
    void clear(size_t count);                                   // room for `count` keys
    void put(std::uint64_t key, const WarmImpulses& impulses);  // key ≠ 0, each once a step
    const WarmImpulses* find(std::uint64_t key) const;          // null where last step had none

private:
    size_t slotOf(std::uint64_t key) const;
    std::vector<std::uint64_t> keys_;  // 0: an empty slot
    std::vector<WarmImpulses> impulses_;
    size_t mask_ = 0;
};

}  // namespace mb
