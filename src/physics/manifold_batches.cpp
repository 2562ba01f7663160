// manifold_batches.cpp — rigid manifolds' normal, friction and rolling rows, kLanes at a time.
//
// Each function mirrors one manifold's rows as they were solved one at a time, operation for
// operation and in glm's order, so that every lane rounds as that did. Where the one-manifold form
// skipped work (a side that does not move, a lane that settled, a row past a lane's last), the
// lane computes and then keeps its old value (select), so nothing changes, not even a zero's sign.
#include "manifold_batches.h"

#include "lane_math.h"

#include <algorithm>
#include <cassert>
#include <cstring>

namespace mb {

namespace {

template <class V>
using Mask = MaskOf<V>;

// Manifolds are grouped by their rows, 1 to 8 (more count as 8), and by the relax sweeps they
// took last step, 1 to 4 (more count as 4).
constexpr int kRowKinds = 8, kSweepKinds = 4, kKinds = kRowKinds * kSweepKinds;

// Lanes of a batch (lane_math.h), and its fields of vectors.
template <class V>
struct Slice : BatchSlice<V, ManifoldBatch> {
    using BatchSlice<V, ManifoldBatch>::operator();
    [[gnu::always_inline]] Lanes3<V> operator()(const LaneVec& f) const {
        return {(*this)(f.x), (*this)(f.y), (*this)(f.z)};
    }
    [[gnu::always_inline]] Mask<V> moves(const Lanes& invMass) const {
        return (*this)(invMass) > V{};
    }
};

// The velocities and spins of each lane's two bodies while its rows are swept.
template <class V>
struct Sides {
    Lanes3<V> velA, spinA, velB, spinB;
};

[[gnu::always_inline]] inline void put(LaneVec& to, int lane, const glm::dvec3& v) {
    to.x[lane] = v.x, to.y[lane] = v.y, to.z[lane] = v.z;
}

template <class V>
[[gnu::always_inline]] inline void load(Lanes3<V>& vel, Lanes3<V>& spin, int l, const double* p) {
    vel.x[l] = p[0], vel.y[l] = p[1], vel.z[l] = p[2];
    spin.x[l] = p[3], spin.y[l] = p[4], spin.z[l] = p[5];
}

template <class V>
[[gnu::always_inline]] inline void save(const Lanes3<V>& vel, const Lanes3<V>& spin, int l,
                                        double* p) {
    p[0] = vel.x[l], p[1] = vel.y[l], p[2] = vel.z[l];
    p[3] = spin.x[l], p[4] = spin.y[l], p[5] = spin.z[l];
}

// Each lane's two bodies' motion since the step began, for its rows' separations.
template <class V>
struct BodyPath {
    Lanes3<V> delta;
    V x, y, z, w;          // the turn, a quaternion
    Mask<V> moves, turns;  // a delta; a turn
};

template <class V>
struct Paths {
    BodyPath<V> a, b;
};

template <class V>
[[gnu::always_inline]] inline void loadPath(BodyPath<V>& p, int l, const glm::dvec3* delta,
                                            const glm::dquat* orient) {
    if (delta) {
        p.moves[l] = -1;
        p.delta.x[l] = delta->x, p.delta.y[l] = delta->y, p.delta.z[l] = delta->z;
    }
    if (orient) {
        p.turns[l] = -1;
        p.x[l] = orient->x, p.y[l] = orient->y, p.z[l] = orient->z, p.w[l] = orient->w;
    }
}

template <class V>
[[gnu::always_inline]] inline Paths<V> gatherPaths(const Slice<V>& at) {
    Paths<V> p{};
    for (int l = 0; l < widthOf<V> && at.first + l < at.c.count; ++l) {
        const int lane = at.first + l;
        loadPath(p.a, l, at.c.deltaA[lane], at.c.orientA[lane]);
        loadPath(p.b, l, at.c.deltaB[lane], at.c.orientB[lane]);
    }
    return p;
}

// q·v as glm turns a vector by a quaternion.
template <class V>
[[gnu::always_inline]] inline Lanes3<V> turn(const BodyPath<V>& q, const Lanes3<V>& v) {
    const Lanes3<V> u{q.x, q.y, q.z};
    const Lanes3<V> uv = cross(u, v), uuv = cross(u, uv);
    return v + ((uv * q.w) + uuv) * splat<V>(2.0);
}

// How far a side's anchor moved since the step's start: its body's displacement and its turn.
template <class V>
[[gnu::always_inline]] inline Lanes3<V> anchorMove(const Slice<V>& at, const AnchorLanes& r,
                                                   const BodyPath<V>& p) {
    const Lanes3<V> none{};
    const Lanes3<V> turned =
        select(p.turns, turn(p, at(r.local)) + at(r.offset) - at(r.anchor), none);
    return select(p.moves, p.delta + turned, none);
}

// Each row's separation now: at the step's start, and along its normal as far as its two
// anchors have come towards each other since.
template <class V>
[[gnu::always_inline]] inline void separate(const Slice<V>& at, RowLanes* rows,
                                            const PathLanes* paths) {
    const Paths<V> p = gatherPaths(at);
    for (int i = 0; i < at.c.rows; ++i) {
        const Lanes3<V> moved = anchorMove(at, paths[i].b, p.b) - anchorMove(at, paths[i].a, p.a);
        at.set(rows[i].separation, at(paths[i].start) + dot(at(rows[i].normal), moved));
    }
}

// A static a reads as still, as it always did.
template <class V>
[[gnu::always_inline]] inline Sides<V> gather(const Slice<V>& at) {
    Sides<V> s{};
    for (int l = 0; l < widthOf<V> && at.first + l < at.c.count; ++l) {
        if (const double* a = at.c.a[at.first + l]) load(s.velA, s.spinA, l, a);
        load(s.velB, s.spinB, l, at.c.b[at.first + l]);
    }
    return s;
}

// Only a body that moves is written: one held fixed may be read by every lane of a level.
template <class V>
[[gnu::always_inline]] inline void scatter(const Slice<V>& at, const Sides<V>& s) {
    for (int l = 0; l < widthOf<V> && at.first + l < at.c.count; ++l) {
        const int lane = at.first + l;
        if (at.c.invMassA[lane] > 0.0) save(s.velA, s.spinA, l, at.c.a[lane]);
        if (at.c.invMassB[lane] > 0.0) save(s.velB, s.spinB, l, at.c.b[lane]);
    }
}

// An impulse along a row's normal: −p on a, +p on b, in the lanes `on`.
template <class V>
[[gnu::always_inline]] inline void applyNormal(const Slice<V>& at, const RowLanes& r, V impulse,
                                               Mask<V> on, Sides<V>& s) {
    const Lanes3<V> n = at(r.normal);
    const Mask<V> onA = on & at.moves(at.c.invMassA), onB = on & at.moves(at.c.invMassB);
    s.velA = select(onA, s.velA - (at(at.c.invMassA) * impulse) * n, s.velA);
    s.spinA = select(onA, s.spinA - impulse * at(r.turnA), s.spinA);
    s.velB = select(onB, s.velB + (at(at.c.invMassB) * impulse) * n, s.velB);
    s.spinB = select(onB, s.spinB + impulse * at(r.turnB), s.spinB);
}

// The speed along a row's normal at which its points part.
template <class V>
[[gnu::always_inline]] inline V normalSpeed(const Slice<V>& at, const RowLanes& r,
                                            const Sides<V>& s) {
    const Lanes3<V> n = at(r.normal);
    const V b = dot(n, s.velB) + dot(at(r.armB), s.spinB);
    return select(at.moves(at.c.hasA), b - dot(n, s.velA) - dot(at(r.armA), s.spinA), b);
}

// The normal row: speculative where apart (close the gap in this substep, no more), a soft
// push-out beyond the slop in the solve pass, rigid in the relax pass. Returns how much each
// lane's row changed its speed, m/s.
template <class V, bool useBias>
[[gnu::always_inline]] inline V solveNormal(const Slice<V>& at, RowLanes& r, const ManifoldPass& p,
                                            Mask<V> on, Sides<V>& s, Mask<V>& pushed) {
    const V sep = at(r.separation), old = at(r.impulse), mass = at(r.mass);
    const Mask<V> apart = sep > V{};
    V bias = select(apart, sep / splat<V>(p.h), V{});
    V massScale = splat<V>(1.0), impulseScale{};
    if constexpr (useBias) {
        const V push = maxOf(splat<V>(p.biasRate) * minOf(V{}, sep + splat<V>(p.slop)),
                             splat<V>(-p.maxPushSpeed));
        bias = select(apart, bias, push);
        massScale = select(apart, massScale, splat<V>(p.massScale));
        impulseScale = select(apart, impulseScale, splat<V>(p.impulseScale));
    }
    const V vn = normalSpeed(at, r, s);
    const V impulse = -mass * massScale * (vn + bias) - impulseScale * old;
    const V total = maxOf(old + impulse, V{});
    const V applied = total - old;
    applyNormal(at, r, applied, on, s);
    at.set(r.impulse, select(on, total, old));
    at.set(r.maxImpulse, select(on, maxOf(at(r.maxImpulse), total), at(r.maxImpulse)));
    if constexpr (useBias) pushed |= on & (total > V{});
    const V size = select(applied < V{}, -applied, applied);
    return select(mass > V{}, size / mass, V{});
}

// Whether each lane's friction rows hold an impulse. One that holds none, under a manifold that
// pushes nothing, has nothing to give: its limits are 0, and its rows would only be clamped to 0
// again (half of a pile of tables' manifolds, each sweep: speculative points not yet met).
template <class V>
[[gnu::always_inline]] inline Mask<V> holdsFriction(const Slice<V>& at) {
    const ManifoldBatch& c = at.c;
    return (at(c.tangentImpulse[0]) != V{}) | (at(c.tangentImpulse[1]) != V{}) |
           (at(c.twistImpulse) != V{}) | (at(c.rollImpulse[0]) != V{}) |
           (at(c.rollImpulse[1]) != V{});
}

// K⁻¹·(s0, s1) with K⁻¹ = [[m[0], m[1]], [m[1], m[2]]] (PairMass), negated.
template <class V>
[[gnu::always_inline]] inline void pairImpulse(const Slice<V>& at, const Lanes (&m)[3], V s0, V s1,
                                               V& first, V& second) {
    first = -(at(m[0]) * s0 + at(m[1]) * s1);
    second = -(at(m[1]) * s0 + at(m[2]) * s1);
}

// A manifold's friction, at its centre: Coulomb's disc |λ_t| ≤ μ·Σλ_n, and the twist about the
// normal, |λ_w| ≤ μ·r·Σλ_n with r the points' mean distance from the centre. Row by row at each
// point, the first point's friction would turn a face that lands flat about its normal; at the
// centre, nothing but a twist can. The twist goes first and the tangents meet the spin it left,
// as one pair (PairMass).
template <class V>
[[gnu::always_inline]] inline void solveFriction(const Slice<V>& at, V normalImpulse, Mask<V> on,
                                                 Sides<V>& s) {
    ManifoldBatch& c = at.c;
    const Mask<V> onA = on & at.moves(c.invMassA), onB = on & at.moves(c.invMassB);
    const V oldTwist = at(c.twistImpulse);
    const V twist = dot(at(c.normal), s.spinB - s.spinA);
    V w = oldTwist - at(c.twistMass) * twist;
    const V twistLimit = at(c.friction) * at(c.twistArm) * normalImpulse;
    w = select(w < -twistLimit, -twistLimit, select(twistLimit < w, twistLimit, w));
    const V dw = w - oldTwist;
    at.set(c.twistImpulse, select(on, w, oldTwist));
    s.spinA = select(onA, s.spinA - dw * at(c.twistA), s.spinA);
    s.spinB = select(onB, s.spinB + dw * at(c.twistB), s.spinB);
    V speed[2], t[2], dt[2];
    const Mask<V> hasA = at.moves(c.hasA);
    for (int k = 0; k < 2; ++k) {
        const Lanes3<V> tangent = at(c.tangent[k]);
        speed[k] = dot(tangent, s.velB) + dot(at(c.armB[k]), s.spinB);
        speed[k] =
            select(hasA, speed[k] - (dot(tangent, s.velA) + dot(at(c.armA[k]), s.spinA)), speed[k]);
    }
    pairImpulse(at, c.tangentMass, speed[0], speed[1], t[0], t[1]);
    const V limit = at(c.friction) * normalImpulse;
    const V t0 = at(c.tangentImpulse[0]) + t[0], t1 = at(c.tangentImpulse[1]) + t[1];
    const V size = sqrtOf(t0 * t0 + t1 * t1);
    const Mask<V> over = size > limit;
    t[0] = select(over, t0 * (limit / size), t0);
    t[1] = select(over, t1 * (limit / size), t1);
    for (int k = 0; k < 2; ++k) {
        dt[k] = t[k] - at(c.tangentImpulse[k]);
        at.set(c.tangentImpulse[k], select(on, t[k], at(c.tangentImpulse[k])));
    }
    const Lanes3<V> push = dt[0] * at(c.tangent[0]) + dt[1] * at(c.tangent[1]);
    s.velA = select(onA, s.velA - at(c.invMassA) * push, s.velA);
    s.spinA = select(onA, s.spinA - (dt[0] * at(c.turnA[0]) + dt[1] * at(c.turnA[1])), s.spinA);
    s.velB = select(onB, s.velB + at(c.invMassB) * push, s.velB);
    s.spinB = select(onB, s.spinB + (dt[0] * at(c.turnB[0]) + dt[1] * at(c.turnB[1])), s.spinB);
}

// Rolling resistance: an angular impulse against the relative spin across the normal (twist
// about the normal is not rolling), about each tangent as the friction's rows, within the disc
// |τ| ≤ rolling · r · Σλ_n with r the body's rolling radius. The rows' masses are made once a
// step: one along the spin's own axis costs two square roots, two divisions and four products
// with I⁻¹ every sweep, and took 9 % of a mixed pile's step.
template <class V>
[[gnu::always_inline]] inline void solveRolling(const Slice<V>& at, V normalImpulse, Mask<V> on,
                                                Sides<V>& s) {
    ManifoldBatch& c = at.c;
    const Mask<V> onA = on & at.moves(c.invMassA), onB = on & at.moves(c.invMassB);
    const Lanes3<V> w = s.spinB - s.spinA;
    const V turn0 = dot(at(c.tangent[0]), w), turn1 = dot(at(c.tangent[1]), w);
    V d0, d1;
    pairImpulse(at, c.rollMass, turn0, turn1, d0, d1);
    const V old0 = at(c.rollImpulse[0]), old1 = at(c.rollImpulse[1]);
    V total0 = old0 + d0, total1 = old1 + d1;
    const V limit = at(c.rollLimit) * normalImpulse;
    const V size = sqrtOf(total0 * total0 + total1 * total1);
    const Mask<V> over = size > limit;
    const V scale = limit / size;
    total0 = select(over, total0 * scale, total0);
    total1 = select(over, total1 * scale, total1);
    d0 = total0 - old0;
    d1 = total1 - old1;
    s.spinA = select(onA, s.spinA - (d0 * at(c.rollA[0]) + d1 * at(c.rollA[1])), s.spinA);
    s.spinB = select(onB, s.spinB + (d0 * at(c.rollB[0]) + d1 * at(c.rollB[1])), s.spinB);
    at.set(c.rollImpulse[0], select(on, total0, old0));
    at.set(c.rollImpulse[1], select(on, total1, old1));
}

// A pass over the lanes of one slice: the sweeps of RigidBodies::solve, each lane until it has
// settled (no row changed its speed by the tolerance) or spent its own sweeps.
template <class V, bool useBias>
[[gnu::always_inline]] inline void solveSlice(const Slice<V>& at, RowLanes* rows,
                                              const PathLanes* paths, const ManifoldPass& p) {
    ManifoldBatch& c = at.c;
    separate(at, rows, paths);
    Sides<V> s = gather(at);
    const V sweeps = at(useBias ? c.solveSweeps : c.relaxSweeps), rowCount = at(c.rowCount);
    Mask<V> settled{}, pushed{};
    V swept{};  // each lane's sweeps
    for (int sweep = 0;; ++sweep) {
        const Mask<V> on = (splat<V>(sweep) < sweeps) & ~settled;
        if (!any(on)) break;
        swept = select(on, swept + splat<V>(1.0), swept);
        V change{};
        for (int i = 0; i < c.rows; ++i) {
            const Mask<V> row = on & (splat<V>(i) < rowCount);
            change = maxOf(change, solveNormal<V, useBias>(at, rows[i], p, row, s, pushed));
        }
        V push{};
        for (int i = 0; i < c.rows; ++i) push += at(rows[i].impulse);
        const Mask<V> rubs = on & ((push > V{}) | holdsFriction(at));
        if (any(rubs)) {
            if (p.rolling) solveRolling(at, push, rubs, s);
            solveFriction(at, push, rubs, s);
        }
        settled |= on & (change < splat<V>(p.sweepTolerance));
    }
    scatter(at, s);
    if constexpr (!useBias) at.set(c.relaxed, swept);
    if constexpr (useBias)
        for (int l = 0; l < widthOf<V> && at.first + l < c.count; ++l) {
            if (!pushed[l]) continue;
            if (bool* a = c.supportedA[at.first + l]) *a = true;
            *c.supportedB[at.first + l] = true;
        }
}

// The warm start's two halves: every row's push, or every manifold's friction and rolling.
template <class V>
[[gnu::always_inline]] inline void warmRows(const Slice<V>& at, const RowLanes* rows) {
    Sides<V> s = gather(at);
    for (int i = 0; i < at.c.rows; ++i)
        applyNormal(at, rows[i], at(rows[i].impulse), splat<V>(i) < at(at.c.rowCount), s);
    scatter(at, s);
}

template <class V>
[[gnu::always_inline]] inline void warmCentre(const Slice<V>& at) {
    ManifoldBatch& c = at.c;
    Sides<V> s = gather(at);
    const Mask<V> onA = at.moves(c.invMassA), onB = at.moves(c.invMassB);
    const V t0 = at(c.tangentImpulse[0]), t1 = at(c.tangentImpulse[1]), w = at(c.twistImpulse);
    const V l0 = at(c.rollImpulse[0]), l1 = at(c.rollImpulse[1]);
    const Lanes3<V> push = t0 * at(c.tangent[0]) + t1 * at(c.tangent[1]);
    const Lanes3<V> turnA = w * at(c.twistA) + t0 * at(c.turnA[0]) + t1 * at(c.turnA[1]) +
                            l0 * at(c.rollA[0]) + l1 * at(c.rollA[1]);
    const Lanes3<V> turnB = w * at(c.twistB) + t0 * at(c.turnB[0]) + t1 * at(c.turnB[1]) +
                            l0 * at(c.rollB[0]) + l1 * at(c.rollB[1]);
    s.velA = select(onA, s.velA - at(c.invMassA) * push, s.velA);
    s.spinA = select(onA, s.spinA - turnA, s.spinA);
    s.velB = select(onB, s.velB + at(c.invMassB) * push, s.velB);
    s.spinB = select(onB, s.spinB + turnB, s.spinB);
    scatter(at, s);
}

// The next batch's bodies, asked for while this one is solved: they lie at random in memory, and
// a pile of 4,000 bodies does not fit in the cache.
inline void prefetchBodies(const ManifoldBatch& c) {
    for (int l = 0; l < c.count; ++l) {
        if (c.a[l]) __builtin_prefetch(c.a[l]);
        __builtin_prefetch(c.b[l]);
    }
}

enum class Step { warmRows, warmCentres, solve, relax };

struct Pass {
    ManifoldBatch* batches;
    RowLanes* rows;
    const PathLanes* paths;
    int count;
    const ManifoldPass& p;
    Step step;
};

template <class V>
[[gnu::always_inline]] inline void passOf(const Pass& pass) {
    for (int k = 0; k < pass.count; ++k) {
        ManifoldBatch& c = pass.batches[k];
        if (k + 1 < pass.count) prefetchBodies(pass.batches[k + 1]);
        RowLanes* rows = pass.rows + c.firstRow;
        const PathLanes* paths = pass.paths + c.firstRow;
        for (int first = 0; first < c.count; first += widthOf<V>) {
            const Slice<V> at{{c, first}};
            switch (pass.step) {
                case Step::warmRows:
                    warmRows(at, rows);
                    break;
                case Step::warmCentres:
                    warmCentre(at);
                    break;
                case Step::solve:
                    solveSlice<V, true>(at, rows, paths, pass.p);
                    break;
                case Step::relax:
                    solveSlice<V, false>(at, rows, paths, pass.p);
                    break;
            }
        }
    }
}

// Compiled for AVX-512 and AVX2 where the CPU has them, and for baseline x86-64 two lanes at a
// time, as contact_batches.cpp's passes are: all give the same bytes.
void twoLanes(const Pass& pass) { passOf<Pair>(pass); }

#if defined(__x86_64__) && !defined(__clang__)
[[gnu::target("arch=x86-64-v4")]] void passAll(const Pass& pass) { passOf<Quad>(pass); }
[[gnu::target("avx2")]] void passAll(const Pass& pass) { passOf<Quad>(pass); }
[[gnu::target("default")]]
#endif
void passAll(const Pass& pass) {
    twoLanes(pass);
}

}  // namespace

void ManifoldBatches::load(const std::vector<NormalRow>& rows,
                           const std::vector<RigidContact>& contacts,
                           const std::vector<RigidManifold>& manifolds, int bodies, int sweeps,
                           int impactSweeps) {
    const int n = int(manifolds.size());
    // scratch: per body, one past the level of its last manifold so far; per manifold, its level,
    // rows and sweeps as one key. next_: per key, the next place in its level.
    scratch_.assign(size_t(bodies) + size_t(n), 0);
    int* above = scratch_.data();
    int* key = above + bodies;
    int levels = 0;
    for (int m = 0; m < n; ++m) {
        const RigidManifold& f = manifolds[size_t(m)];
        const int a = f.movesA, b = f.movesB;
        const int k = std::max(a < 0 ? 0 : above[a], b < 0 ? 0 : above[b]);
        if (a >= 0) above[a] = k + 1;
        if (b >= 0) above[b] = k + 1;
        levels = std::max(levels, k + 1);
        key[m] = k * kKinds + (std::min(f.end - f.begin, kRowKinds) - 1) * kSweepKinds +
                 std::clamp(f.sweeps, 1, kSweepKinds) - 1;
    }
    // Within a level the order is free: manifolds with as many rows go side by side, so that a
    // batch's lanes have rows in the same places (a sphere's one point beside a box's four would
    // sweep three empty rows), and among them those that settled as fast, so that few lanes wait
    // on another's sweeps: a pile's manifolds take as many from step to step.
    std::vector<int>& next = next_;
    next.assign(size_t(levels) * kKinds, 0);
    for (int m = 0; m < n; ++m) ++next[size_t(key[m])];
    std::vector<int>& begin = levelBegin_;  // level k's batches from begin[k]
    begin.assign(size_t(levels) + 1, 0);
    for (int k = 0; k < levels; ++k) {
        int count = 0;
        for (int r = 0; r < kKinds; ++r) {
            const int kind = next[size_t(k * kKinds + r)];
            next[size_t(k * kKinds + r)] = count;
            count += kind;
        }
        begin[size_t(k) + 1] = begin[size_t(k)] + (count + kLanes - 1) / kLanes;
    }
    const int batches = begin.back();
    laneOf_.assign(size_t(batches) * kLanes, -1);
    manifoldSlot_.resize(size_t(n));
    for (int m = 0; m < n; ++m) {
        const int slot = begin[size_t(key[m] / kKinds)] * kLanes + next[size_t(key[m])]++;
        manifoldSlot_[size_t(m)] = slot;
        laneOf_[size_t(slot)] = m;
    }
    // Each batch and its rows are cleared and filled while they are in the cache, one after
    // another: filled in the manifolds' order, the batches of a pile of 4,000 came from memory.
    batches_.resize(size_t(batches));
    int total = 0;
    for (int k = 0; k < batches; ++k) {
        ManifoldBatch& c = batches_[size_t(k)];
        c = ManifoldBatch{};
        c.firstRow = total;
        for (int l = 0; l < kLanes && laneOf_[size_t(k * kLanes + l)] >= 0; ++l) {
            const RigidManifold& f = manifolds[size_t(laneOf_[size_t(k * kLanes + l)])];
            c.count = l + 1;
            c.rows = std::max(c.rows, f.end - f.begin);
        }
        total += c.rows;
    }
    rows_.resize(size_t(total));
    paths_.resize(size_t(total));
    rowSlot_.resize(rows.size());
    for (int k = 0; k < batches; ++k) {
        ManifoldBatch& c = batches_[size_t(k)];
        std::fill_n(rows_.begin() + c.firstRow, c.rows, RowLanes{});
        std::fill_n(paths_.begin() + c.firstRow, c.rows, PathLanes{});
        for (int l = 0; l < c.count; ++l)
            place(c, l, rows, contacts, manifolds[size_t(laneOf_[size_t(k * kLanes + l)])], sweeps,
                  impactSweeps);
    }
}

// A manifold's friction and rolling rows' turns and masses, into lane l.
void putTurns(ManifoldBatch& c, int l, const FrictionRows& f) {
    for (int k = 0; k < 2; ++k) {
        put(c.turnA[k], l, f.turnA[k]);
        put(c.turnB[k], l, f.turnB[k]);
        put(c.rollA[k], l, f.rollA[k]);
        put(c.rollB[k], l, f.rollB[k]);
    }
    put(c.twistA, l, f.twistA);
    put(c.twistB, l, f.twistB);
    c.twistMass[l] = f.twistMass;
    const PairMass* masses[2] = {&f.tangentMass, &f.rollMass};
    Lanes* lanes[2] = {c.tangentMass, c.rollMass};
    for (int k = 0; k < 2; ++k) {
        lanes[k][0][l] = masses[k]->m00;
        lanes[k][1][l] = masses[k]->m01;
        lanes[k][2][l] = masses[k]->m11;
    }
}

// A side's anchor path into lane l of a row.
void putPath(AnchorLanes& to, int l, const AnchorPath& from) {
    put(to.anchor, l, from.anchor);
    put(to.local, l, from.localAnchor);
    put(to.offset, l, from.offset);
}

void ManifoldBatches::place(ManifoldBatch& c, int l, const std::vector<NormalRow>& rows,
                            const std::vector<RigidContact>& contacts, const RigidManifold& m,
                            int sweeps, int impactSweeps) {
    const FrictionRows& f = m.rows;
    // The lanes read a body's spin as the three doubles after its velocity, as RigidBody and
    // PhysicsBody hold them.
    assert(!f.velA || f.spinA == f.velA + 1);
    assert(f.spinB == f.velB + 1);
    c.a[l] = f.velA ? &f.velA->x : nullptr;
    c.b[l] = &f.velB->x;
    c.supportedA[l] = rows[size_t(m.begin)].supportedA;
    c.supportedB[l] = rows[size_t(m.begin)].supportedB;
    const RigidContact& first = contacts[size_t(m.begin)];  // its rows' sides are its bodies
    c.deltaA[l] = first.a.delta;
    c.deltaB[l] = first.b.delta;
    c.orientA[l] = first.a.orient;
    c.orientB[l] = first.b.orient;
    c.rowCount[l] = m.end - m.begin;
    c.solveSweeps[l] = m.impact ? impactSweeps : 1;
    c.relaxSweeps[l] = m.impact ? impactSweeps : sweeps;
    c.hasA[l] = f.velA ? 1.0 : 0.0;
    c.invMassA[l] = f.invMassA;
    c.invMassB[l] = f.invMassB;
    put(c.normal, l, f.normal);
    for (int k = 0; k < 2; ++k) {
        put(c.tangent[k], l, f.tangent[k]);
        put(c.armA[k], l, f.armA[k]);
        put(c.armB[k], l, f.armB[k]);
        c.tangentImpulse[k][l] = f.tangentImpulse[k];
        c.rollImpulse[k][l] = f.rollImpulse[k];
    }
    c.friction[l] = f.friction;
    c.twistArm[l] = f.twistArm;
    c.rollLimit[l] = f.rollLimit;
    c.twistImpulse[l] = f.twistImpulse;
    putTurns(c, l, f);
    for (int i = m.begin; i < m.end; ++i) {
        const NormalRow& row = rows[size_t(i)];
        const int slot = (c.firstRow + i - m.begin) * kLanes + l;
        rowSlot_[size_t(i)] = slot;
        RowLanes& r = rows_[size_t(slot / kLanes)];
        PathLanes& path = paths_[size_t(slot / kLanes)];
        put(r.normal, l, row.normal);
        put(r.armA, l, row.armA);
        put(r.armB, l, row.armB);
        r.impulse[l] = row.impulse;
        r.maxImpulse[l] = row.maxImpulse;
        const RigidContact& contact = contacts[size_t(i)];
        path.start[l] = contact.separation;
        putPath(path.a, l, contact.a);
        putPath(path.b, l, contact.b);
        setTurns(i, row);
    }
}

void ManifoldBatches::setTurns(int row, const NormalRow& r) {
    const int slot = rowSlot_[size_t(row)], l = slot % kLanes;
    RowLanes& to = rows_[size_t(slot / kLanes)];
    put(to.turnA, l, r.turnA);
    put(to.turnB, l, r.turnB);
    to.mass[l] = r.mass;
}

void ManifoldBatches::setTurns(int manifold, const FrictionRows& r) {
    const int slot = manifoldSlot_[size_t(manifold)];
    putTurns(batches_[size_t(slot / kLanes)], slot % kLanes, r);
}

void ManifoldBatches::warmStart(bool twoLanesOnly) {
    for (Step step : {Step::warmRows, Step::warmCentres}) {
        const ManifoldPass none;
        const Pass pass{batches_.data(),      rows_.data(), paths_.data(),
                        int(batches_.size()), none,         step};
        twoLanesOnly ? twoLanes(pass) : passAll(pass);
    }
}

void ManifoldBatches::solve(const ManifoldPass& p, bool useBias, bool twoLanesOnly) {
    const Pass pass{batches_.data(),
                    rows_.data(),
                    paths_.data(),
                    int(batches_.size()),
                    p,
                    useBias ? Step::solve : Step::relax};
    twoLanesOnly ? twoLanes(pass) : passAll(pass);
}

void ManifoldBatches::store(std::vector<NormalRow>& rows,
                            std::vector<RigidManifold>& manifolds) const {
    for (size_t i = 0; i < rows.size(); ++i) {
        const int slot = rowSlot_[i], l = slot % kLanes;
        const RowLanes& from = rows_[size_t(slot / kLanes)];
        rows[i].impulse = from.impulse[l];
        rows[i].maxImpulse = from.maxImpulse[l];
    }
    for (size_t m = 0; m < manifolds.size(); ++m) {
        const int slot = manifoldSlot_[m], l = slot % kLanes;
        const ManifoldBatch& c = batches_[size_t(slot / kLanes)];
        FrictionRows& to = manifolds[m].rows;
        for (int k = 0; k < 2; ++k) {
            to.tangentImpulse[k] = c.tangentImpulse[k][l];
            to.rollImpulse[k] = c.rollImpulse[k][l];
        }
        to.twistImpulse = c.twistImpulse[l];
        manifolds[m].sweeps = int(c.relaxed[l]);
    }
}

}  // namespace mb
