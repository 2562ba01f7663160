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

Lanes3 normalOf(const ContactBatch& c) { return {c.nx, c.ny, c.nz}; }

// A body's solver fields are nine doubles in a row (physics.h): vel, spin, delta. Two bodies'
// fields go into two lanes as pairs: load a pair from each, then take the low halves together and
// the high halves together (unpcklpd, unpckhpd). The fifth pair reads a tenth double, invMass,
// and drops it: it must be a double, inside the struct.
static_assert(kLanes == 2, "gather and scatter transpose pairs of bodies");
static_assert(offsetof(PhysicsBody, spin) == 3 * sizeof(double) && offsetof(PhysicsBody, delta) == 6 * sizeof(double) &&
                  offsetof(PhysicsBody, invMass) == 9 * sizeof(double),
              "the solver's fields come first in PhysicsBody, in a row, and a double follows them");

Lanes pairAt(const PhysicsBody& body, int k) {  // fields 2k and 2k + 1
    Lanes r;
    std::memcpy(&r, reinterpret_cast<const char*>(&body.vel) + k * sizeof r, sizeof r);
    return r;
}
Lanes lows(Lanes p, Lanes q) { return __builtin_shuffle(p, q, LaneMask{0, 2}); }
Lanes highs(Lanes p, Lanes q) { return __builtin_shuffle(p, q, LaneMask{1, 3}); }

[[gnu::always_inline]] inline void gatherBodies(const PhysicsBody& p, const PhysicsBody& q, BodyLanes& to, Lanes3& delta) {
    Lanes pairs[2][5];
    for (int k = 0; k < 5; ++k) pairs[0][k] = pairAt(p, k), pairs[1][k] = pairAt(q, k);
    auto lo = [&](int k) { return lows(pairs[0][k], pairs[1][k]); };
    auto hi = [&](int k) { return highs(pairs[0][k], pairs[1][k]); };
    to.vel = {lo(0), hi(0), lo(1)};
    to.spin = {hi(1), lo(2), hi(2)};
    delta = {lo(3), hi(3), lo(4)};
}

[[gnu::always_inline]] inline PairLanes gather(const ContactBatch& c, const std::vector<PhysicsBody>& bodies) {
    PairLanes s;
    gatherBodies(bodies[size_t(c.a[0])], bodies[size_t(c.a[1])], s.a, s.deltaA);
    gatherBodies(bodies[size_t(c.b[0])], bodies[size_t(c.b[1])], s.b, s.deltaB);
    return s;
}

[[gnu::always_inline]] inline void storeLane(PhysicsBody& body, const BodyLanes& from, int l) {
    auto pick = [l](Lanes u, Lanes v) { return l == 0 ? lows(u, v) : highs(u, v); };
    const Lanes pairs[3] = {pick(from.vel.x, from.vel.y), pick(from.vel.z, from.spin.x),
                            pick(from.spin.y, from.spin.z)};
    std::memcpy(reinterpret_cast<char*>(&body.vel), pairs, sizeof pairs);
}

// Body a is written back only where it moves (the static body, shared by every level, never is).
[[gnu::always_inline]] inline void scatter(const ContactBatch& c, const LaneRows& w, const PairLanes& s, std::vector<PhysicsBody>& bodies) {
    for (int l = 0; l < c.count; ++l) {
        if (w.massA[l] > 0.0) storeLane(bodies[size_t(c.a[l])], s.a, l);
        storeLane(bodies[size_t(c.b[l])], s.b, l);
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
    return any((bits << 1) != 0);  // the sign bit shifted out
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

[[gnu::always_inline]] inline void markSupported(const ContactBatch& c, std::vector<PhysicsBody>& bodies) {
    for (int l = 0; l < c.count; ++l) {
        if (c.normalImpulse[l] <= 0.0) continue;
        bodies[size_t(c.b[l])].supported = true;
        if (c.solve.massA[l] > 0.0) bodies[size_t(c.a[l])].supported = true;
    }
}

void setRows(LaneRows& to, int l, const RowMasses& m, const InverseMasses& w) {
    to.normal[l] = m.normal, to.tangent[l] = m.tangent, to.roll[l] = m.roll;
    to.massA[l] = w.massA, to.inertiaA[l] = w.inertiaA, to.massB[l] = w.massB, to.inertiaB[l] = w.inertiaB;
}

void loadLane(ContactBatch& to, int l, const Contact& c, const std::vector<PhysicsBody>& bodies) {
    to.a[l] = c.a, to.b[l] = c.b;
    to.nx[l] = c.normal.x, to.ny[l] = c.normal.y, to.nz[l] = c.normal.z;
    to.separation[l] = c.separation, to.armA[l] = c.armA, to.armB[l] = c.armB, to.slop[l] = c.slop;
    to.curve[l] = 0.0, to.rollRadius[l] = c.rollRadius;  // curve: 0 until setCurve
    setRows(to.solve, l, c.mass, inverseMasses(c, bodies, false));
    setRows(to.relax, l, c.shock ? c.shockMass : c.mass, inverseMasses(c, bodies, true));
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
            loadLane(c, l, i < 0 ? padding : ctx.contacts[size_t(i)], ctx.bodies);
            c.count += i < 0 ? 0 : 1;
        }
    }
}

template <class Kernel>
void ContactBatches::levels(int begin, int end, const Kernel& kernel) {
    for (int i = graph_.levelBegin[size_t(begin)]; i < graph_.levelBegin[size_t(end)]; ++i) kernel(batches_[size_t(i)]);
}

// The levels of the first two runs share no body: with a worker, it takes the first run's while
// this thread takes the second's. The same bytes whatever the thread count.
template <class Kernel>
void ContactBatches::byLevels(Worker* worker, const Kernel& kernel) {
    const int* runEnd = graph_.runEnd;
    auto first = [&] { levels(0, runEnd[0], kernel); };
    if (worker) worker->post(first);
    else first();
    levels(runEnd[0], runEnd[1], kernel);
    if (worker) worker->wait();
    levels(runEnd[1], graph_.levels(), kernel);
}

void ContactBatches::warmStart(SolverContext& ctx) {
    byLevels(ctx.worker, [&](ContactBatch& c) {
        if (!anyImpulse(c)) return;
        PairLanes s = gather(c, ctx.bodies);
        applyNormal(s, c.solve, c.normalImpulse * normalOf(c));
        applyImpulse(s, c, c.solve, {c.tx, c.ty, c.tz});
        applyAngular(s, c.solve, {c.rx, c.ry, c.rz});
        scatter(c, c.solve, s, ctx.bodies);
    });
}

void ContactBatches::solve(SolverContext& ctx, bool useBias) {
    if (useBias)
        for (PhysicsBody& b : ctx.bodies) b.supported = false;
    byLevels(ctx.worker, [&](ContactBatch& c) {
        const LaneRows& w = useBias ? c.solve : c.relax;
        PairLanes s = gather(c, ctx.bodies);
        if (!solveRows(c, s, ctx, w, useBias)) return;
        scatter(c, w, s, ctx.bodies);
        if (useBias) markSupported(c, ctx.bodies);
    });
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
