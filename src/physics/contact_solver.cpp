// contact_solver.cpp — what each sphere contact needs for a step, and the restitution pass.
#include "contact_solver.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace mb {

namespace {

double inverseOrZero(double k) { return k > 0.0 ? 1.0 / k : 0.0; }

InverseMasses inverseOf(const PhysicsBody& a, const PhysicsBody& b) {
    return {a.invMass, a.invInertia, b.invMass, b.invInertia};
}

RowMasses rowMasses(const Contact& c, const InverseMasses& w) {
    const double kn = w.massA + w.massB;
    return {inverseOrZero(kn),
            inverseOrZero(kn + w.inertiaA * c.armA * c.armA + w.inertiaB * c.armB * c.armB),
            inverseOrZero(w.inertiaA + w.inertiaB)};
}

// Shock propagation (Guendelman et al. 2003) in the relax pass. A light sphere under a heavy one
// moves the heavy one by only m_light/m_heavy of what it needs per Gauss-Seidel pass, so a 1:1e4
// stack would take 1e4 passes to hold. Contacts are solved bottom-up; for a resting contact
// between two spheres one above the other, the lower one is treated as fixed, which stops the
// upper one in a single pass. Only resting contacts under gravity: impacts keep exact momentum.
bool shockPropagates(const Contact& c, const SolverContext& ctx) {
    const bool falling = ctx.gravity > 0.0, onSphere = c.a != int(ctx.bodies.size()) - 1;
    const bool resting = std::abs(c.relativeVelocity) < ctx.settings.restitutionThreshold;
    const bool stacked = std::abs(c.normal.y) > 0.5;
    return falling & onSphere & resting &
           stacked;  // & where && would branch on each, the later ones anyone's guess
}

InverseMasses fixingLower(const Contact& c, const PhysicsBody& a, const PhysicsBody& b) {
    const bool aIsLower = c.normal.y > 0.0;  // the normal points from a to b
    return aIsLower ? InverseMasses{0.0, 0.0, b.invMass, b.invInertia}
                    : InverseMasses{a.invMass, a.invInertia, 0.0, 0.0};
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

PreparedRows prepareContact(Contact& c, const SolverContext& ctx) {
    const PhysicsBody& a = ctx.bodies[size_t(c.a)];
    const PhysicsBody& b = ctx.bodies[size_t(c.b)];
    const InverseMasses own = inverseOf(a, b);
    c.mass = rowMasses(c, own);
    c.relativeVelocity = glm::dot(b.vel - a.vel, c.normal);
    c.maxNormalImpulse = 0.0;
    c.shock = shockPropagates(c, ctx);
    if (!c.shock) return {own, own, c.mass};
    const InverseMasses fixed = fixingLower(c, a, b);
    return {own, fixed, rowMasses(c, fixed)};
}

// Box2D's restitution pass, `iterations` times: only contacts that touched this step and met at
// more than the threshold bounce, and they bounce off the normal velocity they had before the
// step. The passes change neither condition, so the contacts are found once. Along the normal
// there is no torque; body a is left alone where it does not move (the static body).
void applyRestitution(SolverContext& ctx, int iterations, std::vector<int>& bouncing) {
    if (ctx.maxRestitution <= 0.0) return;
    bouncing.resize(ctx.contacts.size());
    size_t count = 0;
    for (size_t i = 0; i < ctx.contacts.size(); ++i) {  // written in full, counted where it bounces
        const Contact& c = ctx.contacts[i];
        bouncing[count] = int(i);
        count +=
            size_t(c.relativeVelocity < -bounceThreshold(ctx)) & size_t(c.maxNormalImpulse > 0.0);
    }
    bouncing.resize(count);
    for (int k = 0; k < iterations; ++k)
        for (int i : bouncing) {
            Contact& c = ctx.contacts[size_t(i)];
            PhysicsBody& a = ctx.bodies[c.a];
            PhysicsBody& b = ctx.bodies[c.b];
            const double vn = glm::dot(b.vel - a.vel, c.normal);
            const double impulse = -c.mass.normal * (vn + c.restitution * c.relativeVelocity);
            const double total = std::max(c.normalImpulse + impulse, 0.0);
            const glm::dvec3 p = (total - c.normalImpulse) * c.normal;
            if (a.invMass > 0.0) a.vel -= a.invMass * p;
            b.vel += b.invMass * p;
            c.normalImpulse = total;
            c.maxNormalImpulse = std::max(c.maxNormalImpulse, total);
        }
}

}  // namespace mb
