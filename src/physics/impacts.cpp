// impacts.cpp — impacts at their time of impact, in time order (see impacts.h).
#include "impacts.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>

namespace mb {

using glm::dvec3;

namespace {

// Clamp a vector impulse to a disc: the isotropic Coulomb cone.
dvec3 clampLength(const dvec3& v, double maxLength) {
    const double len2 = glm::dot(v, v);
    return len2 > maxLength * maxLength ? v * (maxLength / std::sqrt(len2)) : v;
}

}  // namespace

int Impacts::resolve(SolverContext& ctx) {
    const std::vector<PhysicsBody>& bodies = ctx.bodies;
    const size_t n = bodies.size(), contacts = ctx.contacts.size();
    any_ = linked_ = false;
    if (ctx.maxRestitution <= 0.0 || contacts == 0) return 0;  // e = 0: the solver's stop is exact
    // A body a contact pushed at the end of the last step rests on it: no free fall this step.
    accel_.assign(n, dvec3(0.0));
    for (size_t i = 0; i + 1 < n; ++i)
        if (bodies[i].awake && !bodies[i].supported) accel_[i].y = -ctx.gravity;
    offset_.assign(n, dvec3(0.0));
    hit_.assign(n, 0);
    moved_.clear();
    stamp_.assign(contacts, 0);
    count_.assign(contacts, 0);
    heap_.clear();
    // Free flight changes a contact's approach speed by at most |g|·dt in the step: one that
    // starts (Contact::relativeVelocity, before any impact) 2|g|·dt above the threshold, room for
    // rounding, cannot impact until an impact on its bodies finds it again. Most contacts of a
    // pile are such, and skipping them leaves their bodies unread.
    const double reach = -bounceThreshold(ctx) + 2.0 * std::abs(ctx.gravity) * ctx.settings.dt;
    // Which contacts are open, and which of those are due, is anyone's guess contact by contact:
    // each list is written in full and counted on where the contact belongs, with no branch.
    open_.resize(contacts);
    due_.resize(contacts);
    size_t open = 0, due = 0;
    for (size_t i = 0; i < contacts; ++i) {
        open_[open] = int(i);
        open += ctx.contacts[i].normalImpulse > 0.0 ? 0 : 1;
    }
    open_.resize(open);
    for (int i : open_) {
        due_[due] = i;
        due += ctx.contacts[size_t(i)].relativeVelocity < reach ? 1 : 0;
    }
    for (size_t k = 0; k < due; ++k) schedule(ctx, due_[k], 0.0);
    const int staticBody = int(n) - 1;
    int impacts = 0;
    while (!heap_.empty()) {
        std::pop_heap(heap_.begin(), heap_.end(), std::greater<>());
        const Event ev = heap_.back();
        heap_.pop_back();
        if (ev.stamp != stamp_[size_t(ev.contact)]) continue;  // its bodies were hit since
        if (count_[size_t(ev.contact)]++ >= ctx.settings.impactsPerContact) continue;
        const Contact& c = ctx.contacts[size_t(ev.contact)];
        hit(ctx, c, ev.time);
        ++impacts;
        any_ = true;
        if (!linked_) linkBodies(ctx);
        for (int body : {c.a, c.b}) {  // their other contacts' impacts move: find them again
            if (body == staticBody) continue;
            for (int k = first_[size_t(body)]; k < first_[size_t(body) + 1]; ++k) {
                const int j = links_[size_t(k)];
                ++stamp_[size_t(j)];
                schedule(ctx, j, ev.time);
            }
        }
    }
    if (any_) shiftSeparations(ctx.contacts);
    return impacts;
}

// The substeps integrate each body from its start with the velocity it has after its impacts,
// which is its true flight after the last impact, moved by −offset. Each contact's separation is
// moved to match, so that the solver sees where the bodies really go. Before an impact that
// flight, run backwards, lies inside what the body hit, so the solver sees the pair start
// overlapped by (1 + e)·|u|·t* but part at e·|u|: its soft push, biasRate·overlap < 10/s · dt ·
// (1 + e)·|u|, is slower than that for e above 0.1, and the relax pass takes back what it adds.
// Only the contacts of bodies hit move (the others' shift is 0): they are listed, without a
// branch, and correctPositions takes the shift back out of them alone.
void Impacts::shiftSeparations(std::vector<Contact>& contacts) {
    shifted_.resize(contacts.size());
    size_t count = 0;
    for (size_t i = 0; i < contacts.size(); ++i) {
        shifted_[count] = int(i);
        count += hit_[size_t(contacts[i].a)] | hit_[size_t(contacts[i].b)];
    }
    shifted_.resize(count);
    for (int i : shifted_) {
        Contact& c = contacts[size_t(i)];
        c.shift = glm::dot(c.normal, offset_[size_t(c.b)] - offset_[size_t(c.a)]);
        c.separation += c.shift;
    }
}

glm::dvec3 Impacts::offset(int body) const {
    return any_ ? offset_[size_t(body)] : glm::dvec3(0.0);
}

// In free flight a contact's separation is a parabola in t:
//   s(t) = s0 + n·(Δoffset + Δv·t + ½·Δa·t²),
// Δ meaning b's minus a's. Its first zero after `now` is an impact if the bodies then close
// faster than the threshold; a contact already touching at `now` and closing is one at once.
void Impacts::schedule(const SolverContext& ctx, int contact, double now) {
    const Contact& c = ctx.contacts[size_t(contact)];
    // A contact that bore load last step (a ball in a pile) is the solver's: its impulses are
    // shared with its neighbours' at once, not passed down the pile one impact at a time.
    if (c.normalImpulse > 0.0) return;
    const PhysicsBody &a = ctx.bodies[size_t(c.a)], &b = ctx.bodies[size_t(c.b)];
    const double c0 =
        c.separation + glm::dot(c.normal, offset_[size_t(c.b)] - offset_[size_t(c.a)]);
    const double c1 = glm::dot(c.normal, b.vel - a.vel);
    const double c2 = glm::dot(c.normal, accel_[size_t(c.b)] - accel_[size_t(c.a)]);
    const double s = c0 + c1 * now + 0.5 * c2 * now * now, u = c1 + c2 * now;
    const double threshold = -bounceThreshold(ctx);
    double t = now;
    if (s > 0.0) {
        // s + u·τ + ½·c2·τ² = 0: the smaller root, written 2s / (−u + √D) so that it keeps its
        // precision when c2 is small (it is then s / −u), and needs no case for c2 = 0.
        const double d = u * u - 2.0 * s * c2;
        if (d < 0.0) return;
        const double den = std::sqrt(d) - u;
        if (den <= 0.0) return;
        t = now + 2.0 * s / den;
        if (t > ctx.settings.dt) return;
    }
    if (c1 + c2 * t >= threshold) return;  // too slow to bounce: the solver stops it
    heap_.push_back({t, contact, stamp_[size_t(contact)]});
    std::push_heap(heap_.begin(), heap_.end(), std::greater<>());
}

// Newton's law at t: the normal velocity u becomes −e·u, an impulse (1 + e)·|u| / K_n along n.
// Friction opposes the slip at the contact point, at most μ times that, never more than stops
// the slip (K_t): so an impact never adds energy.
void Impacts::hit(SolverContext& ctx, const Contact& c, double t) {
    PhysicsBody &a = ctx.bodies[size_t(c.a)], &b = ctx.bodies[size_t(c.b)];
    const dvec3 va = a.vel + accel_[size_t(c.a)] * t, vb = b.vel + accel_[size_t(c.b)] * t;
    const double kn = a.invMass + b.invMass;
    if (kn <= 0.0) return;
    const double u = glm::dot(c.normal, vb - va);
    const double pn = -(1.0 + c.restitution) * u / kn;
    const dvec3 armA = c.normal * c.armA, armB = -c.normal * c.armB;
    dvec3 slip = (vb + glm::cross(b.spin, armB)) - (va + glm::cross(a.spin, armA));
    slip -= glm::dot(slip, c.normal) * c.normal;
    const double kt = kn + a.invInertia * c.armA * c.armA + b.invInertia * c.armB * c.armB;
    const dvec3 p = pn * c.normal + clampLength(-slip / kt, c.friction * pn);
    a.vel -= a.invMass * p;
    a.spin -= a.invInertia * glm::cross(armA, p);
    b.vel += b.invMass * p;
    b.spin += b.invInertia * glm::cross(armB, p);
    offset_[size_t(c.a)] += a.invMass * p * t;  // −Δv·t
    offset_[size_t(c.b)] -= b.invMass * p * t;
    for (int body : {c.a, c.b}) {
        if (ctx.bodies[size_t(body)].invMass <= 0.0 || hit_[size_t(body)])
            continue;  // the static body stays
        hit_[size_t(body)] = 1;
        moved_.push_back(body);
    }
}

// Each dynamic body's contacts that may impact (open_: schedule() leaves those that bore load to
// the solver), for finding their impacts again after it is hit. Built on the first impact of a
// step.
void Impacts::linkBodies(const SolverContext& ctx) {
    const int staticBody = int(ctx.bodies.size()) - 1;
    first_.assign(ctx.bodies.size() + 1, 0);
    for (int j : open_)
        for (int body : {ctx.contacts[size_t(j)].a, ctx.contacts[size_t(j)].b})
            if (body != staticBody) ++first_[size_t(body) + 1];
    for (size_t i = 1; i < first_.size(); ++i) first_[i] += first_[i - 1];
    links_.resize(size_t(first_.back()));
    std::vector<int>& next = next_;
    next.assign(first_.begin(), first_.end() - 1);
    for (int j : open_)
        for (int body : {ctx.contacts[size_t(j)].a, ctx.contacts[size_t(j)].b})
            if (body != staticBody) links_[size_t(next[size_t(body)]++)] = j;
    linked_ = true;
}

void Impacts::correctPositions(std::vector<PhysicsBody>& bodies,
                               std::vector<Contact>& contacts) const {
    if (!any_) return;
    for (int i : shifted_) {
        Contact& c = contacts[size_t(i)];
        c.separation -= c.shift;
        c.shift = 0.0;
    }
    for (int i : moved_) {
        bodies[size_t(i)].pos += offset_[size_t(i)];
        bodies[size_t(i)].delta += offset_[size_t(i)];
    }
}

}  // namespace mb
