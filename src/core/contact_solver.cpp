// contact_solver.cpp — normal, friction and rolling rows of sphere contacts.
#include "marchbox/contact_solver.h"

#include "marchbox/worker.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace mb {

using glm::dvec3;

namespace {

double inverseOrZero(double k) { return k > 0.0 ? 1.0 / k : 0.0; }

// The inverse mass and inertia impulses are applied with: the bodies' own, or zero for a body
// held fixed (the lower body under shock propagation).
struct Inverse {
    double massA, inertiaA, massB, inertiaB;
};

Inverse inverseOf(const PhysicsBody& a, const PhysicsBody& b) {
    return {a.invMass, a.invInertia, b.invMass, b.invInertia};
}

// Linear impulse p at the contact point: −p on a, +p on b. Both arms lie along the normal, so
// the torques are r_a·(n × p) on a and r_b·(n × p) on b, against their spins: one cross product.
// Body a is left alone where its inverse mass is 0 (the static body, or the lower body under
// shock propagation): nothing would change, and the static body, shared by both halves of the
// contacts, is never written while two threads solve them.
void applyImpulse(PhysicsBody& a, PhysicsBody& b, const Contact& c, const Inverse& w, const dvec3& p) {
    const dvec3 np = glm::cross(c.normal, p);
    if (w.massA > 0.0) {
        a.vel -= w.massA * p;
        a.spin -= (w.inertiaA * c.armA) * np;
    }
    b.vel += w.massB * p;
    b.spin -= (w.inertiaB * c.armB) * np;
}

// An impulse along the normal: both arms are parallel to it, so it exerts no torque (the cross
// products would only add rounding noise).
void applyNormal(PhysicsBody& a, PhysicsBody& b, const Inverse& w, const dvec3& p) {
    if (w.massA > 0.0) a.vel -= w.massA * p;
    b.vel += w.massB * p;
}

void applyAngular(PhysicsBody& a, PhysicsBody& b, const Inverse& w, const dvec3& l) {
    if (w.massA > 0.0) a.spin -= w.inertiaA * l;
    b.spin += w.inertiaB * l;
}

// Clamp an accumulated vector impulse to a disc: the isotropic Coulomb cone.
dvec3 clampLength(const dvec3& v, double maxLength) {
    const double len2 = glm::dot(v, v);
    return len2 > maxLength * maxLength ? v * (maxLength / std::sqrt(len2)) : v;
}

void solveNormal(Contact& c, PhysicsBody& a, PhysicsBody& b, const SolverContext& ctx, const Inverse& w,
                 double normalMass, bool useBias) {
    const double s = c.separation + glm::dot(b.delta - a.delta, c.normal);
    double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
    const bool open = s > 0.0;
    if (open) {
        bias = s / ctx.h;  // speculative: close at most the gap this substep
    } else if (useBias && s + c.slop < 0.0) {
        bias = std::max(ctx.soft.biasRate * (s + c.slop), -ctx.settings.maxPushSpeed);
        massScale = ctx.soft.massScale;
        impulseScale = ctx.soft.impulseScale;
    }
    // A curved surface bends away from the straight path a substep takes along it; the solve pass
    // aims the path's end at the surface (RATTLE's position step), the relax pass then works
    // along the normal found there (its velocity step). Exact for a circle: speed is kept.
    if (useBias) bias += c.curve / ctx.h;
    const double vn = glm::dot(b.vel - a.vel, c.normal);
    const double impulse = -normalMass * massScale * (vn + bias) - impulseScale * c.normalImpulse;
    double total = std::max(c.normalImpulse + impulse, 0.0);
    // An open contact in the relax pass may give back impulse (the solve pass's push-out) but
    // not slow an approach fast enough to bounce: the solve pass before each position update
    // already keeps it from closing past its gap, and at the end of the step that approach is
    // the next step's impact, which Impacts resolves at its time (slowed here, it would bounce
    // lower).
    if (open && !useBias && ctx.settings.impacts && vn < -bounceThreshold(ctx))
        total = std::min(total, c.normalImpulse);
    if (total == c.normalImpulse) return;  // an open speculative contact stays open: nothing to do
    applyNormal(a, b, w, (total - c.normalImpulse) * c.normal);
    c.normalImpulse = total;
    c.maxNormalImpulse = std::max(c.maxNormalImpulse, total);
}

void solveFriction(Contact& c, PhysicsBody& a, PhysicsBody& b, const Inverse& w, double tangentMass,
                   double friction) {
    // The contact points move at v_a + ω_a × r_a·n and v_b − ω_b × r_b·n; the spin terms lie in
    // the tangent plane already.
    dvec3 vt = b.vel - a.vel;
    vt -= glm::dot(vt, c.normal) * c.normal + glm::cross(c.armA * a.spin + c.armB * b.spin, c.normal);
    const dvec3 total = clampLength(c.tangentImpulse - tangentMass * vt, friction * c.normalImpulse);
    applyImpulse(a, b, c, w, total - c.tangentImpulse);
    c.tangentImpulse = total;
}

void solveRolling(Contact& c, PhysicsBody& a, PhysicsBody& b, const Inverse& w, double rollMass,
                  double resistance) {
    if (resistance <= 0.0) return;
    const dvec3 relative = b.spin - a.spin;
    const double limit = resistance * c.rollRadius * c.normalImpulse;
    const dvec3 total = clampLength(c.rollImpulse - rollMass * relative, limit);
    applyAngular(a, b, w, total - c.rollImpulse);
    c.rollImpulse = total;
}

bool idle(const Contact& c) {
    return c.normalImpulse == 0.0 && c.tangentImpulse == dvec3(0.0) && c.rollImpulse == dvec3(0.0);
}

// The rows of one contact, in Box2D's order: normal, then friction limited by the normal
// impulse just found, then rolling resistance.
void solveRows(Contact& c, PhysicsBody& a, PhysicsBody& b, const SolverContext& ctx, const RowMasses& m,
               const Inverse& w, bool useBias) {
    solveNormal(c, a, b, ctx, w, m.normal, useBias);
    // A speculative contact that stays open carries no friction: skip the rows that would find 0.
    if (idle(c)) return;
    solveFriction(c, a, b, w, m.tangent, ctx.friction);
    solveRolling(c, a, b, w, m.roll, ctx.rolling);
}

RowMasses rowMasses(const Contact& c, const Inverse& w) {
    const double kn = w.massA + w.massB;
    return {inverseOrZero(kn), inverseOrZero(kn + w.inertiaA * c.armA * c.armA + w.inertiaB * c.armB * c.armB),
            inverseOrZero(w.inertiaA + w.inertiaB)};
}

// Shock propagation (Guendelman et al. 2003) in the relax pass. A light sphere under a heavy one
// moves the heavy one by only m_light/m_heavy of what it needs per Gauss-Seidel pass, so a 1:1e4
// stack would take 1e4 passes to hold. Contacts are solved bottom-up; for a resting contact
// between two spheres one above the other, the lower one is treated as fixed, which stops the
// upper one in a single pass. Only resting contacts under gravity: impacts keep exact momentum.
bool shockPropagates(const Contact& c, const SolverContext& ctx) {
    return ctx.gravity > 0.0 && c.a != int(ctx.bodies.size()) - 1 &&
           std::abs(c.relativeVelocity) < ctx.settings.restitutionThreshold && std::abs(c.normal.y) > 0.5;
}

Inverse fixingLower(const Contact& c, const PhysicsBody& a, const PhysicsBody& b) {
    const bool aIsLower = c.normal.y > 0.0;  // the normal points from a to b
    return aIsLower ? Inverse{0.0, 0.0, b.invMass, b.invInertia} : Inverse{a.invMass, a.invInertia, 0.0, 0.0};
}

// Runs rows(begin, end) over the two halves at once, the first on the worker, then over the
// contacts that join them.
template <class Rows>
void inRuns(SolverContext& ctx, const Rows& rows) {
    const int n = int(ctx.contacts.size());
    auto first = [&] { rows(0, ctx.split[0]); };
    if (ctx.worker) ctx.worker->post(first);
    else first();
    rows(ctx.split[0], ctx.split[1]);
    if (ctx.worker) ctx.worker->wait();
    rows(ctx.split[1], n);
}

}  // namespace

