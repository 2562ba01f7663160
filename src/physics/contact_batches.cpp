// contact_batches.cpp — normal, friction and rolling rows of sphere contacts, kLanes at a time.
//
// Each function mirrors one contact's rows (Box2D v3's soft step), operation for operation. The
// branches of the one-contact form become masks (select) where they choose a value, and nothing
// where they only skipped work: a lane whose impulse does not change applies a change of 0.
// Whole batches still skip what none of their lanes needs.
#include "contact_batches.h"

#include "branchless.h"
#include "lane_math.h"
#include "worker.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <glm/geometric.hpp>

namespace mb {

namespace {

template <class V>
struct BodyLanes {
    Lanes3<V> vel, spin;
};

template <class V>
struct PairLanes {
    BodyLanes<V> a, b;
    Lanes3<V> deltaA, deltaB;
};

template <class V>
struct Slice : BatchSlice<V, ContactBatch> {
    [[gnu::always_inline]] Lanes3<V> normal() const {
        return {(*this)(this->c.nx), (*this)(this->c.ny), (*this)(this->c.nz)};
    }
};

// A body's solver fields are nine doubles in a row (physics.h): vel, spin, delta. The bodies of a
// batch side are read as rows (four wide: vel and spin.x, then pairs; two wide: pairs) and
// transposed into lanes; vel and spin go back the same way, row by row, so that the next level's
// reads of the same rows come straight from these writes (a read that straddled two writes would
// wait for both to reach the cache).
static_assert(kLanes == 4, "gather and scatter transpose four bodies' rows");
static_assert(offsetof(PhysicsBody, spin) == 3 * sizeof(double) &&
                  offsetof(PhysicsBody, delta) == 6 * sizeof(double),
              "the solver's fields come first in PhysicsBody, in a row");

template <class Row>
[[gnu::always_inline]] inline Row rowAt(const PhysicsBody& body, int field) {
    Row r;
    std::memcpy(&r, reinterpret_cast<const char*>(&body.vel) + field * sizeof(double), sizeof r);
    return r;
}

template <class Row>
[[gnu::always_inline]] inline void storeRow(PhysicsBody& body, int field, const Row& r) {
    std::memcpy(reinterpret_cast<char*>(&body.vel) + field * sizeof(double), &r, sizeof r);
}

// The four-wide forms below are unused where the baseline is built alone (see passLevels).
//
// Four rows of four become four lanes of four, and back: c[k][l] = r[l][k].
[[gnu::always_inline]] inline void transpose(const Quad (&r)[4], Quad (&c)[4]) {
    const Quad t0 = __builtin_shufflevector(r[0], r[1], 0, 4, 2, 6),
               t1 = __builtin_shufflevector(r[0], r[1], 1, 5, 3, 7);
    const Quad t2 = __builtin_shufflevector(r[2], r[3], 0, 4, 2, 6),
               t3 = __builtin_shufflevector(r[2], r[3], 1, 5, 3, 7);
    c[0] = __builtin_shufflevector(t0, t2, 0, 1, 4, 5),
    c[1] = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
    c[2] = __builtin_shufflevector(t0, t2, 2, 3, 6, 7),
    c[3] = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
}

// Four pairs become two lanes of four.
[[gnu::always_inline, maybe_unused]] inline void transpose(const Pair (&p)[4], Quad& first,
                                                           Quad& second) {
    const Quad u = __builtin_shufflevector(p[0], p[2], 0, 1, 2, 3),
               v = __builtin_shufflevector(p[1], p[3], 0, 1, 2, 3);
    first = __builtin_shufflevector(u, v, 0, 4, 2, 6),
    second = __builtin_shufflevector(u, v, 1, 5, 3, 7);
}

// Two pairs become two lanes of two, and back.
[[gnu::always_inline]] inline void transpose(const Pair (&p)[2], Pair& first, Pair& second) {
    first = __builtin_shufflevector(p[0], p[1], 0, 2),
    second = __builtin_shufflevector(p[0], p[1], 1, 3);
}

// Fields field and field + 1 of each body, as two lanes.
template <class V>
[[gnu::always_inline]] inline void gatherPairs(PhysicsBody* const* p, int field, V& first,
                                               V& second) {
    Pair pairs[widthOf<V>];
    for (int l = 0; l < widthOf<V>; ++l) pairs[l] = rowAt<Pair>(*p[l], field);
    transpose(pairs, first, second);
}

// Fields 0-3: vel and spin.x.
[[gnu::always_inline, maybe_unused]] inline void gatherRows(PhysicsBody* const* p,
                                                            Lanes3<Quad>& vel, Quad& spinX) {
    const Quad rows[4] = {rowAt<Quad>(*p[0], 0), rowAt<Quad>(*p[1], 0), rowAt<Quad>(*p[2], 0),
                          rowAt<Quad>(*p[3], 0)};
    Quad lanes[4];
    transpose(rows, lanes);
    vel = {lanes[0], lanes[1], lanes[2]};
    spinX = lanes[3];
}

[[gnu::always_inline]] inline void gatherRows(PhysicsBody* const* p, Lanes3<Pair>& vel,
                                              Pair& spinX) {
    gatherPairs(p, 0, vel.x, vel.y);
    gatherPairs(p, 2, vel.z, spinX);
}

template <class V>
[[gnu::always_inline]] inline void gatherBodies(PhysicsBody* const* p, BodyLanes<V>& to,
                                                Lanes3<V>& delta) {
    gatherRows(p, to.vel, to.spin.x);
    gatherPairs(p, 4, to.spin.y, to.spin.z);
    gatherPairs(p, 6, delta.x, delta.y);
    for (int l = 0; l < widthOf<V>; ++l) delta.z[l] = p[l]->delta.z;
}

template <class V>
[[gnu::always_inline]] inline PairLanes<V> gather(const Slice<V>& at) {
    PairLanes<V> s;
    gatherBodies(at.c.a + at.first, s.a, s.deltaA);
    gatherBodies(at.c.b + at.first, s.b, s.deltaB);
    return s;
}

// One side's rows, four wide: vel and spin.x in rows[l], spin.y and z in the halves of spins[l %
// 2].
struct BodyRows {
    Quad rows[4];
    Quad spins[2];
};

// Two wide: body l's fields 2k and 2k + 1 in pairs[k][l], k = 0, 1, 2 (vel and spin).
struct BodyPairs {
    Pair pairs[3][2];
};

[[gnu::always_inline, maybe_unused]] inline BodyRows rowsOf(const BodyLanes<Quad>& from) {
    BodyRows r;
    transpose({from.vel.x, from.vel.y, from.vel.z, from.spin.x}, r.rows);
    r.spins[0] = __builtin_shufflevector(from.spin.y, from.spin.z, 0, 4, 2, 6);
    r.spins[1] = __builtin_shufflevector(from.spin.y, from.spin.z, 1, 5, 3, 7);
    return r;
}

[[gnu::always_inline]] inline BodyPairs rowsOf(const BodyLanes<Pair>& from) {
    BodyPairs r;
    transpose({from.vel.x, from.vel.y}, r.pairs[0][0], r.pairs[0][1]);
    transpose({from.vel.z, from.spin.x}, r.pairs[1][0], r.pairs[1][1]);
    transpose({from.spin.y, from.spin.z}, r.pairs[2][0], r.pairs[2][1]);
    return r;
}

[[gnu::always_inline, maybe_unused]] inline void storeLane(PhysicsBody& body, const BodyRows& from,
                                                           int l) {
    storeRow(body, 0, from.rows[l]);
    const Quad& spins = from.spins[l % 2];
    storeRow(body, 4,
             l < 2 ? __builtin_shufflevector(spins, spins, 0, 1)
                   : __builtin_shufflevector(spins, spins, 2, 3));
}

[[gnu::always_inline]] inline void storeLane(PhysicsBody& body, const BodyPairs& from, int l) {
    for (int k = 0; k < 3; ++k) storeRow(body, 2 * k, from.pairs[k][l]);
}

// Body a is written back only where it moves (the static body, shared by every level and both
// threads, never is): elsewhere its lane goes to `sink`, the caller's scratch.
template <class V>
[[gnu::always_inline]] inline void scatter(const Slice<V>& at, const LaneRows& w,
                                           const PairLanes<V>& s, PhysicsBody& sink) {
    const auto a = rowsOf(s.a), b = rowsOf(s.b);
    for (int l = 0; l < widthOf<V>; ++l) {
        const int lane = at.first + l;
        if (lane >= at.c.count) break;
        storeLane(*pick(w.massA[lane] > 0.0, at.c.a[lane], &sink), a, l);
        storeLane(*at.c.b[lane], b, l);
    }
}

// Linear impulse p at the contact point: −p on a, +p on b. Both arms lie along the normal, so the
// torques are r_a·(n × p) on a and r_b·(n × p) on b, against their spins: one cross product.
// A body held fixed has inverse mass 0 and is not moved; nor is a lane whose impulse did not
// change (its change is 0).
template <class V>
[[gnu::always_inline]] inline void applyImpulse(PairLanes<V>& s, const Slice<V>& at,
                                                const LaneRows& w, const Lanes3<V>& p) {
    const Lanes3<V> np = cross(at.normal(), p);
    s.a.vel = s.a.vel - at(w.massA) * p;
    s.a.spin = s.a.spin - (at(w.inertiaA) * at(at.c.armA)) * np;
    s.b.vel = s.b.vel + at(w.massB) * p;
    s.b.spin = s.b.spin - (at(w.inertiaB) * at(at.c.armB)) * np;
}

// Along the normal there is no torque (the cross products would only add rounding noise).
template <class V>
[[gnu::always_inline]] inline void applyNormal(PairLanes<V>& s, const Slice<V>& at,
                                               const LaneRows& w, const Lanes3<V>& p) {
    s.a.vel = s.a.vel - at(w.massA) * p;
    s.b.vel = s.b.vel + at(w.massB) * p;
}

template <class V>
[[gnu::always_inline]] inline void applyAngular(PairLanes<V>& s, const Slice<V>& at,
                                                const LaneRows& w, const Lanes3<V>& l) {
    s.a.spin = s.a.spin - at(w.inertiaA) * l;
    s.b.spin = s.b.spin + at(w.inertiaB) * l;
}

// Whether any lane carries an impulse (a zero of either sign carries none).
template <class V>
[[gnu::always_inline]] inline bool anyImpulse(const Slice<V>& at) {
    const ContactBatch& c = at.c;
    using Mask = MaskOf<V>;
    const Mask bits = Mask(at(c.normalImpulse)) | Mask(at(c.tx)) | Mask(at(c.ty)) | Mask(at(c.tz)) |
                      Mask(at(c.rx)) | Mask(at(c.ry)) | Mask(at(c.rz));
    return any(bits << 1);  // the sign bit shifted out
}

}  // namespace

namespace {

// Returns whether any lane's impulse changed.
template <class V>
[[gnu::always_inline]] inline bool solveNormal(const Slice<V>& at, PairLanes<V>& s,
                                               const SolverContext& ctx, const LaneRows& w,
                                               bool useBias) {
    ContactBatch& c = at.c;
    const Lanes3<V> n = at.normal();
    const V sep = at(c.separation) + dot(s.deltaB - s.deltaA, n);
    const V zero{};
    const MaskOf<V> open = sep > zero;
    const MaskOf<V> push = useBias ? ~open & (sep + at(c.slop) < zero) : MaskOf<V>{};
    // Open: speculative, close at most the gap this substep. Pushing: soft, with bias.
    const V pushBias =
        maxOf(ctx.soft.biasRate * (sep + at(c.slop)), splat<V>(-ctx.settings.maxPushSpeed));
    V bias = select(open, sep / ctx.h, select(push, pushBias, zero));
    const V massScale = select(push, splat<V>(ctx.soft.massScale), splat<V>(1.0));
    const V impulseScale = select(push, splat<V>(ctx.soft.impulseScale), zero);
    // A curved surface bends away from the straight path a substep takes along it; the solve pass
    // aims the path's end at the surface (RATTLE's position step), the relax pass then works
    // along the normal found there (its velocity step). Exact for a circle: speed is kept.
    if (useBias) bias += at(c.curve) / ctx.h;
    const V vn = dot(s.b.vel - s.a.vel, n);
    const V old = at(c.normalImpulse);
    const V impulse = -at(w.normal) * massScale * (vn + bias) - impulseScale * old;
    V total = maxOf(old + impulse, zero);
    // An open contact in the relax pass may give back impulse (the solve pass's push-out) but
    // not slow an approach fast enough to bounce: the solve pass before each position update
    // already keeps it from closing past its gap, and at the end of the step that approach is
    // the next step's impact, which Impacts resolves at its time (slowed here, it would bounce
    // lower).
    if (!useBias && ctx.settings.impacts)
        total = select(open & (vn < splat<V>(-bounceThreshold(ctx))), minOf(total, old), total);
    const MaskOf<V> changed = total != old;  // an open contact that stays open: nothing
    if (!any(changed)) return false;
    applyNormal(s, at, w, (total - old) * n);
    at.set(c.maxNormalImpulse,
           select(changed, maxOf(at(c.maxNormalImpulse), total), at(c.maxNormalImpulse)));
    at.set(c.normalImpulse, total);
    return true;
}

template <class V>
[[gnu::always_inline]] inline void solveFriction(const Slice<V>& at, PairLanes<V>& s,
                                                 const LaneRows& w) {
    // The contact points move at v_a + ω_a × r_a·n and v_b − ω_b × r_b·n; the spin terms lie in
    // the tangent plane already.
    ContactBatch& c = at.c;
    const Lanes3<V> n = at.normal();
    Lanes3<V> vt = s.b.vel - s.a.vel;
    vt = vt - (dot(vt, n) * n + cross(at(c.armA) * s.a.spin + at(c.armB) * s.b.spin, n));
    const Lanes3<V> old{at(c.tx), at(c.ty), at(c.tz)};
    const Lanes3<V> total =
        clampLength(old - at(w.tangent) * vt, at(c.friction) * at(c.normalImpulse));
    applyImpulse(s, at, w, total - old);
    at.set(c.tx, total.x), at.set(c.ty, total.y), at.set(c.tz, total.z);
}

template <class V>
[[gnu::always_inline]] inline void solveRolling(const Slice<V>& at, PairLanes<V>& s,
                                                const LaneRows& w, double resistance) {
    if (resistance <= 0.0) return;
    ContactBatch& c = at.c;
    const Lanes3<V> relative = s.b.spin - s.a.spin;
    const V limit = resistance * at(c.rollRadius) * at(c.normalImpulse);
    const Lanes3<V> old{at(c.rx), at(c.ry), at(c.rz)};
    const Lanes3<V> total = clampLength(old - at(w.roll) * relative, limit);
    applyAngular(s, at, w, total - old);
    at.set(c.rx, total.x), at.set(c.ry, total.y), at.set(c.rz, total.z);
}

// The rows of a contact, in Box2D's order: normal, then friction limited by the normal impulse
// just found, then rolling resistance. A speculative contact that stays open carries no friction:
// a batch of them skips the rows that would find 0. Returns whether the bodies may have moved.
template <class V>
[[gnu::always_inline]] inline bool solveRows(const Slice<V>& at, PairLanes<V>& s,
                                             const SolverContext& ctx, const LaneRows& w,
                                             bool useBias) {
    const bool moved = solveNormal(at, s, ctx, w, useBias);
    if (!anyImpulse(at)) return moved;
    solveFriction(at, s, w);
    solveRolling(at, s, w, ctx.rolling);
    return true;
}

// Without branches on which lanes push: body a's flag where it moves, else b's again (the static
// body, shared by both threads' runs, is never written).
template <class V>
[[gnu::always_inline]] inline void markSupported(const Slice<V>& at) {
    const ContactBatch& c = at.c;
    for (int l = at.first; l < at.first + widthOf<V>; ++l) {
        if (l >= c.count) break;
        const bool pushed = c.normalImpulse[l] > 0.0;
        c.b[l]->supported |= pushed;
        pick(c.solve.massA[l] > 0.0, c.a[l], c.b[l])->supported |= pushed;
    }
}

void setRows(LaneRows& to, int l, const RowMasses& m, const InverseMasses& w) {
    to.normal[l] = m.normal, to.tangent[l] = m.tangent, to.roll[l] = m.roll;
    to.massA[l] = w.massA, to.inertiaA[l] = w.inertiaA, to.massB[l] = w.massB,
    to.inertiaB[l] = w.inertiaB;
}

void loadLane(ContactBatch& to, int l, Contact& c, const SolverContext& ctx) {
    const PreparedRows rows = prepareContact(c, ctx);
    to.a[l] = &ctx.bodies[size_t(c.a)], to.b[l] = &ctx.bodies[size_t(c.b)];
    to.nx[l] = c.normal.x, to.ny[l] = c.normal.y, to.nz[l] = c.normal.z;
    to.separation[l] = c.separation, to.armA[l] = c.armA, to.armB[l] = c.armB, to.slop[l] = c.slop;
    to.curve[l] = 0.0, to.rollRadius[l] = c.rollRadius;  // curve: 0 until setCurve
    to.friction[l] = c.friction;
    setRows(to.solve, l, c.mass, rows.solve);
    setRows(to.relax, l, rows.relaxMass, rows.relax);
    to.normalImpulse[l] = c.normalImpulse, to.maxNormalImpulse[l] = c.maxNormalImpulse;
    to.tx[l] = c.tangentImpulse.x, to.ty[l] = c.tangentImpulse.y, to.tz[l] = c.tangentImpulse.z;
    to.rx[l] = c.rollImpulse.x, to.ry[l] = c.rollImpulse.y, to.rz[l] = c.rollImpulse.z;
}

}  // namespace

void ContactBatches::load(const SolverContext& ctx) {
    buildContactGraph(ctx.contacts, ctx.split, int(ctx.bodies.size()) - 1, graph_, scratch_);
    batches_.resize(size_t(graph_.batches()));
    // A batch is loaded from its own contacts alone: with a worker, it takes the first half.
    Worker* worker = ctx.worker;
    const int half = worker ? graph_.batches() / 2 : 0;
    auto first = [&] { loadBatches(ctx, 0, half); };
    if (worker) worker->post(first);
    loadBatches(ctx, half, graph_.batches());
    if (worker) worker->wait();
}

void ContactBatches::loadBatches(const SolverContext& ctx, int begin, int end) {
    Contact padding;  // on the static body alone, no mass, no impulse: never written back
    padding.a = padding.b = int(ctx.bodies.size()) - 1;
    for (int k = begin; k < end; ++k) {
        ContactBatch& c = batches_[size_t(k)];
        c.count = 0;
        for (int l = 0; l < kLanes; ++l) {
            const int i = graph_.slots[size_t(k * kLanes + l)];
            loadLane(c, l, i < 0 ? padding : ctx.contacts[size_t(i)], ctx);
            c.count += i < 0 ? 0 : 1;
        }
    }
}

namespace {

enum class Step { warmStart, solve, relax };

// One pass's batches, levels [levelBegin[k], levelBegin[k + 1]) for level k.
struct Pass {
    ContactBatch* batches;
    const int* levelBegin;
    SolverContext& ctx;
    Step step;
};

// A batch's lanes are solved widthOf<V> at a time: four wide, the whole batch, no test; two wide,
// each half that holds a contact (the last batch of a level may hold one or two).
template <class V>
[[gnu::always_inline]] inline int lanesHeld(const ContactBatch& c) {
    return widthOf<V> == kLanes ? kLanes : c.count;
}

template <class V>
[[gnu::always_inline]] inline void warmStartBatches(const Pass& pass, int begin, int end) {
    PhysicsBody sink;
    for (int i = pass.levelBegin[begin]; i < pass.levelBegin[end]; ++i) {
        ContactBatch& c = pass.batches[i];
        for (int first = 0; first < lanesHeld<V>(c); first += widthOf<V>) {
            const Slice<V> at{{c, first}};
            if (!anyImpulse(at)) continue;
            PairLanes<V> s = gather(at);
            applyNormal(s, at, c.solve, at(c.normalImpulse) * at.normal());
            applyImpulse(s, at, c.solve, {at(c.tx), at(c.ty), at(c.tz)});
            applyAngular(s, at, c.solve, {at(c.rx), at(c.ry), at(c.rz)});
            scatter(at, c.solve, s, sink);
        }
    }
}

template <class V, bool useBias>
[[gnu::always_inline]] inline void solveBatches(const Pass& pass, int begin, int end) {
    PhysicsBody sink;
    for (int i = pass.levelBegin[begin]; i < pass.levelBegin[end]; ++i) {
        ContactBatch& c = pass.batches[i];
        const LaneRows& w = useBias ? c.solve : c.relax;
        for (int first = 0; first < lanesHeld<V>(c); first += widthOf<V>) {
            const Slice<V> at{{c, first}};
            PairLanes<V> s = gather(at);
            if (!solveRows(at, s, pass.ctx, w, useBias)) continue;
            scatter(at, w, s, sink);
            if (useBias) markSupported(at);
        }
    }
}

// The solve and relax passes compiled apart, each with what it does not use left out.
template <class V>
[[gnu::always_inline]] inline void passLevelsOf(const Pass& pass, int begin, int end) {
    switch (pass.step) {
        case Step::warmStart:
            return warmStartBatches<V>(pass, begin, end);
        case Step::solve:
            return solveBatches<V, true>(pass, begin, end);
        case Step::relax:
            return solveBatches<V, false>(pass, begin, end);
    }
}

// Levels [begin, end) of a pass, compiled for AVX-512 and AVX2 where the CPU has them (one
// instruction for a batch's four lanes, chosen at load time) and for baseline x86-64, which takes
// a batch in halves: four-wide lanes would each fill two of its sixteen SSE2 registers and spill
// (physics_step_bench 1000 180 under callgrind: 1.78e9 instructions four wide, 1.30e9 in halves).
// The lanes of a batch are independent, and without FMA every product rounds on its own, so all
// give the same bytes. Clang (the fuzz build) rejects the AVX
// versions' inlined lane helpers as an ABI change, and other CPUs have other names: those build
// the baseline alone.
void twoLanes(const Pass& pass, int begin, int end) { passLevelsOf<Pair>(pass, begin, end); }

#if defined(__x86_64__) && !defined(__clang__)
[[gnu::target("arch=x86-64-v4")]] void passLevels(const Pass& pass, int begin, int end) {
    passLevelsOf<Quad>(pass, begin, end);
}
[[gnu::target("avx2")]] void passLevels(const Pass& pass, int begin, int end) {
    passLevelsOf<Quad>(pass, begin, end);
}
[[gnu::target("default")]]
#endif
void passLevels(const Pass& pass, int begin, int end) {
    twoLanes(pass, begin, end);
}

// The levels of the first two runs share no body: with a worker, it takes the first run's while
// this thread takes the second's. The same bytes whatever the thread count.
void byLevels(const ContactGraph& graph, const Pass& pass) {
    Worker* worker = pass.ctx.worker;
    auto levels = [&](int begin, int end) {
        pass.ctx.settings.twoLanes ? twoLanes(pass, begin, end) : passLevels(pass, begin, end);
    };
    auto first = [&] { levels(0, graph.runEnd[0]); };
    if (worker) worker->post(first);
    else first();
    levels(graph.runEnd[0], graph.runEnd[1]);
    if (worker) worker->wait();
    levels(graph.runEnd[1], graph.levels());
}

}  // namespace

void ContactBatches::warmStart(SolverContext& ctx) {
    byLevels(graph_, {batches_.data(), graph_.levelBegin.data(), ctx, Step::warmStart});
}

void ContactBatches::solve(SolverContext& ctx, bool useBias) {
    if (useBias)
        for (PhysicsBody& b : ctx.bodies) b.supported = false;
    byLevels(graph_,
             {batches_.data(), graph_.levelBegin.data(), ctx, useBias ? Step::solve : Step::relax});
}

void ContactBatches::store(std::vector<Contact>& contacts) const {
    for (size_t i = 0; i < contacts.size(); ++i) {
        const int slot = graph_.slotOf[i], l = slot % kLanes;
        const ContactBatch& c = batches_[size_t(slot / kLanes)];
        Contact& to = contacts[i];
        to.normalImpulse = c.normalImpulse[l];
        to.maxNormalImpulse = c.maxNormalImpulse[l];
        to.tangentImpulse = {c.tx[l], c.ty[l], c.tz[l]};
        to.rollImpulse = {c.rx[l], c.ry[l], c.rz[l]};
    }
}

ContactBatch& ContactBatches::batchOf(int contact, int& lane) {
    const int slot = graph_.slotOf[size_t(contact)];
    lane = slot % kLanes;
    return batches_[size_t(slot / kLanes)];
}

void ContactBatches::setCurve(int contact, double curve) {
    int l;
    batchOf(contact, l).curve[l] = curve;
}

void ContactBatches::follow(int contact, const glm::dvec3& normal, double separation) {
    int l;
    ContactBatch& c = batchOf(contact, l);
    c.nx[l] = normal.x, c.ny[l] = normal.y, c.nz[l] = normal.z;
    c.separation[l] = separation;
    c.curve[l] = 0.0;
    glm::dvec3 t{c.tx[l], c.ty[l], c.tz[l]};
    t -= glm::dot(t, normal) * normal;
    c.tx[l] = t.x, c.ty[l] = t.y, c.tz[l] = t.z;
}

}  // namespace mb
