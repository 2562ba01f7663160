// marchbox/lane_math.h — vectors of kLanes contacts' values: the glm operations the solver uses,
// lane by lane, in glm's own order of operations so that each lane rounds as glm does.
//
// Comparisons give masks (all bits set where true); select(m, a, b) takes a where m is set.
//
// Every function is always inlined, even unoptimised: the solver's passes are compiled for AVX2
// and AVX-512 as well as baseline x86-64, and a call between them would disagree on how a Lanes
// value is passed (in a register with AVX, in memory without).
#pragma once

#include "marchbox/contact_batches.h"

#include <cmath>

namespace mb {

using LaneMask = decltype(Lanes{} < Lanes{});  // 64-bit integers, as wide as Lanes

[[gnu::always_inline]] inline Lanes splat(double x) {
    Lanes r;
    for (int i = 0; i < kLanes; ++i) r[i] = x;
    return r;
}
// Bitwise: and, and-not, or (the vector ?: of GCC 12 branches lane by lane).
[[gnu::always_inline]] inline Lanes select(LaneMask m, Lanes a, Lanes b) { return Lanes((LaneMask(a) & m) | (LaneMask(b) & ~m)); }
// Whether any lane has a bit set: halves folded onto each other, then the last two lanes.
[[gnu::always_inline]] inline bool any(LaneMask m) {
    static_assert(kLanes == 4, "two folds");
    const LaneMask half = m | __builtin_shufflevector(m, m, 2, 3, 0, 1);
    return (half[0] | half[1]) != 0;
}
[[gnu::always_inline]] inline Lanes maxOf(Lanes a, Lanes b) { return select(a < b, b, a); }  // std::max(a, b)
[[gnu::always_inline]] inline Lanes minOf(Lanes a, Lanes b) { return select(b < a, b, a); }  // std::min(a, b)
// One instruction for all lanes where std::sqrt need not set errno: contact_batches.cpp is
// compiled with -fno-math-errno (src/CMakeLists.txt).
[[gnu::always_inline]] inline Lanes sqrtOf(Lanes x) {
    Lanes r;
    for (int i = 0; i < kLanes; ++i) r[i] = std::sqrt(x[i]);
    return r;
}

struct Lanes3 {
    Lanes x, y, z;
};

[[gnu::always_inline]] inline Lanes3 operator+(const Lanes3& a, const Lanes3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
[[gnu::always_inline]] inline Lanes3 operator-(const Lanes3& a, const Lanes3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
[[gnu::always_inline]] inline Lanes3 operator*(Lanes s, const Lanes3& v) { return {s * v.x, s * v.y, s * v.z}; }
[[gnu::always_inline]] inline Lanes3 operator*(const Lanes3& v, Lanes s) { return {v.x * s, v.y * s, v.z * s}; }
[[gnu::always_inline]] inline Lanes3 select(LaneMask m, const Lanes3& a, const Lanes3& b) {
    return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z)};
}
[[gnu::always_inline]] inline Lanes dot(const Lanes3& a, const Lanes3& b) {
    const Lanes3 t{a.x * b.x, a.y * b.y, a.z * b.z};
    return t.x + t.y + t.z;
}
[[gnu::always_inline]] inline Lanes3 cross(const Lanes3& a, const Lanes3& b) {
    return {a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y};
}
// Clamp a vector to a disc of radius maxLength (the isotropic Coulomb cone).
[[gnu::always_inline]] inline Lanes3 clampLength(const Lanes3& v, Lanes maxLength) {
    const Lanes len2 = dot(v, v);
    return select(len2 > maxLength * maxLength, v * (maxLength / sqrtOf(len2)), v);
}

}  // namespace mb