double bounceThreshold(const SolverContext& ctx) {
    return ctx.gravity > 0.0 ? ctx.settings.restitutionThreshold : 0.0;
}

Softness makeSoftness(double hertz, double dampingRatio, double h) {
    if (hertz <= 0.0) return {};
    const double omega = 2.0 * M_PI * hertz;
    const double a1 = 2.0 * dampingRatio + h * omega;
    const double a2 = h * omega * a1;
    const double a3 = 1.0 / (1.0 + a2);
    return {omega / a1, a2 * a3, a3};
}

double contactSeparation(const Contact& c, const std::vector<PhysicsBody>& bodies) {
    return c.separation + glm::dot(bodies[c.b].delta - bodies[c.a].delta, c.normal);
}

void prepareContacts(SolverContext& ctx) {
    for (Contact& c : ctx.contacts) {
        const PhysicsBody& a = ctx.bodies[c.a];
        const PhysicsBody& b = ctx.bodies[c.b];
        c.mass = rowMasses(c, inverseOf(a, b));
        c.relativeVelocity = glm::dot(b.vel - a.vel, c.normal);
        c.maxNormalImpulse = 0.0;
        c.shock = shockPropagates(c, ctx);
        if (c.shock) c.shockMass = rowMasses(c, fixingLower(c, a, b));
    }
}

