// contact_solver.cpp — normal, friction and rolling rows of sphere contacts.
#include "marchbox/contact_solver.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace mb {

using glm::dvec3;

namespace {

double inverseOrZero(double k) { return k > 0.0 ? 1.0 / k : 0.0; }

// Linear impulse p at the contact point: −p on a, +p on b.
void applyImpulse(PhysicsBody& a, PhysicsBody& b, const Contact& c, const dvec3& p) {
    a.vel -= a.invMass * p;
    a.spin -= a.invInertia * glm::cross(c.normal * c.armA, p);
    b.vel += b.invMass * p;
    b.spin += b.invInertia * glm::cross(-c.normal * c.armB, p);
}

void applyAngular(PhysicsBody& a, PhysicsBody& b, const dvec3& l) {
    a.spin -= a.invInertia * l;
    b.spin += b.invInertia * l;
}

// Clamp an accumulated vector impulse to a disc: the isotropic Coulomb cone.
dvec3 clampLength(const dvec3& v, double maxLength) {
    const double len = glm::length(v);
    return len > maxLength ? v * (maxLength / len) : v;
}

void solveNormal(Contact& c, PhysicsBody& a, PhysicsBody& b, const SolverContext& ctx, bool useBias) {
    const double s = contactSeparation(c, ctx.bodies);
    double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
    if (s > 0.0) {
        bias = s / ctx.h;  // speculative: close at most the gap this substep
    } else if (useBias && s + c.slop < 0.0) {
        bias = std::max(ctx.soft.biasRate * (s + c.slop), -ctx.settings.maxPushSpeed);
        massScale = ctx.soft.massScale;
        impulseScale = ctx.soft.impulseScale;
    }
    const double vn = glm::dot(b.vel - a.vel, c.normal);
    const double impulse = -c.normalMass * massScale * (vn + bias) - impulseScale * c.normalImpulse;
    const double total = std::max(c.normalImpulse + impulse, 0.0);
    applyImpulse(a, b, c, (total - c.normalImpulse) * c.normal);
    c.normalImpulse = total;
    c.maxNormalImpulse = std::max(c.maxNormalImpulse, total);
}

void solveFriction(Contact& c, PhysicsBody& a, PhysicsBody& b, double friction) {
    const dvec3 va = a.vel + glm::cross(a.spin, c.normal * c.armA);
    const dvec3 vb = b.vel + glm::cross(b.spin, -c.normal * c.armB);
    dvec3 vt = vb - va;
    vt -= glm::dot(vt, c.normal) * c.normal;
    const dvec3 total = clampLength(c.tangentImpulse - c.tangentMass * vt, friction * c.normalImpulse);
    applyImpulse(a, b, c, total - c.tangentImpulse);
    c.tangentImpulse = total;
}

void solveRolling(Contact& c, PhysicsBody& a, PhysicsBody& b, double resistance) {
    if (resistance <= 0.0) return;
    const dvec3 relative = b.spin - a.spin;
    const double limit = resistance * c.rollRadius * c.normalImpulse;
    const dvec3 total = clampLength(c.rollImpulse - c.rollMass * relative, limit);
    applyAngular(a, b, total - c.rollImpulse);
    c.rollImpulse = total;
}

// The rows of one contact, in Box2D's order: normal, then friction limited by the normal
// impulse just found, then rolling resistance.
void solveRows(Contact& c, PhysicsBody& a, PhysicsBody& b, const SolverContext& ctx, bool useBias) {
    solveNormal(c, a, b, ctx, useBias);
    // A speculative contact that stays open carries no friction: skip the rows that would find 0.
    if (c.normalImpulse == 0.0 && c.tangentImpulse == dvec3(0.0) && c.rollImpulse == dvec3(0.0)) return;
    solveFriction(c, a, b, ctx.friction);
    solveRolling(c, a, b, ctx.settings.rollingResistance);
}

void setMasses(Contact& c, const PhysicsBody& a, const PhysicsBody& b) {
    const double kn = a.invMass + b.invMass;
    c.normalMass = inverseOrZero(kn);
    c.tangentMass = inverseOrZero(kn + a.invInertia * c.armA * c.armA + b.invInertia * c.armB * c.armB);
    c.rollMass = inverseOrZero(a.invInertia + b.invInertia);
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

void solveFixingLower(Contact& c, PhysicsBody& a, PhysicsBody& b, const SolverContext& ctx) {
    const bool aIsLower = c.normal.y > 0.0;  // the normal points from a to b
    PhysicsBody lower = aIsLower ? a : b;
    lower.invMass = lower.invInertia = 0.0;
    Contact fixed = c;
    setMasses(fixed, aIsLower ? lower : a, aIsLower ? b : lower);
    solveRows(fixed, aIsLower ? lower : a, aIsLower ? b : lower, ctx, false);
    c.normalImpulse = fixed.normalImpulse;
    c.tangentImpulse = fixed.tangentImpulse;
    c.rollImpulse = fixed.rollImpulse;
}

}  // namespace

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
        setMasses(c, a, b);
        c.relativeVelocity = glm::dot(b.vel - a.vel, c.normal);
        c.maxNormalImpulse = 0.0;
    }
}

void warmStartContacts(SolverContext& ctx) {
    for (Contact& c : ctx.contacts) {
        if (c.normalImpulse == 0.0 && c.tangentImpulse == dvec3(0.0) && c.rollImpulse == dvec3(0.0)) continue;
        PhysicsBody& a = ctx.bodies[c.a];
        PhysicsBody& b = ctx.bodies[c.b];
        applyImpulse(a, b, c, c.normalImpulse * c.normal + c.tangentImpulse);
        applyAngular(a, b, c.rollImpulse);
    }
}

void solveContacts(SolverContext& ctx, bool useBias) {
    for (Contact& c : ctx.contacts) {
        PhysicsBody& a = ctx.bodies[c.a];
        PhysicsBody& b = ctx.bodies[c.b];
        if (!useBias && shockPropagates(c, ctx))
            solveFixingLower(c, a, b, ctx);
        else
            solveRows(c, a, b, ctx, useBias);
    }
}

// Box2D's restitution pass: only contacts that touched this step and met at more than the
// threshold bounce, and they bounce off the normal velocity they had before the step.
void applyRestitution(SolverContext& ctx) {
    if (ctx.restitution <= 0.0) return;
    for (Contact& c : ctx.contacts) {
        if (c.relativeVelocity > -ctx.settings.restitutionThreshold || c.maxNormalImpulse <= 0.0)
            continue;
        PhysicsBody& a = ctx.bodies[c.a];
        PhysicsBody& b = ctx.bodies[c.b];
        const double vn = glm::dot(b.vel - a.vel, c.normal);
        const double impulse = -c.normalMass * (vn + ctx.restitution * c.relativeVelocity);
        const double total = std::max(c.normalImpulse + impulse, 0.0);
        applyImpulse(a, b, c, (total - c.normalImpulse) * c.normal);
        c.normalImpulse = total;
        c.maxNormalImpulse = std::max(c.maxNormalImpulse, total);
    }
}

}  // namespace mb
