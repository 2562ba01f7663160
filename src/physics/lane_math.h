// lane_math.h — vectors of contacts' values, V at once (Lanes, or a Pair in the baseline):
// the glm operations the solver uses, lane by lane, in glm's own order of operations so that each
// lane rounds as glm does.
//
// Comparisons give masks (all bits set where true); select(m, a, b) takes a where m is set.
//
// Every function is always inlined, even unoptimised: the solver's passes are compiled for AVX2
// and AVX-512 as well as baseline x86-64, and a call between them would disagree on how a vector
// is passed (in a register with AVX, in memory without).
#pragma once

#include "contact_batches.h"

#include <cmath>
#include <cstring>

namespace mb {

// What the solver computes with (V below): a batch's four lanes, as Lanes less the alignment that a
// template argument would drop (only the batch's fields in memory need it), or half of them, one
// SSE2 register, where the baseline solves a batch two lanes at a time.
using Quad = double __attribute__((vector_size(kLanes * sizeof(double))));
using Pair = double __attribute__((vector_size(2 * sizeof(double))));

template <class V>
constexpr int widthOf = int(sizeof(V) / sizeof(double));  // lanes in V: kLanes, or 2 for a Pair
template <class V>
using MaskOf = decltype(V{} < V{});  // 64-bit integers, as wide as V

template <class V>
[[gnu::always_inline]] inline V splat(double x) {
    V r;
    for (int i = 0; i < widthOf<V>; ++i) r[i] = x;
    return r;
}
// Bitwise: and, and-not, or (the vector ?: of GCC 12 branches lane by lane).
template <class V>
[[gnu::always_inline]] inline V select(MaskOf<V> m, V a, V b) {
    return V((MaskOf<V>(a) & m) | (MaskOf<V>(b) & ~m));
}
// Whether any lane has a bit set: four lanes' halves folded onto each other, then the last two.
template <class M>
[[gnu::always_inline]] inline bool any(M m) {
    static_assert(sizeof m == 2 * sizeof(double) || sizeof m == 4 * sizeof(double),
                  "one fold at most");
    if constexpr (sizeof m == 4 * sizeof(double)) m |= __builtin_shufflevector(m, m, 2, 3, 0, 1);
    return (m[0] | m[1]) != 0;
}
template <class V>
[[gnu::always_inline]] inline V maxOf(V a, V b) {
    return select(a < b, b, a);
}  // std::max(a, b)
template <class V>
[[gnu::always_inline]] inline V minOf(V a, V b) {
    return select(b < a, b, a);
}  // std::min(a, b)
// One instruction for all lanes where std::sqrt need not set errno: contact_batches.cpp is
// compiled with -fno-math-errno (src/CMakeLists.txt).
template <class V>
[[gnu::always_inline]] inline V sqrtOf(V x) {
    V r;
    for (int i = 0; i < widthOf<V>; ++i) r[i] = std::sqrt(x[i]);
    return r;
}

// Lanes [first, first + widthOf<V>) of a batch c: the whole batch with AVX, a half of it in the
// baseline. Its fields stay kLanes wide in memory; at(field) loads these lanes of one.
template <class V, class Batch>
struct BatchSlice {
    Batch& c;
    int first;

    [[gnu::always_inline]] V operator()(const Lanes& field) const {
        V v;
        std::memcpy(&v, reinterpret_cast<const double*>(&field) + first, sizeof v);
        return v;
    }
    [[gnu::always_inline]] void set(Lanes& field, const V& v) const {
        std::memcpy(reinterpret_cast<double*>(&field) + first, &v, sizeof v);
    }
};

template <class V>
struct Lanes3 {
    V x, y, z;
};

template <class V>
[[gnu::always_inline]] inline Lanes3<V> operator+(const Lanes3<V>& a, const Lanes3<V>& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class V>
[[gnu::always_inline]] inline Lanes3<V> operator-(const Lanes3<V>& a, const Lanes3<V>& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class V>
[[gnu::always_inline]] inline Lanes3<V> operator*(V s, const Lanes3<V>& v) {
    return {s * v.x, s * v.y, s * v.z};
}
template <class V>
[[gnu::always_inline]] inline Lanes3<V> operator*(const Lanes3<V>& v, V s) {
    return {v.x * s, v.y * s, v.z * s};
}
template <class V>
[[gnu::always_inline]] inline Lanes3<V> select(MaskOf<V> m, const Lanes3<V>& a,
                                               const Lanes3<V>& b) {
    return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z)};
}
template <class V>
[[gnu::always_inline]] inline V dot(const Lanes3<V>& a, const Lanes3<V>& b) {
    const Lanes3<V> t{a.x * b.x, a.y * b.y, a.z * b.z};
    return t.x + t.y + t.z;
}
template <class V>
[[gnu::always_inline]] inline Lanes3<V> cross(const Lanes3<V>& a, const Lanes3<V>& b) {
    return {a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y};
}
// Clamp a vector to a disc of radius maxLength (the isotropic Coulomb cone).
template <class V>
[[gnu::always_inline]] inline Lanes3<V> clampLength(const Lanes3<V>& v, V maxLength) {
    const V len2 = dot(v, v);
    return select(len2 > maxLength * maxLength, v * (maxLength / sqrtOf(len2)), v);
}

}  // namespace mb