void warmStartContacts(SolverContext& ctx) {
    inRuns(ctx, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            const Contact& c = ctx.contacts[size_t(i)];
            if (idle(c)) continue;
            PhysicsBody& a = ctx.bodies[c.a];
            PhysicsBody& b = ctx.bodies[c.b];
            const Inverse w = inverseOf(a, b);
            applyNormal(a, b, w, c.normalImpulse * c.normal);
            applyImpulse(a, b, c, w, c.tangentImpulse);
            applyAngular(a, b, w, c.rollImpulse);
        }
    });
}

void solveContacts(SolverContext& ctx, bool useBias) {
    if (useBias)
        for (PhysicsBody& b : ctx.bodies) b.supported = false;
    inRuns(ctx, [&](int begin, int end) {
        for (int i = begin; i < end; ++i) {
            Contact& c = ctx.contacts[size_t(i)];
            PhysicsBody& a = ctx.bodies[c.a];
            PhysicsBody& b = ctx.bodies[c.b];
            if (!useBias && c.shock) {
                solveRows(c, a, b, ctx, c.shockMass, fixingLower(c, a, b), false);
                continue;
            }
            const Inverse w = inverseOf(a, b);
            solveRows(c, a, b, ctx, c.mass, w, useBias);
            // Marked here, while the bodies are in cache, rather than in a pass of its own.
            if (useBias && c.normalImpulse > 0.0) b.supported = true;
            if (useBias && c.normalImpulse > 0.0 && w.massA > 0.0) a.supported = true;
        }
    });
}

// Box2D's restitution pass: only contacts that touched this step and met at more than the
// threshold bounce, and they bounce off the normal velocity they had before the step.
void applyRestitution(SolverContext& ctx) {
    if (ctx.restitution <= 0.0) return;
    for (Contact& c : ctx.contacts) {
        if (c.relativeVelocity >= -bounceThreshold(ctx) || c.maxNormalImpulse <= 0.0)
            continue;
        PhysicsBody& a = ctx.bodies[c.a];
        PhysicsBody& b = ctx.bodies[c.b];
        const double vn = glm::dot(b.vel - a.vel, c.normal);
        const double impulse = -c.mass.normal * (vn + ctx.restitution * c.relativeVelocity);
        const double total = std::max(c.normalImpulse + impulse, 0.0);
        applyNormal(a, b, inverseOf(a, b), (total - c.normalImpulse) * c.normal);
        c.normalImpulse = total;
        c.maxNormalImpulse = std::max(c.maxNormalImpulse, total);
    }
}

}  // namespace mb
