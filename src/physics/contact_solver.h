// contact_solver.h — sequential impulses on sphere contacts, Box2D v3 style soft step:
// the contacts, their row masses for a step and the restitution pass. The substeps' rows run in
// batches (contact_batches.h).
//
// A contact joins body a and body b along a unit normal from a to b. A static surface is the
// world's static body (zero inverse mass and velocity) as a. Both contact arms lie along the
// normal, so the normal row has no angular part and the tangent row is isotropic:
//   K_n = 1/m_a + 1/m_b,   K_t = K_n + r_a²/I_a + r_b²/I_b,   K_roll = 1/I_a + 1/I_b.
// Within a step the normal is fixed and the separation follows the bodies' displacements:
//   s = s0 + n·(Δx_b − Δx_a).
#pragma once

#include "marchbox/physics/physics.h"

#include <glm/vec3.hpp>
#include <vector>

namespace mb {

// Effective masses of a contact's rows: 1/K_n, 1/K_t, 1/K_roll.
struct RowMasses {
    double normal = 0.0, tangent = 0.0, roll = 0.0;
};

struct Contact {
    int a = 0, b = 0;               // bodies; a is the static body for a static surface
    int feature = -1;               // StaticHit::feature, or -1 between two spheres
    bool shock = false;             // the relax pass holds the lower body fixed
    bool curved = false;            // a static surface that curves: followed every substep
    glm::dvec3 normal{0, 1, 0};     // from a to b
    double separation = 0.0;        // at the start of the step; < 0 overlaps
    double armA = 0.0, armB = 0.0;  // centre to contact point, along ±normal
    double slop = 0.0;              // overlap left alone, m
    RowMasses mass;
    double rollRadius = 0.0;  // lever of rolling resistance
    double friction = 0.0;    // the pair's (surface.h)
    double restitution = 0.0;
    double shift = 0.0;             // added to separation for the impacts (impacts.h), m
    double relativeVelocity = 0.0;  // normal velocity at the start of the step (after the
                                    // impacts, from prepareContact), for bounce
    double normalImpulse = 0.0;     // accumulated per substep, warm started across steps
    double maxNormalImpulse = 0.0;  // largest this step: did it touch?
    glm::dvec3 tangentImpulse{0.0};
    glm::dvec3 rollImpulse{0.0};
};

// Soft constraint coefficients for one substep h (Box2D v3 b2MakeSoft): a spring of angular
// frequency ω = 2πf and damping ratio ζ, integrated implicitly:
//   biasRate = ω / (2ζ + hω),  massScale = hω(2ζ + hω) / (1 + hω(2ζ + hω)),
//   impulseScale = 1 / (1 + hω(2ζ + hω)).
struct Softness {
    double biasRate = 0.0, massScale = 1.0, impulseScale = 0.0;
};
Softness makeSoftness(double hertz, double dampingRatio, double h);

// The inverse masses and inertias a contact's impulses are applied with: the bodies' own, or 0
// for a body held fixed (the lower body under shock propagation, in the relax pass).
struct InverseMasses {
    double massA, inertiaA, massB, inertiaB;
};

class Worker;

struct SolverContext {
    std::vector<PhysicsBody>& bodies;  // the static body last
    std::vector<Contact>& contacts;
    const PhysicsSettings& settings;
    double gravity;         // m/s² along −y
    double maxRestitution;  // of any contact: 0, and nothing bounces
    double rolling;         // rolling resistance: torque = rolling · radius · normal force
    double h;               // substep, s
    Softness soft;
    // The contacts come in three runs: [0, split[0]) and [split[0], split[1]) share no dynamic
    // body, so the solver takes the two at once, the first on `worker` (null: one thread), with
    // the same result as one after the other; [split[1], end) joins them, after both.
    int split[2] = {0, 0};
    Worker* worker = nullptr;
};

// Impacts slower than this do not bounce: settings.restitutionThreshold under gravity, where
// resting contacts meet at the speed gravity gives them in a step; 0 without gravity. Inline: the
// relax pass asks for it per batch, and a call there would spill every vector register it holds.
inline double bounceThreshold(const SolverContext& ctx) {
    return ctx.gravity > 0.0 ? ctx.settings.restitutionThreshold : 0.0;
}

// What a contact's rows apply this step: the inverse masses of the solve pass, and of the relax
// pass with its row masses (other than the solve pass's under shock propagation).
struct PreparedRows {
    InverseMasses solve, relax;
    RowMasses relaxMass;
};
// Row masses, the approach speed and shock propagation of one contact, for this step, from its
// bodies. The contacts must be sorted bottom-up for shock propagation (see the .cpp).
PreparedRows prepareContact(Contact& c, const SolverContext& ctx);
void applyRestitution(SolverContext& ctx, int iterations,
                      std::vector<int>& bouncing);  // bouncing: scratch
double contactSeparation(const Contact& c, const std::vector<PhysicsBody>& bodies);  // now

}  // namespace mb
