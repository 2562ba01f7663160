// branchless.h — choices made by arithmetic, for conditions that vary contact by contact
// or body by body: a branch on them is anyone's guess, and a wrong guess costs more than both
// sides.
#pragma once

#include <bit>
#include <cstdint>

namespace mb {

// a where `first`, else b (a double or a pointer), without a branch. Always inlined: the solver's
// passes that call it are compiled for several targets (lane_math.h).
template <class T>
[[gnu::always_inline]] inline T pick(bool first, T a, T b) {
    static_assert(sizeof(T) == sizeof(std::uint64_t));
    const auto mask = -std::uint64_t(first);
    return std::bit_cast<T>((std::bit_cast<std::uint64_t>(a) & mask) |
                            (std::bit_cast<std::uint64_t>(b) & ~mask));
}

}  // namespace mb
