// rigid_rows.h — the rigid bodies' contacts, and their rows as the solver sweeps them: each
// point's normal row, and each manifold's friction and rolling rows at its centre, with
// everything a sweep reads made once a step.
#pragma once

#include <cstdint>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

namespace mb {

struct RigidBody;

// Where a contact's point on one side has gone since the step began.
struct AnchorPath {
    const glm::dvec3* delta = nullptr;   // displacement this step; null: a static side
    const glm::dquat* orient = nullptr;  // null where the anchor does not turn with the body
    glm::dvec3 anchor{0.0};              // contact point − centre, world, at the step's start
    // Where the anchor goes as the body turns: a point of the body (localAnchor, its frame) and
    // an offset that stays put in the world. A corner turns with the body (offset 0); a round
    // surface's contact stays below its centre, the probe's, which turns (offset −ρ·normal).
    glm::dvec3 localAnchor{0.0};
    glm::dvec3 offset{0.0};
};

// What a contact's impulses move on one side: a rigid body, a sphere, or nothing (static).
struct ContactSide : AnchorPath {
    RigidBody* rigid = nullptr;  // where the side is a rigid body
    int body = -1;               // a rigid body's index, or count() + a sphere's; −1: static
    glm::dvec3* vel = nullptr;
    glm::dvec3* spin = nullptr;
    bool* supported = nullptr;
    double invMass = 0.0;
    double sphereInverseInertia = 0.0;  // 1 / I, where the side is a sphere
};

struct RigidContact {
    ContactSide a, b;       // the normal points from a to b
    std::uint64_t key = 0;  // the pair and the probe, for warm starting
    glm::dvec3 normal{0.0, 1.0, 0.0};
    double separation = 0.0;  // at the step's start; < 0 overlaps
    double height = 0.0;      // of its manifold's lowest point: solved bottom-up
    double friction = 0.0, restitution = 0.0;
    double normalImpulse = 0.0;     // last step's, to start the row from
    double relativeVelocity = 0.0;  // normal, at the step's start, for restitution
};

// What a row's impulses move on each side: the velocity and spin, and the inverse mass (0 for
// a static or sleeping side, whose pointers may be null).
struct RowBodies {
    glm::dvec3 *velA = nullptr, *spinA = nullptr, *velB = nullptr, *spinB = nullptr;
    double invMassA = 0.0, invMassB = 0.0;
};

// A contact's normal row as the sweeps read and write it: what they touch and nothing else, a
// third of a RigidContact, so that a pile's rows stay in cache through the substeps.
struct NormalRow : RowBodies {
    bool *supportedA = nullptr, *supportedB = nullptr;
    glm::dvec3 normal{0.0};
    glm::dvec3 armA{0.0}, armB{0.0};    // anchor × normal, each side
    glm::dvec3 turnA{0.0}, turnB{0.0};  // I⁻¹·arm: the spin a unit impulse gives
    double mass = 0.0;                  // 1 / K along the normal
    double impulse = 0.0, maxImpulse = 0.0;
};

// Two rows solved as one: K⁻¹ for their 2×2 effective mass K, where K's off-diagonal is what
// one row's impulse does to the other's speed. Each row's own mass would let both answer a
// motion they share, and give it twice over: a rod 6 cm thick lying against a wall spins about
// its axis under both tangents' arms, and each sweep turned that spin back the other way,
// larger (4,500 rad/s, three times the energy, within a step).
struct PairMass {
    double m00 = 0.0, m01 = 0.0, m11 = 0.0;

    // The impulses that bring speeds (s0, s1) to 0.
    double first(double s0, double s1) const { return -(m00 * s0 + m01 * s1); }
    double second(double s0, double s1) const { return -(m01 * s0 + m11 * s1); }
};

// A manifold's friction rows at its centre: all that a sweep reads and writes, with the crosses
// and I⁻¹ products done once a step (each tangent's arm, anchor × tangent, and turn, I⁻¹·arm,
// per side, the twist's I⁻¹·n, and rolling's I⁻¹·t about each tangent). The manifold keeps
// these alone: the RigidContact they are made from is not read again this step.
struct FrictionRows : RowBodies {
    glm::dvec3 normal{0.0}, tangent[2];
    glm::dvec3 armA[2], armB[2], turnA[2], turnB[2];
    glm::dvec3 twistA{0.0}, twistB{0.0};
    glm::dvec3 rollA[2], rollB[2];
    double friction = 0.0, twistMass = 0.0, twistArm = 0.0;
    PairMass tangentMass, rollMass;  // each pair of rows solved as one
    double rollLimit = 0.0;  // rolling resistance · rolling radius: the torque's bound a push
    double tangentImpulse[2] = {0.0, 0.0}, twistImpulse = 0.0;  // from last step's, on
    double rollImpulse[2] = {0.0, 0.0};                         // about the tangents
};

// A pair's points that face one way, solved together: its points' normal rows are rows
// [begin, end) of the step's, and its friction and rolling are at their centre.
struct RigidManifold {
    int begin = 0, end = 0;  // its points' rows, and their contacts
    std::uint64_t key = 0;   // its friction's, for warm starting
    bool impact = false;     // a point came in faster than kImpactSpeed: swept until it settles
    // The bodies its rows move (ContactSide::body), −1 for a side they hold fixed.
    int movesA = -1, movesB = -1;
    int sweeps = 1;     // in the relax pass: last step's, until this step's are known
    FrictionRows rows;  // the points' friction and rolling, at their centre
};

}  // namespace mb
