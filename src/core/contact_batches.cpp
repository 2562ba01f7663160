// contact_batches.cpp — normal, friction and rolling rows of sphere contacts, kLanes at a time.
//
// Each function mirrors one contact's rows (Box2D v3's soft step), operation for operation. The
// branches of the one-contact form become masks (select) where they choose a value, and nothing
// where they only skipped work: a lane whose impulse does not change applies a change of 0.
// Whole batches still skip what none of their lanes needs.
#include "marchbox/contact_batches.h"

#include "marchbox/lane_math.h"
#include "marchbox/worker.h"

#include <cstddef>
#include <cstring>
#include <glm/geometric.hpp>

namespace mb {

namespace {

struct BodyLanes {
    Lanes3 vel, spin;
};

struct PairLanes {
    BodyLanes a, b;
    Lanes3 deltaA, deltaB;
};

[[gnu::always_inline]] inline Lanes3 normalOf(const ContactBatch& c) { return {c.nx, c.ny, c.nz}; }

// A body's solver fields are nine doubles in a row (physics.h): vel, spin, delta. The four bodies
// of a batch side are read as rows (vel and spin.x; spin.y and z; delta.x and y; delta.z) and
// transposed into lanes; vel and spin go back the same way, row by row, so that the next level's
// reads of the same rows come straight from these writes (a read that straddled two writes would
// wait for both to reach the cache).
static_assert(kLanes == 4, "gather and scatter transpose four bodies' rows");
static_assert(offsetof(PhysicsBody, spin) == 3 * sizeof(double) && offsetof(PhysicsBody, delta) == 6 * sizeof(double),
              "the solver's fields come first in PhysicsBody, in a row");

using Pair = double __attribute__((vector_size(2 * sizeof(double))));

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

// Four rows of four become four lanes of four, and back: c[k][l] = r[l][k].
[[gnu::always_inline]] inline void transpose(const Lanes (&r)[4], Lanes (&c)[4]) {
    const Lanes t0 = __builtin_shufflevector(r[0], r[1], 0, 4, 2, 6), t1 = __builtin_shufflevector(r[0], r[1], 1, 5, 3, 7);
    const Lanes t2 = __builtin_shufflevector(r[2], r[3], 0, 4, 2, 6), t3 = __builtin_shufflevector(r[2], r[3], 1, 5, 3, 7);
    c[0] = __builtin_shufflevector(t0, t2, 0, 1, 4, 5), c[1] = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
    c[2] = __builtin_shufflevector(t0, t2, 2, 3, 6, 7), c[3] = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
}

// Four pairs become two lanes of four.
[[gnu::always_inline]] inline void transpose(const Pair (&p)[4], Lanes& first, Lanes& second) {
    const Lanes u = __builtin_shufflevector(p[0], p[2], 0, 1, 2, 3), v = __builtin_shufflevector(p[1], p[3], 0, 1, 2, 3);
    first = __builtin_shufflevector(u, v, 0, 4, 2, 6), second = __builtin_shufflevector(u, v, 1, 5, 3, 7);
}

[[gnu::always_inline]] inline void gatherBodies(PhysicsBody* const (&p)[kLanes], BodyLanes& to, Lanes3& delta) {
    const Lanes rows[4] = {rowAt<Lanes>(*p[0], 0), rowAt<Lanes>(*p[1], 0), rowAt<Lanes>(*p[2], 0), rowAt<Lanes>(*p[3], 0)};
    Lanes lanes[4];
    transpose(rows, lanes);
    to.vel = {lanes[0], lanes[1], lanes[2]};
    to.spin.x = lanes[3];
    const Pair spins[4] = {rowAt<Pair>(*p[0], 4), rowAt<Pair>(*p[1], 4), rowAt<Pair>(*p[2], 4), rowAt<Pair>(*p[3], 4)};
    transpose(spins, to.spin.y, to.spin.z);
    const Pair deltas[4] = {rowAt<Pair>(*p[0], 6), rowAt<Pair>(*p[1], 6), rowAt<Pair>(*p[2], 6), rowAt<Pair>(*p[3], 6)};
    transpose(deltas, delta.x, delta.y);
    delta.z = Lanes{p[0]->delta.z, p[1]->delta.z, p[2]->delta.z, p[3]->delta.z};
}

[[gnu::always_inline]] inline PairLanes gather(const ContactBatch& c) {
    PairLanes s;
    gatherBodies(c.a, s.a, s.deltaA);
    gatherBodies(c.b, s.b, s.deltaB);
    return s;
}

// One side's rows: vel and spin.x in rows[l], spin.y and z in the halves of spins[l % 2].
struct BodyRows {
    Lanes rows[4];
    Lanes spins[2];
};

[[gnu::always_inline]] inline BodyRows rowsOf(const BodyLanes& from) {
    BodyRows r;
    transpose({from.vel.x, from.vel.y, from.vel.z, from.spin.x}, r.rows);
    r.spins[0] = __builtin_shufflevector(from.spin.y, from.spin.z, 0, 4, 2, 6);
    r.spins[1] = __builtin_shufflevector(from.spin.y, from.spin.z, 1, 5, 3, 7);
    return r;
}

[[gnu::always_inline]] inline void storeLane(PhysicsBody& body, const BodyRows& from, int l) {
    storeRow(body, 0, from.rows[l]);
    const Lanes& spins = from.spins[l % 2];
    storeRow(body, 4, l < 2 ? __builtin_shufflevector(spins, spins, 0, 1) : __builtin_shufflevector(spins, spins, 2, 3));
}

// Body a is written back only where it moves (the static body, shared by every level, never is).
[[gnu::always_inline]] inline void scatter(const ContactBatch& c, const LaneRows& w, const PairLanes& s) {
    const BodyRows a = rowsOf(s.a), b = rowsOf(s.b);
    for (int l = 0; l < kLanes; ++l) {
        if (l >= c.count) break;
        if (w.massA[l] > 0.0) storeLane(*c.a[l], a, l);
        storeLane(*c.b[l], b, l);
    }
}

// Linear impulse p at the contact point: −p on a, +p on b. Both arms lie along the normal, so the
// torques are r_a·(n × p) on a and r_b·(n × p) on b, against their spins: one cross product.
// A body held fixed has inverse mass 0 and is not moved; nor is a lane whose impulse did not
// change (its change is 0).
[[gnu::always_inline]] inline void applyImpulse(PairLanes& s, const ContactBatch& c, const LaneRows& w, const Lanes3& p) {
    const Lanes3 np = cross(normalOf(c), p);
    s.a.vel = s.a.vel - w.massA * p;
    s.a.spin = s.a.spin - (w.inertiaA * c.armA) * np;
    s.b.vel = s.b.vel + w.massB * p;
    s.b.spin = s.b.spin - (w.inertiaB * c.armB) * np;
}

// Along the normal there is no torque (the cross products would only add rounding noise).
[[gnu::always_inline]] inline void applyNormal(PairLanes& s, const LaneRows& w, const Lanes3& p) {
    s.a.vel = s.a.vel - w.massA * p;
    s.b.vel = s.b.vel + w.massB * p;
}

[[gnu::always_inline]] inline void applyAngular(PairLanes& s, const LaneRows& w, const Lanes3& l) {
    s.a.spin = s.a.spin - w.inertiaA * l;
    s.b.spin = s.b.spin + w.inertiaB * l;
}

// Whether any lane carries an impulse (a zero of either sign carries none).
[[gnu::always_inline]] inline bool anyImpulse(const ContactBatch& c) {
    const LaneMask bits = LaneMask(c.normalImpulse) | LaneMask(c.tx) | LaneMask(c.ty) | LaneMask(c.tz) |
                          LaneMask(c.rx) | LaneMask(c.ry) | LaneMask(c.rz);
    return any(bits << 1);  // the sign bit shifted out
}

}  // namespace

namespace {

// Returns whether any lane's impulse changed.
[[gnu::always_inline]] inline bool solveNormal(ContactBatch& c, PairLanes& s, const SolverContext& ctx, const LaneRows& w, bool useBias) {
    const Lanes3 n = normalOf(c);
    const Lanes sep = c.separation + dot(s.deltaB - s.deltaA, n);
    const Lanes zero{};
    const LaneMask open = sep > zero;
    const LaneMask push = useBias ? ~open & (sep + c.slop < zero) : LaneMask{};
    // Open: speculative, close at most the gap this substep. Pushing: soft, with bias.
    const Lanes pushBias = maxOf(ctx.soft.biasRate * (sep + c.slop), splat(-ctx.settings.maxPushSpeed));
    Lanes bias = select(open, sep / ctx.h, select(push, pushBias, zero));
    const Lanes massScale = select(push, splat(ctx.soft.massScale), splat(1.0));
    const Lanes impulseScale = select(push, splat(ctx.soft.impulseScale), zero);
    // A curved surface bends away from the straight path a substep takes along it; the solve pass
    // aims the path's end at the surface (RATTLE's position step), the relax pass then works
    // along the normal found there (its velocity step). Exact for a circle: speed is kept.
    if (useBias) bias += c.curve / ctx.h;
    const Lanes vn = dot(s.b.vel - s.a.vel, n);
    const Lanes impulse = -w.normal * massScale * (vn + bias) - impulseScale * c.normalImpulse;
    Lanes total = maxOf(c.normalImpulse + impulse, zero);
    // An open contact in the relax pass may give back impulse (the solve pass's push-out) but
    // not slow an approach fast enough to bounce: the solve pass before each position update
    // already keeps it from closing past its gap, and at the end of the step that approach is
    // the next step's impact, which Impacts resolves at its time (slowed here, it would bounce
    // lower).
    if (!useBias && ctx.settings.impacts)
        total = select(open & (vn < splat(-bounceThreshold(ctx))), minOf(total, c.normalImpulse), total);
    const LaneMask changed = total != c.normalImpulse;  // an open contact that stays open: nothing
    if (!any(changed)) return false;
    applyNormal(s, w, (total - c.normalImpulse) * n);
    c.maxNormalImpulse = select(changed, maxOf(c.maxNormalImpulse, total), c.maxNormalImpulse);
    c.normalImpulse = total;
    return true;
}

[[gnu::always_inline]] inline void solveFriction(ContactBatch& c, PairLanes& s, const LaneRows& w, double friction) {
    // The contact points move at v_a + ω_a × r_a·n and v_b − ω_b × r_b·n; the spin terms lie in
    // the tangent plane already.
    const Lanes3 n = normalOf(c);
    Lanes3 vt = s.b.vel - s.a.vel;
    vt = vt - (dot(vt, n) * n + cross(c.armA * s.a.spin + c.armB * s.b.spin, n));
    const Lanes3 old{c.tx, c.ty, c.tz};
    const Lanes3 total = clampLength(old - w.tangent * vt, friction * c.normalImpulse);
    applyImpulse(s, c, w, total - old);
    c.tx = total.x, c.ty = total.y, c.tz = total.z;
}

[[gnu::always_inline]] inline void solveRolling(ContactBatch& c, PairLanes& s, const LaneRows& w, double resistance) {
    if (resistance <= 0.0) return;
    const Lanes3 relative = s.b.spin - s.a.spin;
    const Lanes limit = resistance * c.rollRadius * c.normalImpulse;
    const Lanes3 old{c.rx, c.ry, c.rz};
    const Lanes3 total = clampLength(old - w.roll * relative, limit);
    applyAngular(s, w, total - old);
    c.rx = total.x, c.ry = total.y, c.rz = total.z;
}

// The rows of a contact, in Box2D's order: normal, then friction limited by the normal impulse
// just found, then rolling resistance. A speculative contact that stays open carries no friction:
// a batch of them skips the rows that would find 0. Returns whether the bodies may have moved.
[[gnu::always_inline]] inline bool solveRows(ContactBatch& c, PairLanes& s, const SolverContext& ctx, const LaneRows& w, bool useBias) {
    const bool moved = solveNormal(c, s, ctx, w, useBias);
    if (!anyImpulse(c)) return moved;
    solveFriction(c, s, w, ctx.friction);
    solveRolling(c, s, w, ctx.rolling);
    return true;
}

[[gnu::always_inline]] inline void markSupported(const ContactBatch& c) {
    for (int l = 0; l < kLanes; ++l) {
        if (l >= c.count) break;
        if (c.normalImpulse[l] <= 0.0) continue;
        c.b[l]->supported = true;
        if (c.solve.massA[l] > 0.0) c.a[l]->supported = true;
    }
}

void setRows(LaneRows& to, int l, const RowMasses& m, const InverseMasses& w) {
    to.normal[l] = m.normal, to.tangent[l] = m.tangent, to.roll[l] = m.roll;
    to.massA[l] = w.massA, to.inertiaA[l] = w.inertiaA, to.massB[l] = w.massB, to.inertiaB[l] = w.inertiaB;
}

void loadLane(ContactBatch& to, int l, Contact& c, const SolverContext& ctx) {
    const PreparedRows rows = prepareContact(c, ctx);
    to.a[l] = &ctx.bodies[size_t(c.a)], to.b[l] = &ctx.bodies[size_t(c.b)];
    to.nx[l] = c.normal.x, to.ny[l] = c.normal.y, to.nz[l] = c.normal.z;
    to.separation[l] = c.separation, to.armA[l] = c.armA, to.armB[l] = c.armB, to.slop[l] = c.slop;
    to.curve[l] = 0.0, to.rollRadius[l] = c.rollRadius;  // curve: 0 until setCurve
    setRows(to.solve, l, c.mass, rows.solve);
    setRows(to.relax, l, rows.relaxMass, rows.relax);
    to.normalImpulse[l] = c.normalImpulse, to.maxNormalImpulse[l] = c.maxNormalImpulse;
    to.tx[l] = c.tangentImpulse.x, to.ty[l] = c.tangentImpulse.y, to.tz[l] = c.tangentImpulse.z;
    to.rx[l] = c.rollImpulse.x, to.ry[l] = c.rollImpulse.y, to.rz[l] = c.rollImpulse.z;
}

}  // namespace

void ContactBatches::load(const SolverContext& ctx) {
    const int staticBody = int(ctx.bodies.size()) - 1;
    buildContactGraph(ctx.contacts, ctx.split, staticBody, graph_, scratch_);
    Contact padding;  // on the static body alone, no mass, no impulse: never written back
    padding.a = padding.b = staticBody;
    batches_.resize(size_t(graph_.batches()));
    for (int k = 0; k < graph_.batches(); ++k) {
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

// One pass's batches, levels [levelBegin[k], levelBegin[k + 1]) for level k.
struct Pass {
    ContactBatch* batches;
    const int* levelBegin;
    SolverContext& ctx;
    bool useBias;
};
using PassLevels = void (*)(const Pass& pass, int begin, int end);  // levels [begin, end)

// Each pass is compiled for AVX-512 and AVX2, where the CPU has them (one instruction for the
// four lanes, chosen at load time), and for baseline x86-64. Without FMA every product rounds on
// its own, so all give the same bytes. Clang (the fuzz build) rejects the clones' inlined lane
// helpers as an ABI change, and other CPUs have other names: those build the baseline alone.
#if defined(__x86_64__) && !defined(__clang__)
#define MB_PASS_CLONES [[gnu::target_clones("arch=x86-64-v4", "avx2", "default")]]
#else
#define MB_PASS_CLONES
#endif

MB_PASS_CLONES void warmStartLevels(const Pass& pass, int begin, int end) {
    for (int i = pass.levelBegin[begin]; i < pass.levelBegin[end]; ++i) {
        ContactBatch& c = pass.batches[i];
        if (!anyImpulse(c)) continue;
        PairLanes s = gather(c);
        applyNormal(s, c.solve, c.normalImpulse * normalOf(c));
        applyImpulse(s, c, c.solve, {c.tx, c.ty, c.tz});
        applyAngular(s, c.solve, {c.rx, c.ry, c.rz});
        scatter(c, c.solve, s);
    }
}

template <bool useBias>
[[gnu::always_inline]] inline void solveBatches(const Pass& pass, int begin, int end) {
    for (int i = pass.levelBegin[begin]; i < pass.levelBegin[end]; ++i) {
        ContactBatch& c = pass.batches[i];
        const LaneRows& w = useBias ? c.solve : c.relax;
        PairLanes s = gather(c);
        if (!solveRows(c, s, pass.ctx, w, useBias)) continue;
        scatter(c, w, s);
        if (useBias) markSupported(c);
    }
}

// The solve and relax passes compiled apart, each with what it does not use left out.
MB_PASS_CLONES void solveLevels(const Pass& pass, int begin, int end) {
    if (pass.useBias) solveBatches<true>(pass, begin, end);
    else solveBatches<false>(pass, begin, end);
}

// The levels of the first two runs share no body: with a worker, it takes the first run's while
// this thread takes the second's. The same bytes whatever the thread count.
void byLevels(const ContactGraph& graph, PassLevels levels, const Pass& pass) {
    Worker* worker = pass.ctx.worker;
    auto first = [&] { levels(pass, 0, graph.runEnd[0]); };
    if (worker) worker->post(first);
    else first();
    levels(pass, graph.runEnd[0], graph.runEnd[1]);
    if (worker) worker->wait();
    levels(pass, graph.runEnd[1], graph.levels());
}

}  // namespace

void ContactBatches::warmStart(SolverContext& ctx) {
    byLevels(graph_, warmStartLevels, {batches_.data(), graph_.levelBegin.data(), ctx, true});
}

void ContactBatches::solve(SolverContext& ctx, bool useBias) {
    if (useBias)
        for (PhysicsBody& b : ctx.bodies) b.supported = false;
    byLevels(graph_, solveLevels, {batches_.data(), graph_.levelBegin.data(), ctx, useBias});
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
