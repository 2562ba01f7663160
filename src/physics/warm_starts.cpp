// warm_starts.cpp — the open-addressing table of last step's impulses (warm_starts.h).
#include "warm_starts.h"

namespace mb {

void WarmStarts::clear(size_t count) {
    size_t size = 16;
    while (size < 2 * count) size *= 2;
    keys_.assign(size, 0);
    places_.resize(size);
    impulses_.clear();
    impulses_.reserve(count);
    mask_ = size - 1;
}

// Fibonacci hashing: the keys' pair and probe bits spread over the table's width.
size_t WarmStarts::slotOf(std::uint64_t key) const {
    return size_t((key * 0x9e3779b97f4a7c15ull) >> 32) & mask_;
}

void WarmStarts::put(std::uint64_t key, const WarmImpulses& impulses) {
    size_t slot = slotOf(key);
    while (keys_[slot] != 0) slot = (slot + 1) & mask_;
    keys_[slot] = key;
    places_[slot] = std::uint32_t(impulses_.size());
    impulses_.push_back(impulses);
}

const WarmImpulses* WarmStarts::find(std::uint64_t key) const {
    if (keys_.empty()) return nullptr;
    for (size_t slot = slotOf(key); keys_[slot] != 0; slot = (slot + 1) & mask_)
        if (keys_[slot] == key) return &impulses_[places_[slot]];
    return nullptr;
}

}  // namespace mb
