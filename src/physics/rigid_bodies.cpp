// rigid_bodies.cpp — bodies of every shape but the sphere: their contacts, rows and motion.
#include "rigid_bodies.h"

#include "island.h"
#include "manifold_points.h"
#include "pair_table.h"
#include "rigid_body.h"
#include "tetra_gradient.h"

#include "marchbox/scene/shapes.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_access.hpp>
#include <limits>
#include <map>
#include <optional>
#include <ranges>
#include <span>
#include <string>
#include <tuple>
#include <utility>

namespace mb {

using glm::dmat3;
using glm::dquat;
using glm::dvec3;

dquat RigidBody::shapeOrient() const {
    return framed ? glm::normalize(orient * glm::conjugate(axes)) : orient;
}

dvec3 RigidBody::origin() const { return framed ? pos - shapeOrient() * centre : pos; }

namespace {

constexpr double kImpactSpeed = 3.0;      // m/s: a point coming in faster makes an impact (solve)
constexpr int kImpactSweeps = 4;          // times the relax pass's sweeps, at most, for an impact
constexpr int kStaticKeyBase = 128;       // static probes' contact keys: 128 to 254 (255: friction)
constexpr int kStaticKeys = 127;          // of them
constexpr double kOwnSurface = 1e-4;      // of a body's bound: a point this near lies on it
constexpr int kSideScan = 6;              // samples along a side against a shape not convex
constexpr double kSideLevel = 0.1;        // of the slop: a side's stretch this level is a line
constexpr size_t kLookAhead = 16;         // contacts whose warm start is asked for ahead
constexpr double kSweepTolerance = 1e-3;  // m/s: a sweep that changed no row more has converged
constexpr double kTurnTolerance = 0.1;    // of an inverse inertia, moved by a turn (followTurns)
constexpr int kNewtonSteps = 4;           // at most, projecting a point onto a bound's surface
constexpr int kGroupManifold = 8;         // points a group's manifold keeps (reduceManifold)
constexpr int kTraceSteps = 64;           // at most, along a ray to a bound's surface
// A landing no further than this times the bound certifies it: the true distance lies between
// the two. The gradient's direction is good to ~1e-3 (fineGradient), which moves the landing by
// its square; the float differences near an edge by ~1e-4. Within it, the bound is used.
constexpr double kCertified = 1.0 + 1e-3;

// The shape alone, at the origin and unturned: the body's frame.
SdfObject shapeOf(const Object& o) {
    Object at = o;
    at.pos = glm::vec3(0.0f);
    at.rot = glm::vec3(0.0f);
    at.orient.reset();
    at.op = CsgOp::Union;
    at.blend = 0.0f;
    return makeSdfObject(at);
}

dmat3 worldInverseInertia(const dquat& q, const dvec3& inertia) {
    const dmat3 r = glm::mat3_cast(q);
    return r * dmat3(1.0 / inertia.x, 0, 0, 0, 1.0 / inertia.y, 0, 0, 0, 1.0 / inertia.z) *
           glm::transpose(r);
}

// Body b's kinetic energy moving at `vel`, spinning at `spin` (world), turned by `orient`.
double kineticEnergyOf(const RigidBody& b, const dvec3& vel, const dvec3& spin,
                       const dquat& orient) {
    const dvec3 local = glm::conjugate(orient) * spin;
    return 0.5 * glm::dot(vel, vel) / b.invMass + 0.5 * glm::dot(local * b.inertia, local);
}

// Where a step's arithmetic overflowed for a body (a cone 10¹⁰ m tall and 10⁻¹⁰ m wide, pushed
// out of the ground it stands 5·10⁹ m deep in), NaN would go on into every later step, into the
// bodies it touches and into the scene saved, which would then not load; so would a value past
// a float's range, which the scene stores (a box 10³⁰ m long, turning in the ground). Such a
// body is put back where the step began, still; true where it was.
bool holdIfOverflowed(RigidBody& b) {
    auto inRange = [](auto v) {
        for (int i = 0; i < v.length(); ++i)
            if (!(std::abs(v[i]) <= std::numeric_limits<float>::max())) return false;
        return true;
    };
    if (inRange(b.pos) && inRange(b.vel) && inRange(b.spin) && inRange(b.orient)) return false;
    b.pos = b.startPos;
    b.orient = b.startOrient;
    b.vel = b.spin = dvec3(0.0);
    b.invInertia = worldInverseInertia(b.orient, b.inertia);
    return true;
}

// How far the inverse inertia the rows were made with is from the body's now, relative to the
// body's own: the largest element of their difference in the principal frame, each scaled by
// √(I_i·I_j), where the inverse inertia itself is the identity. Measured element by element in
// the world, the rod's transverse rows could be 10⁴ times wrong under a tenth of its axial one.
double turnError(const RigidBody& b) {
    const dmat3 turn = glm::mat3_cast(b.orient);
    const dmat3 moved = glm::transpose(turn) * (b.invInertia - b.rowInertia) * turn;
    double most = 0.0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            most = std::max(most, std::abs(moved[c][r]) * std::sqrt(b.inertia[c] * b.inertia[r]));
    return most;
}

// The body's signed distance at world point p, and its gradient (tetrahedral differences in
// the shape's frame, where the float SDF sees small numbers, turned back to world).
struct ShapeSample {
    double distance;
    dvec3 normal;
    bool creased = false;  // the normal's samples straddled an edge or corner (normalAt)
};

// p in the shape's frame (the body's, moved to its centre and turned to its axes where framed).
glm::vec3 localPoint(const RigidBody& b, const dvec3& p) {
    const dvec3 local = glm::conjugate(b.orient) * (p - b.pos);
    return glm::vec3(b.framed ? b.centre + b.axes * local : local);
}

double shapeDistance(const RigidBody& b, const glm::vec3& l) {
    return b.groupShape ? double(b.groupShape->distance(l)) : double(sdObjectLocal(b.shape, l));
}

double distanceTo(const RigidBody& b, const dvec3& p) { return shapeDistance(b, localPoint(b, p)); }

// Whether world point p lies on the body's own surface (or in it), not carved away: where a
// partial probe's sphere meets another surface (Probe::partial).
bool onOwnSurface(const RigidBody& b, const dvec3& p) {
    return distanceTo(b, p) <= kOwnSurface * b.bound;
}

// 4h·∇f in the shape's frame (tetra_gradient.h), unnormalised.
dvec3 gradientAt(const RigidBody& b, const dvec3& p, double* step) {
    const float h = float(kTetraStep * b.bound);
    *step = double(h);
    return tetraGradient([&b](const glm::vec3& l) { return shapeDistance(b, l); }, localPoint(b, p),
                         h);
}

dvec3 toWorld(const RigidBody& b, const dvec3& shapeVector) {
    return b.orient * (b.framed ? glm::conjugate(b.axes) * shapeVector : shapeVector);
}

// The gradient by central differences a tenth as wide as gradientAt's: Newton's steps go along
// it, and near a crease of the distance (as far from a cup's wall as from its floor) a wider
// difference averages the two sides and steps off the nearest point. Good to ~1e-3 in float.
dvec3 fineGradient(const RigidBody& b, const dvec3& p) {
    const glm::vec3 l = localPoint(b, p);
    const float h = float(1e-4 * b.bound);
    dvec3 g;
    for (int k = 0; k < 3; ++k) {
        glm::vec3 e(0.0f);
        e[k] = h;
        g[k] = (shapeDistance(b, l + e) - shapeDistance(b, l - e)) / (2.0 * double(h));
    }
    return toWorld(b, g);
}

// `creased`, where asked: whether the gradient's four samples straddled an edge or a corner of
// the shape (isCreased).
dvec3 normalAt(const RigidBody& b, const dvec3& p, bool* creased = nullptr) {
    double h;
    const dvec3 n = gradientAt(b, p, &h);
    const double len = glm::length(n);
    if (creased) *creased = isCreased(len, h);
    return toWorld(b, len > 0.0 ? n / len : dvec3(0, 1, 0));
}

// How far along the ray from p (outside) the surface is, sphere tracing the body's SDF (a bound
// never steps past it): infinite beyond `limit`, or where the ray takes too many steps.
double traceRay(const RigidBody& b, const dvec3& p, const dvec3& dir, double limit, double tol) {
    double t = 0.0;
    for (int k = 0; k < kTraceSteps; ++k) {
        const double f = distanceTo(b, p + t * dir);
        if (f <= tol) return t;
        t += f;
        if (t > limit) break;
    }
    return std::numeric_limits<double>::infinity();
}

// The nearest point of the surface seen from p (outside) lies on the ray to it, first on that
// ray: p's distance is the least over directions of how far the rays go. The gradient's
// direction and a cube's six faces and eight corners (one of them within 37° of any direction,
// so a face at distance d is met by 1.25·d), then a pattern search about the best: tilts of a
// quarter radian that halve whenever none is shorter, to 0.25°. Rays end at `limit`, what the
// caller can use; with none shorter, the distance is `limit`.
ShapeSample searchSurface(const RigidBody& b, const dvec3& p, const dvec3& down, double limit,
                          double tol) {
    dvec3 best = down;
    double shortest = traceRay(b, p, down, limit, tol);
    for (int k = 0; k < 14; ++k) {
        dvec3 dir(0.0);
        if (k < 6) {
            dir[k % 3] = k < 3 ? 1.0 : -1.0;
        } else {
            dir = glm::normalize(dvec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1));
        }
        const double t = traceRay(b, p, dir, limit, tol);
        if (t < shortest) shortest = t, best = dir;
    }
    if (!std::isfinite(shortest)) return {limit, -down};
    for (double tilt = 0.25; tilt > 4e-3;) {
        const dvec3 u = glm::normalize(
            glm::cross(best, std::abs(best.x) < 0.57 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
        const dvec3 v = glm::cross(best, u);
        bool shorter = false;
        for (const dvec3& side : {u, -u, v, -v}) {
            const dvec3 dir = glm::normalize(best + tilt * side);
            const double t = traceRay(b, p, dir, shortest, tol);
            if (t < shortest) shortest = t, best = dir, shorter = true;
        }
        if (!shorter) tilt *= 0.5;
    }
    return {shortest, -best};
}

// Where the body's SDF is a bound, `bound` (its value at p) may be far below the distance to
// what is drawn: over a cup, max(outer, −inner) is the distance to a lid across its mouth.
// Newton's steps along the gradient, x −= f·∇f/|∇f|², take p onto f = 0, a point of the true
// surface, and p's distance is measured from it, |p − x|: no less than the true distance, and
// certified where it is no more than |f(p)|, which is no more than the true distance (an exact
// SDF's first step lands so). Where the steps do not land so (over the cup's mouth they go back
// and forth between its rim's plane and the carved cylinder's top), the rays find the distance,
// up to `limit` (searchSurface). Points inside keep the bound, landing or not: a push out no
// deeper than the true one, so they take no steps.
ShapeSample projectOntoSurface(const RigidBody& b, const dvec3& p, double bound, double limit) {
    if (bound <= 0.0) return {bound, normalAt(b, p)};
    const double tol = 1e-6 * b.bound;
    dvec3 x = p, down(0.0, -1.0, 0.0);
    double f = bound;
    for (int k = 0; k < kNewtonSteps && std::abs(f) > tol; ++k) {
        const dvec3 g = fineGradient(b, x);
        const double g2 = glm::dot(g, g);
        if (g2 < 1e-12) break;
        if (k == 0) down = -g / std::sqrt(g2);
        x -= f * g / g2;
        f = distanceTo(b, x);
    }
    const double gap = glm::length(p - x);
    if (std::abs(f) <= tol && gap <= kCertified * std::abs(bound) + tol)
        return {bound, normalAt(b, p)};
    ShapeSample found = searchSurface(b, p, down, limit, tol);
    if (std::abs(f) <= tol && gap < found.distance) found = {gap, (p - x) / gap};
    return found;
}

// The distance to what is drawn where it is under `reach`: exact shapes as they are (the normal
// left to the caller), bounds projected onto their surface.
ShapeSample surfaceNear(const RigidBody& b, const dvec3& p, double reach) {
    const double bound = distanceTo(b, p);
    if (b.exact || bound >= reach) return {bound, dvec3(0.0)};
    return projectOntoSurface(b, p, bound, reach);
}

// Above the float SDF's rounding (~1e-6 of the bound) and a group's probes' distance off its
// surface (1e-5 of it, groupProbes): the box culls skip only what the SDF puts out of reach too.
double boxSlack(const RigidBody& b) { return 1e-4 * b.bound; }

// The pair's reach between two bodies' boxes: its reach and both boxes' slack.
double boxReach(const RigidBody& a, const RigidBody& b, double reach) {
    return reach + boxSlack(a) + boxSlack(b);
}

// A group met by a body, both with parts, is probed part against part (near_parts.h).
bool partwise(const RigidBody& a, const RigidBody& b) {
    return (a.groupShape || b.groupShape) && !a.parts.empty() && !b.parts.empty();
}

// Whether p (world) lies at least `reach` from a group's shape by its parts' boxes, so that its
// distance there, which would be no less, need not be found. An object's own distance costs no
// more than a box's, and a group's is only bounded by parts where it has them.
bool beyondParts(const RigidBody& b, const dvec3& p, double reach) {
    if (!b.groupShape || b.parts.empty()) return false;
    const dvec3 local = glm::conjugate(b.orient) * (p - b.pos);
    const double far = reach + boxSlack(b);
    if (distanceToBox(b.hull, local) >= far) return true;
    for (const OrientedBox& part : b.parts)
        if (distanceToBox(part, local) < far) return false;
    return true;
}

// The shape's distance and normal at p, for a sphere of `radius` about p, where the shape's
// bounding sphere, its parts' boxes and its distance bound leave it within `reach` (the distance
// projected onto the surface where the SDF is a bound); none where it is out of reach.
std::optional<ShapeSample> sampleNear(const RigidBody& shape, const dvec3& p, double radius,
                                      double reach) {
    if (glm::length(p - shape.pos) - radius >= shape.bound + reach) return std::nullopt;
    if (beyondParts(shape, p, radius + reach)) return std::nullopt;
    const double bound = distanceTo(shape, p);
    if (bound - radius >= reach) return std::nullopt;
    if (!shape.exact) return projectOntoSurface(shape, p, bound, radius + reach);
    ShapeSample sample{bound, dvec3(0.0)};
    sample.normal = normalAt(shape, p, &sample.creased);
    return sample;
}

// anchor × normal: the turn that moves a side's point along the normal. On a solid of
// revolution every normal to the surface meets the axis, so at a true contact that arm has no
// part along the axis; at a probe's point beside it (a rim's quarter turns from its lowest
// point) such a part reads the spin about the axis as that point closing in: a disc spinning
// at 600 rad/s on edge against a wall read 120 m/s and was thrown off at 50 m/s.
dvec3 normalArm(const ContactSide& s, const dvec3& normal) {
    dvec3 arm = glm::cross(s.anchor, normal);
    if (s.rigid && s.rigid->revolved) {
        const dvec3 axis = s.rigid->orient * dvec3(0.0, 1.0, 0.0);
        arm -= glm::dot(arm, axis) * axis;
    }
    return arm;
}

// The speed along the normal at which the sides' points part (> 0) or close, from the contact
// and its row's arms (normalArm): what restitution measures the approach by.
double normalVelocity(const RigidContact& c, const NormalRow& r) {
    double v = glm::dot(c.normal, *c.b.vel) + glm::dot(r.armB, *c.b.spin);
    if (c.a.vel) v -= glm::dot(c.normal, *c.a.vel) + glm::dot(r.armA, *c.a.spin);
    return v;
}

// The normal row's speed and impulse: normalVelocity's sums, and an impulse along the normal,
// with the crosses done once a step.
double normalSpeed(const NormalRow& r) {
    const double b = glm::dot(r.normal, *r.velB) + glm::dot(r.armB, *r.spinB);
    return r.velA ? b - glm::dot(r.normal, *r.velA) - glm::dot(r.armA, *r.spinA) : b;
}

void applyNormal(NormalRow& r, double impulse) {
    if (r.invMassA > 0.0) {
        *r.velA -= r.invMassA * impulse * r.normal;
        *r.spinA -= impulse * r.turnA;
    }
    if (r.invMassB > 0.0) {
        *r.velB += r.invMassB * impulse * r.normal;
        *r.spinB += impulse * r.turnB;
    }
}

RowBodies bodiesOf(const RigidContact& c) {
    return {c.a.vel, c.a.spin, c.b.vel, c.b.spin, c.a.invMass, c.b.invMass};
}

// 1 / K for an impulse λ·d at the contact, r × d being the arm and I⁻¹·(r × d) the turn on each
// side: K = Σ 1/m + Σ arm·turn.
double rowMass(const RowBodies& r, const dvec3& armA, const dvec3& turnA, const dvec3& armB,
               const dvec3& turnB) {
    double k = r.invMassA + r.invMassB;
    if (r.invMassA > 0.0) k += glm::dot(armA, turnA);
    if (r.invMassB > 0.0) k += glm::dot(armB, turnB);
    return k > 0.0 ? 1.0 / k : 0.0;
}

// K⁻¹ of two rows whose K is [[k00, k01], [k01, k11]]. K is positive definite where either
// side moves (each row's own mass is positive): 0 where neither does.
PairMass invertPair(double k00, double k01, double k11) {
    const double det = k00 * k11 - k01 * k01;
    if (!(det > 0.0)) return {};
    return {k11 / det, -k01 / det, k00 / det};
}

// What a normal row's arms do through each side's inverse inertia (world): the turns and the
// row's mass.
void setTurns(NormalRow& r, const dmat3& invInertiaA, const dmat3& invInertiaB) {
    r.turnA = invInertiaA * r.armA;
    r.turnB = invInertiaB * r.armB;
    r.mass = rowMass(r, r.armA, r.turnA, r.armB, r.turnB);
}

// ... and a manifold's friction and rolling rows', from their normal, tangents and arms.
void setTurns(FrictionRows& r, const dmat3& invInertiaA, const dmat3& invInertiaB) {
    double twist = 0.0;
    if (r.invMassA > 0.0) twist += glm::dot(r.normal, invInertiaA * r.normal);
    if (r.invMassB > 0.0) twist += glm::dot(r.normal, invInertiaB * r.normal);
    r.twistMass = twist > 0.0 ? 1.0 / twist : 0.0;
    for (int k = 0; k < 2; ++k) {
        r.turnA[k] = invInertiaA * r.armA[k];
        r.turnB[k] = invInertiaB * r.armB[k];
        r.rollA[k] = r.invMassA > 0.0 ? invInertiaA * r.tangent[k] : dvec3(0.0);
        r.rollB[k] = r.invMassB > 0.0 ? invInertiaB * r.tangent[k] : dvec3(0.0);
    }
    // Tangent i's speed from tangent j's unit impulse: along it, and through each side's turn.
    auto tangents = [&](int i, int j) {
        double k = i == j ? r.invMassA + r.invMassB : 0.0;
        if (r.invMassA > 0.0) k += glm::dot(r.armA[i], r.turnA[j]);
        if (r.invMassB > 0.0) k += glm::dot(r.armB[i], r.turnB[j]);
        return k;
    };
    auto rolls = [&](int i, int j) { return glm::dot(r.tangent[i], r.rollA[j] + r.rollB[j]); };
    r.tangentMass = invertPair(tangents(0, 0), tangents(0, 1), tangents(1, 1));
    r.rollMass = invertPair(rolls(0, 0), rolls(0, 1), rolls(1, 1));
    r.twistA = invInertiaA * r.normal;
    r.twistB = invInertiaB * r.normal;
}

// A side's inverse inertia (world) as its rows take it: 0 where they hold it fixed. A rigid
// body's is the one it had as the step's contacts were made (rowInertia), until it turns.
dmat3 inverseInertiaOf(const ContactSide& s) {
    if (s.invMass == 0.0) return dmat3(0.0);
    return s.rigid ? s.rigid->rowInertia : dmat3(s.sphereInverseInertia);
}

NormalRow rowOf(const RigidContact& c) {
    NormalRow r;
    static_cast<RowBodies&>(r) = bodiesOf(c);
    r.supportedA = c.a.supported;
    r.supportedB = c.b.supported;
    r.normal = c.normal;
    r.armA = normalArm(c.a, c.normal);
    r.armB = normalArm(c.b, c.normal);
    setTurns(r, inverseInertiaOf(c.a), inverseInertiaOf(c.b));
    r.impulse = c.normalImpulse;
    return r;
}

// Two unit tangents with the normal n, from the normal alone, so a persisting contact keeps its
// friction impulse's frame from step to step.
void tangentsOf(const dvec3& n, dvec3 (&tangent)[2]) {
    const dvec3 other = std::abs(n.x) < 0.57 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
    tangent[0] = glm::normalize(glm::cross(other, n));
    tangent[1] = glm::cross(n, tangent[0]);
}

// A bounce: the normal speed the contact leaves with at the step's end, and how far past the
// surface the body should be by then (0 where it touched from the step's start).
struct Bounce {
    double speed, rise;
};

Bounce bounceOf(const RigidContact& c, double accel, double dt) {
    const double v0 = c.relativeVelocity, s0 = c.separation;
    if (s0 <= 0.0) return {-c.restitution * v0, 0.0};
    // The first root of s0 + v0·t + ½·a·t² = 0 (v0 < 0: approaching), written to avoid the
    // cancellation of −v0 − √(v0² − 2·a·s0).
    const double root = std::sqrt(std::max(0.0, v0 * v0 - 2.0 * accel * s0));
    const double t = std::min(dt, 2.0 * s0 / (-v0 + root));
    const double after = dt - t, out = -c.restitution * (v0 + accel * t);
    return {out + accel * after, out * after + 0.5 * accel * after * after};
}

// Whole impulses at a manifold's centre, as the warm start applies them and undo takes them
// back: along each tangent, the twist about the normal, and rolling about each tangent.
void applyCentre(FrictionRows& r, double sign) {
    const double t0 = sign * r.tangentImpulse[0], t1 = sign * r.tangentImpulse[1];
    const double w = sign * r.twistImpulse;
    const double l0 = sign * r.rollImpulse[0], l1 = sign * r.rollImpulse[1];
    const dvec3 p = t0 * r.tangent[0] + t1 * r.tangent[1];
    if (r.invMassA > 0.0) {
        *r.velA -= r.invMassA * p;
        *r.spinA -=
            w * r.twistA + t0 * r.turnA[0] + t1 * r.turnA[1] + l0 * r.rollA[0] + l1 * r.rollA[1];
    }
    if (r.invMassB > 0.0) {
        *r.velB += r.invMassB * p;
        *r.spinB +=
            w * r.twistB + t0 * r.turnB[0] + t1 * r.turnB[1] + l0 * r.rollB[0] + l1 * r.rollB[1];
    }
}

// The contact keys of a body's rim r: its four support points' from rimKey, and its sixteen
// points' (leastAlongRim), after every rim's support points, from rimPointKey.
int rimKey(const RigidBody& b, int r) { return int(b.probes.size()) + 4 * r; }
int rimPointKey(const RigidBody& b, int r) {
    return int(b.probes.size() + 4 * b.rims.size()) + kRimPoints * r;
}

// The first contact key of a body's sides (probeSide, two each), after its probes' and its
// rims'; an ellipsoid's support point's, after its sides'.
int sideKey(const RigidBody& b) { return int(b.probes.size()) + kRimIds * int(b.rims.size()); }
int supportKey(const RigidBody& b) { return sideKey(b) + kSideIds * int(b.sides.size()); }

// The body's side k (RigidBody::sides) in the world.
Side worldSide(const RigidBody& b, int k) {
    Side s = b.sides[size_t(k)];
    s.from = b.pos + b.orient * s.from;
    s.to = b.pos + b.orient * s.to;
    return s;
}

// A contact's key: its first body + 1 in the top 24 bits, its second + 1 in the next 24, its
// manifold in the byte above its probe's. A static surface has no second body, and its feature
// is its manifold's byte. A scene of many static objects has more than 255 surfaces: from 256
// on, the feature would spill into the second body's bits (surface 256 named body 0, and joined
// its body to body 0's island), so it takes those bits, under kStaticSurface, which no body's
// index reaches (kMaxObjects is 4096). The first 255 keep their byte, and so the order their
// manifolds are solved in, and every result of the scenes that have them.
constexpr std::uint64_t kStaticSurface = std::uint64_t(1) << 39;

std::uint64_t pairKey(int a, int b) {
    return std::uint64_t(a + 1) << 40 | std::uint64_t(b + 1) << 16;
}

std::uint64_t staticKey(int a, int feature) {
    if (feature < 256) return pairKey(a, -1) | std::uint64_t(feature) << 8;
    return std::uint64_t(a + 1) << 40 | kStaticSurface | std::uint64_t(feature) << 16;
}

// The two bodies a key names (−1: the static scene).
std::pair<int, int> pairOf(std::uint64_t key) {
    const int second = key & kStaticSurface ? -1 : int(key >> 16 & 0xffffff) - 1;
    return {int(key >> 40) - 1, second};
}

void setSurface(RigidContact& k, const Surface& pair) {
    k.friction = pair.friction;
    k.restitution = pair.restitution;
}

template <class Candidate>
double lowest(const std::vector<Candidate>& all) {
    double low = all.empty() ? 0.0 : all[0].point.y;
    for (const Candidate& c : all) low = std::min(low, c.point.y);
    return low;
}

// A manifold's points that can meet their surface within the step, with its nearest: those no
// further from the surface than it by more than the speculative distance and what the bodies'
// turning (`turn`, m/s at their bounds) brings nearer. A body falling fast flat on its face
// reaches, by the bodies' whole motion, probes far up its sides; kept among the four most spread
// points, they took the place of the face's corners, which alone then stopped it, turned it, and
// the ground's friction sent it sliding.
void keepNearest(std::vector<PairCandidate>& all, double speculative, double turn, double dt) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const PairCandidate& c : all) nearest = std::min(nearest, c.separation);
    const double limit = nearest + speculative + 2.0 * turn * dt;
    std::erase_if(all, [limit](const PairCandidate& c) { return c.separation > limit; });
}

// Where a side of an analytic contact turns from: a capsule's segment point, r + ½·s behind the
// contact along the normal (`behind`: −1 on a's side, +1 on b's); a box's point turns with it.
dvec3 coreOf(const RigidBody& body, const PairContact& c, double behind) {
    if (body.shape.type != ShapeType::Capsule) return c.point;
    return c.point + behind * (double(body.shape.radius) + 0.5 * c.separation) * c.normal;
}

// Every object but the solid sphere (the spheres' solver has those) and every group.
bool rigidObject(const Object& o) {
    return o.dynamic() && (o.type != ShapeType::Sphere || o.shell > 0.0f);
}

// The shape's parts (in its frame) in the body's, x_body = axes⁻¹·(x_shape − centre), and
// their hull; set once the body's frame is.
void setParts(RigidBody& b, const std::vector<OrientedBox>& shapeParts) {
    const dquat toBody = glm::conjugate(b.axes);
    b.parts.clear();
    for (const OrientedBox& part : shapeParts)
        b.parts.push_back(placed(part, toBody, -(toBody * b.centre)));
    b.hull = boxAround(b.parts);
}

void setMass(RigidBody& b, const MassProperties& mp) {
    b.invMass = 1.0 / mp.mass;
    b.inertia = mp.inertia;
    b.invInertia = worldInverseInertia(b.orient, b.inertia);
}

RigidBody objectBody(const Object& o, int index, const World& world) {
    RigidBody b;
    const MassProperties mp = massProperties(o);
    const dquat turn = glm::normalize(dquat(o.orientation()));
    b.framed = mp.centre != dvec3(0.0);  // a cone: its axes are its own
    b.centre = mp.centre;
    b.pos = b.framed ? dvec3(o.pos) + turn * b.centre : dvec3(o.pos);
    b.vel = dvec3(o.vel);
    b.spin = dvec3(o.spin);
    b.orient = turn;
    setMass(b, mp);
    b.shape = shapeOf(o);
    b.bound = double(b.shape.bound) + glm::length(b.centre);
    b.exact = exactShape(b.shape);
    b.ellipsoid = o.type == ShapeType::Ellipsoid;
    b.revolved = shapeRow(o.type).revolved || (b.ellipsoid && o.size.x == o.size.z);
    b.surface = surfaceOf(o, world);
    b.object = index;
    b.probes = probesOf(o);
    b.rims = rimsOf(o);
    if (const std::optional<Side> side = sideOf(b.shape)) b.sides = {*side};
    if (b.ellipsoid) b.sides = ellipsoidSides(dvec3(o.size));
    if (b.exact) setParts(b, {boxAbout(b.shape)});
    if (b.framed) {
        for (Probe& p : b.probes) p.local -= b.centre;
        for (Rim& r : b.rims) r.centre -= b.centre;
        for (Side& side : b.sides) side.from -= b.centre, side.to -= b.centre;
    }
    return b;
}

// The bytes that make a group's shape (not its place, materials or motion): groups of the same
// shape share their mass properties and probes, found once.
std::string shapeKey(const GroupShape& shape) {
    std::string key;
    auto add = [&key](const auto& value) {
        key.append(reinterpret_cast<const char*>(&value), sizeof value);
    };
    auto addVec = [&add](const glm::vec3& v) { add(v.x), add(v.y), add(v.z); };
    for (const SdfObject& o : shape.sdf.objects) {
        add(int(o.type)), add(int(o.op)), add(o.group);
        addVec(o.pos), addVec(o.size);
        for (int c = 0; c < 3; ++c) addVec(o.toLocal[c]);
        for (float v : {o.radius, o.minor, o.height, o.blend, o.top, o.round, o.shell}) add(v);
    }
    for (const SdfGroup& g : shape.sdf.groups) {
        add(g.parent), add(int(g.op)), add(g.first), add(g.last), add(g.blend);
        addVec(g.pos), addVec(g.spacing);
        for (int c = 0; c < 3; ++c) addVec(g.toLocal[c]);
        for (int a = 0; a < 3; ++a) add(int(g.mirror[a])), add(g.repeat[a]);
    }
    return key;
}

struct GroupFound {
    Moments moments;
    GroupProbes probes;
};

Surface surfaceOf(const Group& g, const World& world) {
    return {double(g.friction.value_or(world.friction)),
            double(g.restitution.value_or(world.restitution))};
}

// False for a group with no solid: nothing to move.
bool groupBody(const Scene& scene, int g, std::map<std::string, GroupFound>& found,
               RigidBody* out) {
    const Group& group = scene.groups[size_t(g)];
    auto shape = std::make_shared<GroupShape>(groupShapeOf(scene, g));
    if (shape->empty()) return false;
    const std::string key = shapeKey(*shape);
    auto it = found.find(key);
    if (it == found.end()) {
        const Moments moments =
            rememberedMoments(key, [&] { return groupMoments(*shape).moments; });
        it = found
                 .emplace(key, GroupFound{moments, moments.volume > 0.0 ? groupProbes(*shape)
                                                                        : GroupProbes{}})
                 .first;
    }
    if (it->second.moments.volume <= 0.0) return false;
    const MassProperties mp = massFromMoments(it->second.moments, double(group.mass));
    RigidBody& b = *out;
    const dquat turn = glm::normalize(dquat(group.orientation()));
    b.framed = true;
    b.centre = mp.centre;
    b.axes = mp.axes;
    b.orient = glm::normalize(turn * b.axes);
    b.pos = dvec3(group.pos) + turn * b.centre;
    b.vel = dvec3(group.vel);
    b.spin = dvec3(group.spin);
    setMass(b, mp);
    b.groupShape = shape;
    b.bound = shape->bound + glm::length(b.centre);
    b.surface = surfaceOf(group, scene.world);
    b.group = g;
    setParts(b, unionParts(*shape));
    // A union of exact members is exact outside it, and its hull holds it more tightly than the
    // sphere about the group's origin.
    b.exact = !b.parts.empty();
    if (b.exact) b.bound = std::min(b.bound, glm::length(b.hull.centre) + glm::length(b.hull.half));
    const dquat toBody = glm::conjugate(b.axes);
    for (const Probe& p : it->second.probes.probes)
        b.probes.push_back({toBody * (p.local - b.centre), p.radius, p.part, p.partial});
    for (const Rim& r : it->second.probes.rims)
        b.rims.push_back(
            {toBody * (r.centre - b.centre), r.radius, toBody * r.axis, r.tube, r.part, r.core});
    for (Side side : it->second.probes.sides) {
        side.from = toBody * (side.from - b.centre);
        side.to = toBody * (side.to - b.centre);
        b.sides.push_back(side);
    }
    return true;
}

}  // namespace

// The bodies in the scene's tree order: a top-level group where it stands, before
// objects[first]; StaticCollider ids handed out in the same order, each body's in one run.
RigidBodies::RigidBodies(const Scene& scene, const PhysicsSettings& settings)
    : settings_(settings),
      rolling_(scene.world.rolling),
      dt_(settings.dt),
      statics_(withoutBodyMembers(scene)) {
    std::map<std::string, GroupFound> found;
    size_t g = 0;
    auto groupsBefore = [&](size_t i) {
        for (; g < scene.groups.size() && size_t(scene.groups[g].first) <= i; ++g) {
            const Group& group = scene.groups[g];
            RigidBody b;
            if (group.dynamic() && groupBody(scene, int(g), found, &b))
                bodies_.push_back(std::move(b));
        }
    };
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        groupsBefore(i);
        const Object& o = scene.objects[i];
        if (rigidObject(o)) bodies_.push_back(objectBody(o, int(i), scene.world));
    }
    groupsBefore(scene.objects.size());
    int ids = 0;
    for (RigidBody& b : bodies_) {
        b.staticIds = ids;
        // The probes', the rims' two each, an ellipsoid's two, the whole body's, the sides'.
        ids += int(b.probes.size() + 2 * b.rims.size()) + 3 + int(b.sides.size());
        auto keep = [&](const auto& r) {
            loaded_.push_back(
                {r.pos, r.rot, r.vel, r.spin, r.orient, b.pos, b.vel, b.spin, b.orient});
        };
        if (b.group >= 0) keep(scene.groups[size_t(b.group)]);
        else keep(scene.objects[size_t(b.object)]);
    }
}

//-----------------------------------------------------------------------------
// Contacts
//-----------------------------------------------------------------------------

ContactSide RigidBodies::sideOf(RigidBody& b, const dvec3& point, const dvec3& centre) {
    ContactSide s;
    s.rigid = &b;
    s.body = int(&b - bodies_.data());
    s.vel = &b.vel;
    s.spin = &b.spin;
    s.delta = &b.delta;
    s.orient = b.revolved ? &b.untwisted : &b.orient;
    s.supported = &b.supported;
    s.invMass = b.awake ? b.invMass : 0.0;
    s.anchor = point - b.pos;
    s.localAnchor = glm::conjugate(b.orient) * (centre - b.pos);
    s.offset = point - centre;
    return s;
}

void RigidBodies::collide(std::vector<PhysicsBody>& spheres, double gravity) {
    contacts_.clear();
    massRatio_ = 1.0;
    pairCache_.nextStep();
    if (bodies_.empty()) return;  // a scene of spheres alone: nothing here to do
    for (RigidBody& b : bodies_) {
        b.rowInertia = b.invInertia;  // as the contacts take it
        b.startPos = b.pos;
        b.startVel = b.vel;
        b.startSpin = b.spin;
        b.startOrient = b.untwisted = b.orient;
    }
    const int n = count(), m = int(spheres.size()) - 1;  // spheres end with the static body
    centres_.resize(size_t(n + m));
    extents_.resize(size_t(n + m));
    margins_.resize(size_t(n));
    // Placed when a pair first asks, into room that never moves while spans are held.
    boxesFirst_.assign(size_t(n), -1);
    boxes_.clear();
    size_t room = 0;
    for (const RigidBody& b : bodies_) room += 1 + b.parts.size();
    boxes_.reserve(room);
    touching_.assign(size_t(n), 0);
    for (int i = 0; i < n; ++i) {
        const RigidBody& b = bodies_[size_t(i)];
        margins_[size_t(i)] = 4.0 * settings_.linearSlop +
                              (glm::length(b.vel) + glm::length(b.spin) * b.bound) * dt_ +
                              gravity * dt_ * dt_;
        centres_[size_t(i)] = b.pos;
        extents_[size_t(i)] = b.bound + margins_[size_t(i)];
    }
    for (int s = 0; s < m; ++s) {
        const PhysicsBody& b = spheres[size_t(s)];
        centres_[size_t(n + s)] = b.pos;
        extents_[size_t(n + s)] =
            b.radius + 4.0 * settings_.linearSlop + glm::length(b.vel) * dt_ + gravity * dt_ * dt_;
    }
    for (int i = 0; i < n; ++i)
        if (bodies_[size_t(i)].awake) collideStatics(i);
    if (n + m > 1) broadphase_.findPairs(centres_, extents_, pairs_);
    else pairs_.clear();
    for (auto [i, j] : pairs_) {
        if (i >= n) continue;  // sphere pairs are the sphere solver's
        if (j < n) {
            if (bodies_[size_t(i)].awake || bodies_[size_t(j)].awake) collidePair(i, j);
        } else if (bodies_[size_t(i)].awake || spheres[size_t(j - n)].awake) {
            collideSphere(i, spheres[size_t(j - n)], j - n);
        }
    }
    wake(spheres);
    sortBottomUp();
    makeRows();
    for (size_t k = 0; k < manifolds_.size(); ++k) {
        if (k + kLookAhead < manifolds_.size())
            kept_.prefetch(contacts_[size_t(manifolds_[k + kLookAhead].begin)].key | 0xff);
        prepareFriction(manifolds_[k]);
    }
    measureStacks(int(spheres.size()));
    const int most = std::max(1, settings_.relaxSweeps);
    batches_.load(rows_, contacts_, manifolds_, count() + int(spheres.size()), most,
                  kImpactSweeps * most);
}

// Each body's depth is one more than that of the deepest body it rests on, found up the
// manifolds in their bottom-up order: a face that holds the body up (|n·y| ≥ 0.5) counts, one
// beside it does not. A static or sleeping body under it counts as the ground. A pile whose
// manifolds' heights do not follow its stacking may be undercounted by a body or two.
void RigidBodies::measureStacks(int spheres) {
    depths_.assign(size_t(count() + spheres), 0);
    stackDepth_ = 0;
    for (const RigidManifold& m : manifolds_) {
        const RigidContact& c = contacts_[size_t(m.begin)];
        if (std::abs(c.normal.y) < 0.5) continue;
        const auto [first, second] = pairOf(c.key);
        const int a = second < 0 ? -1 : first, b = second < 0 ? first : second;
        const bool aBelow = c.normal.y > 0.0;  // the normal points from a to b
        const int lower = aBelow ? a : b, upper = aBelow ? b : a;
        if (upper < 0) continue;  // a static surface over a body: it holds nothing up
        const ContactSide& under = aBelow ? c.a : c.b;
        const int below = lower < 0 || under.invMass == 0.0 ? 0 : depths_[size_t(lower)];
        int& depth = depths_[size_t(upper)];
        depth = std::max(depth, below + 1);
        stackDepth_ = std::max(stackDepth_, depth);
    }
}

// Manifolds bottom-up, each one's points together, in the order of their keys. Each manifold's
// points are found together, so the manifolds are sorted, about half as many as the points (a
// pile of 1000's sort of every point was 5 % of its step), and then each one's few points. The
// contacts are large: their order is sorted, then they move once.
void RigidBodies::sortBottomUp() {
    order_.clear();
    for (size_t begin = 0; begin < contacts_.size();) {
        const RigidContact& first = contacts_[begin];
        size_t end = begin + 1;  // so a NaN height, equal to none, is a run of its own
        while (end < contacts_.size() && contacts_[end].height == first.height &&
               contacts_[end].key >> 8 == first.key >> 8)
            ++end;
        order_.push_back({first.height, first.key >> 8, begin, end});
        begin = end;
    }
    std::sort(order_.begin(), order_.end(), [](const Place& x, const Place& y) {
        return x.height < y.height || (x.height == y.height && x.manifold < y.manifold);
    });
    // Each manifold is one run: two runs of one manifold would take their points in turn.
    assert(std::ranges::adjacent_find(order_, [](const Place& x, const Place& y) {
               return x.height == y.height && x.manifold == y.manifold;
           }) == order_.end());
    sorted_.clear();
    for (const Place& p : order_) {
        const auto from = sorted_.insert(sorted_.end(), contacts_.begin() + std::ptrdiff_t(p.begin),
                                         contacts_.begin() + std::ptrdiff_t(p.end));
        std::sort(from, sorted_.end(),
                  [](const RigidContact& x, const RigidContact& y) { return x.key < y.key; });
    }
    contacts_.swap(sorted_);
}

// A candidate's normal, separation and probe; `height` its manifold's, `pair` its pair's key.
RigidContact RigidBodies::contactFrom(const Candidate& c, double height, std::uint64_t pair) {
    RigidContact k;
    k.normal = c.normal;
    k.separation = c.separation;
    k.height = height;
    k.key = pair | std::uint64_t(c.probe);
    return k;
}

// One manifold per static surface the body's probes reach.
void RigidBodies::collideStatics(int i) {
    RigidBody& b = bodies_[size_t(i)];
    std::vector<std::vector<Candidate>>& byFeature = byFeature_;
    for (std::vector<Candidate>& feature : byFeature) feature.clear();
    probeStatics(i, byFeature);
    ContactSide fixed;
    for (size_t f = 0; f < byFeature.size(); ++f) {
        if (byFeature[f].empty()) continue;
        candidates_ = byFeature[f];
        keepNearest(candidates_, 4.0 * settings_.linearSlop, glm::length(b.spin) * b.bound, dt_);
        reduceManifold(candidates_, b.groupShape ? kGroupManifold : kMaxManifold);
        const double low = lowest(candidates_);
        for (const Candidate& c : candidates_) {
            RigidContact k = contactFrom(c, low, staticKey(i, int(f)));
            k.a = fixed;
            k.b = sideOf(b, c.point, c.centreB);
            setSurface(k, combine(b.surface, statics_.surface(int(f))));
            contacts_.push_back(k);
        }
    }
}

void RigidBodies::probeStatics(int i, std::vector<std::vector<Candidate>>& byFeature) {
    const RigidBody& b = bodies_[size_t(i)];
    const double reach = margins_[size_t(i)];
    const int rimIds = b.staticIds + int(b.probes.size()), lastId = rimIds + 2 * int(b.rims.size());
    // The sphere about the whole body first: inside a pile most bodies are nowhere near a wall.
    statics_.query(lastId + 2, b.pos, b.bound, reach, hits_, b.bound);
    if (hits_.empty()) return;
    faces_ = hits_;  // each surface near, as its normal faces the body's centre
    // A rim's support point turns about the rim's centre: that is its probe's centre.
    auto add = [&](const StaticHit& hit, const dvec3& at, double radius, int probe,
                   const dvec3& centre) {
        addStaticCandidate(b, hit, at, radius, probe, centre, byFeature);
    };
    for (size_t k = 0; k < b.probes.size(); ++k) {
        const Probe& p = b.probes[k];
        const dvec3 c = b.pos + b.orient * p.local;
        const int id = b.staticIds + int(k);
        statics_.query(id, c, p.radius, reach, hits_, b.bound);
        surfaces_ = hits_;  // lookInside writes hits_
        for (StaticHit hit : surfaces_) {
            if (p.partial && !onOwnSurface(b, c - p.radius * hit.normal)) continue;
            dvec3 at = c;
            const StaticHit* face = faceOf(hit.feature);
            if (p.radius == 0.0 && face) lookInside(b, id, reach, face->normal, b.pos, &hit, &at);
            add(hit, at, p.radius, int(k), at);
        }
    }
    for (size_t r = 0; r < b.rims.size(); ++r) {
        const Rim& rim = b.rims[r];
        const dvec3 c = b.pos + b.orient * rim.centre, axis = b.orient * rim.axis;
        const int id = rimIds + int(2 * r);
        statics_.query(id, c, 0.0, rim.radius + rim.tube + reach, hits_, b.bound);
        surfaces_ = hits_;  // the queries below write hits_
        for (const StaticHit& surface : surfaces_) {
            const std::array<dvec3, 4> support = rimSupport(c, axis, rim.radius, surface.normal);
            const bool flat = rimLiesFlat(axis, surface.normal);
            for (size_t k = 0; k < support.size(); ++k) {
                dvec3 at = support[k];
                const StaticHit* found =
                    hitOn(surface.feature, id + 1, at, rim.tube, reach, b.bound);
                if (!found) continue;
                StaticHit hit = *found;
                if (rim.tube == 0.0) lookInside(b, id + 1, reach, surface.normal, c, &hit, &at);
                add(hit, at, rim.tube, rimKey(b, int(r)) + int(k), k == 0 && !flat ? c : at);
            }
            if (rim.core && statics_.isGroupSurface(surface.feature))
                probeStaticRing(b, int(r), surface.feature, id + 1, reach, byFeature);
        }
    }
    for (size_t k = 0; k < b.sides.size(); ++k) probeStaticSide(b, int(k), reach, byFeature);
    probeStaticProbes(b, reach, byFeature);
    if (!b.ellipsoid) return;
    // An ellipsoid touches each surface at its support point along that surface's normal: the
    // normal seen from its centre first, then the one seen from that point (a curved surface's).
    const dvec3 semi(b.shape.size);
    const int key = supportKey(b);
    statics_.query(lastId, b.pos, 0.0, std::max({semi.x, semi.y, semi.z}) + reach, hits_, b.bound);
    surfaces_ = hits_;
    for (const StaticHit& surface : surfaces_) {
        dvec3 normal = surface.normal;
        for (int pass = 0; pass < 2; ++pass) {
            const dvec3 at =
                b.pos + b.orient * ellipsoidSupport(semi, glm::conjugate(b.orient) * -normal);
            statics_.query(lastId + 1, at, 0.0, reach, hits_, b.bound);
            const auto hit = std::find_if(hits_.begin(), hits_.end(), [&](const StaticHit& h) {
                return h.feature == surface.feature;
            });
            if (hit == hits_.end()) break;
            if (pass == 1 || glm::dot(hit->normal, normal) > 1.0 - 1e-12) {
                add(*hit, at, 0.0, key, at);
                break;
            }
            normal = hit->normal;
        }
    }
}

// The sphere of the body's probe `probe` (centre `centre`) at `at` meeting a static surface.
void RigidBodies::addStaticCandidate(const RigidBody& b, const StaticHit& hit, const dvec3& at,
                                     double radius, int probe, const dvec3& centre,
                                     std::vector<std::vector<Candidate>>& byFeature) {
    if (size_t(hit.feature) >= byFeature.size()) byFeature.resize(size_t(hit.feature) + 1);
    const dvec3 normal = hit.creased ? staticNormalBesideCrease(b, hit, at, radius) : hit.normal;
    const dvec3 point = at - (radius + 0.5 * hit.separation) * normal;
    byFeature[size_t(hit.feature)].push_back({point, normal, hit.separation, probe, point, centre});
}

// A torus's core r against a static group, where the group comes nearest along it, as probeRim
// does against a body: a ring lying flat on two static bars, which cross its tube away from its
// four support points, sank 1.7 cm into them and tilted 9.6°.
void RigidBodies::probeStaticRing(const RigidBody& b, int r, int feature, int id, double reach,
                                  std::vector<std::vector<Candidate>>& byFeature) {
    const Rim& rim = b.rims[size_t(r)];
    const int fixed = rimPointKey(b, r);
    auto distance = [&](const dvec3& p) { return statics_.surfaceDistance(feature, p); };
    leastAlongRim(rim, b.pos, b.orient, distance, reach, [&](const dvec3& at, int k) {
        if (const StaticHit* hit = hitOn(feature, id, at, rim.tube, reach, b.bound))
            addStaticCandidate(b, *hit, at, rim.tube, fixed + k, at, byFeature);
    });
}

// The body's side k against each static group near it, as probeSide (the ground, a plane, never
// comes nearest between the rims). Each group is searched as a convex shape: a second least along
// the side, where two of its objects meet, is left to the rims and the static probes (a scan
// found one under a spinning rod and changed its flight in the thin bodies' bin 29 into one
// that gained 7 % energy, as a rim-only one gained 12 %).
void RigidBodies::probeStaticSide(const RigidBody& b, int k, double reach,
                                  std::vector<std::vector<Candidate>>& byFeature) {
    const Side side = worldSide(b, k);
    const int id = b.staticIds + int(b.probes.size() + 2 * b.rims.size()) + 3 + k;
    statics_.query(id, 0.5 * (side.from + side.to), 0.0, sideBound(side) + reach, hits_, b.bound);
    surfaces_ = hits_;  // hitOn writes hits_
    for (const StaticHit& surface : surfaces_) {
        if (!statics_.isGroupSurface(surface.feature)) continue;
        auto distance = [&](const dvec3& p) {
            return statics_.surfaceDistance(surface.feature, p);
        };
        const SideTouch touch =
            nearestOnSide(distance, side, reach, 1e-6 * (glm::length(side.from) + b.bound),
                          kSideLevel * settings_.linearSlop, 0);
        for (int e = 0; e < touch.count; ++e) {
            const dvec3 at = glm::mix(side.from, side.to, touch.t[e]);
            const double radius = sideRadius(side, touch.t[e]);
            const StaticHit* hit = hitOn(surface.feature, id, at, radius, reach, b.bound);
            if (!hit || (side.partial && !onOwnSurface(b, at - radius * hit->normal))) continue;
            addStaticCandidate(b, *hit, at, radius, sideKey(b) + kSideIds * k + e, at, byFeature);
        }
    }
}

// The static surface `feature` as the body's centre sees it (probeStatics' faces_).
const StaticHit* RigidBodies::faceOf(int feature) const {
    const auto face = std::find_if(faces_.begin(), faces_.end(),
                                   [feature](const StaticHit& f) { return f.feature == feature; });
    return face == faces_.end() ? nullptr : &*face;
}

// The static surface `feature` as a sphere at `at` meets it within reach, in hits_; null where
// it does not. `id` names the sphere for the query.
const StaticHit* RigidBodies::hitOn(int feature, int id, const dvec3& at, double radius,
                                    double reach, double size) {
    statics_.query(id, at, radius, reach, hits_, size);
    const auto hit = std::find_if(hits_.begin(), hits_.end(),
                                  [feature](const StaticHit& h) { return h.feature == feature; });
    return hit == hits_.end() ? nullptr : &*hit;
}

// A sharp point of the body (a corner, a sharp rim's) that meets a wall across the face it lies
// on (`face`, the surface's normal seen from `centre`, more than 60° away) lies on the surface's
// edge, pressed in: a box on a static box of its own footprint has each corner on the other's
// side wall, where the distance inside is 0 (the wall's), not the depth below the face; so has a
// cylinder on a static one of its radius. Every such point met a wall, none held the weight,
// and the body sank through. Looked at again a tenth of the way towards `centre` along the face,
// the point meets the face: where that is deeper, it is the contact. `at` and `hit` move there.
void RigidBodies::lookInside(const RigidBody& b, int id, double reach, const dvec3& face,
                             const dvec3& centre, StaticHit* hit, dvec3* at) {
    if (glm::dot(hit->normal, face) >= 0.5) return;
    const dvec3 towards = centre - *at;
    const dvec3 inside = *at + 0.1 * (towards - glm::dot(towards, face) * face);
    const StaticHit* there = hitOn(hit->feature, id, inside, 0.0, reach, b.bound);
    if (!there || there->separation >= hit->separation) return;
    *hit = *there;
    *at = inside;
}

// As normalBesideCrease, for a sharp probe of the body on an edge of a static surface. The
// surface is sampled as the query sampled it, at the body's size. A probe too thick to sample
// beside the crease (its centre inside the surface, near an edge) takes the surface's normal
// as the body's centre sees it: the creased samples sum to a normal with a part along the edge,
// which slid a thin cone along a wall's end 0.32 m into the wall.
dvec3 RigidBodies::staticNormalBesideCrease(const RigidBody& b, const StaticHit& hit,
                                            const dvec3& at, double radius) {
    const double inside = kBesideCrease * b.bound - radius;
    if (inside > 0.0)
        return statics_.hit(hit.feature, at - inside * normalAt(b, at), b.bound).normal;
    const StaticHit* face = faceOf(hit.feature);
    return face ? face->normal : hit.normal;
}

// As normalBesideCrease, for a static object's sharp probe on an edge of the body: the body's
// normal a little way into the static object, along the object's own inward normal.
dvec3 RigidBodies::normalBesideStaticProbe(const RigidBody& b, const StaticProbe& p,
                                           const dvec3& normal) {
    const double inside = kBesideCrease * b.bound - p.radius;
    if (inside <= 0.0) return normal;
    return normalAt(b, p.centre - inside * statics_.hit(p.feature, p.centre, b.bound).normal);
}

// The static objects' own probes (StaticProbe) against the body's shape, keyed above the body's
// own probes: a box lands flat on a post's top, which no corner or edge of its own meets. Then
// their sides, as a body's (probeSide), and their tori's cores, as a body's (probeRim), keyed
// after the probes.
void RigidBodies::probeStaticProbes(const RigidBody& b, double reach,
                                    std::vector<std::vector<Candidate>>& byFeature) {
    for (const StaticProbe& p : statics_.near(b.pos, b.bound, reach))
        meetStaticProbe(b, p, p.key, reach, byFeature);
    auto distance = [&](const dvec3& p) { return distanceTo(b, p); };
    const std::vector<StaticSide>& sides = statics_.sides();
    for (size_t k = 0; k < sides.size(); ++k) {
        const Side& side = sides[k].side;
        if (glm::length(b.pos - 0.5 * (side.from + side.to)) >= sideBound(side) + b.bound + reach)
            continue;
        const SideTouch touch =
            nearestOnSide(distance, side, reach, 1e-6 * (glm::length(b.pos) + b.bound),
                          kSideLevel * settings_.linearSlop, b.groupShape ? kSideScan : 0);
        for (int e = 0; e < touch.count; ++e) {
            const StaticProbe sphere{glm::mix(side.from, side.to, touch.t[e]),
                                     sideRadius(side, touch.t[e]), sides[k].feature};
            meetStaticProbe(b, sphere, sides[k].key + e, reach, byFeature);
        }
    }
    const std::vector<StaticRing>& rings = statics_.rings();
    for (size_t k = 0; k < rings.size(); ++k) {
        const Rim& core = rings[k].core;
        if (glm::length(b.pos - core.centre) >= core.radius + core.tube + b.bound + reach) continue;
        leastAlongRim(core, dvec3(0.0), dquat(1.0, 0.0, 0.0, 0.0), distance, reach,
                      [&](const dvec3& at, int e) {
                          const StaticProbe sphere{at, core.tube, rings[k].feature};
                          meetStaticProbe(b, sphere, rings[k].key + e, reach, byFeature);
                      });
    }
}

// A static object's sphere (a probe's, its side's or its core's), its feature's `index`th
// (StaticProbe::key), against the body's shape.
void RigidBodies::meetStaticProbe(const RigidBody& b, const StaticProbe& p, int index, double reach,
                                  std::vector<std::vector<Candidate>>& byFeature) {
    const std::optional<ShapeSample> near = sampleNear(b, p.centre, p.radius, reach);
    if (!near || near->distance - p.radius >= reach) return;
    ShapeSample sample = *near;
    if (sample.creased) sample.normal = normalBesideStaticProbe(b, p, sample.normal);
    const int key = kStaticKeyBase + index % kStaticKeys;
    // The normal from the static side to the body, against the body's own; the point midway
    // between the probe's sphere and the body's surface, on the body's face.
    const double separation = sample.distance - p.radius;
    const dvec3 point = p.centre - (p.radius + 0.5 * separation) * sample.normal;
    if (size_t(p.feature) >= byFeature.size()) byFeature.resize(size_t(p.feature) + 1);
    byFeature[size_t(p.feature)].push_back({point, -sample.normal, separation, key, point, point});
}

// How far apart two bodies' points may be and still meet within the step: the slop's margin
// and how far their relative motion and turning carry them. The same either way round.
double RigidBodies::reachOf(const RigidBody& a, const RigidBody& b) const {
    return 4.0 * settings_.linearSlop +
           (glm::length(a.vel - b.vel) + glm::length(a.spin) * a.bound +
            glm::length(b.spin) * b.bound) *
               dt_;
}

std::span<const OrientedBox> RigidBodies::boxesOf(int i) {
    const RigidBody& b = bodies_[size_t(i)];
    int& first = boxesFirst_[size_t(i)];
    if (first < 0) {
        first = int(boxes_.size());
        appendPlacedBoxes(b, boxes_);
    }
    return {boxes_.data() + first, 1 + b.parts.size()};
}

// Whether two bodies lie so far apart by their hulls, which hold their probes, that no probe of
// either comes within the pair's reach of the other's parts: probing would find nothing. Checked
// before the probes, most of which it spares: first each hull against the sphere about the other
// body, then the hulls' separating axes. The broad phase's spheres overlap far more often than
// the hulls do: of the mixed pile of 1000's pairs that are probed, 47 % find no point, and this
// sees 81 % of those (a cylinder's hull is its own box; a bound's shape has none). `pairReach`:
// reachOf(a, b), which the caller has.
bool RigidBodies::boxesApart(int i, int j, double pairReach) {
    const RigidBody &a = bodies_[size_t(i)], &b = bodies_[size_t(j)];
    if (a.parts.empty() || b.parts.empty()) return false;
    const double reach = boxReach(a, b, pairReach);
    const OrientedBox &hullA = boxesOf(i)[0], &hullB = boxesOf(j)[0];
    if (distanceToBox(hullA, b.pos) >= b.bound + reach ||
        distanceToBox(hullB, a.pos) >= a.bound + reach)
        return true;
    return !boxesOverlap(hullA, hullB, -reach);
}

// The prober's probes against the shape's SDF; `flip` where the prober is the pair's a, so
// every normal points from a to b. Keys: offset + probe. Where a group meets a body and both
// have parts, each of the prober's parts is probed against the shape's parts near it alone
// (near_parts.h); every other pair against the whole shape.
void RigidBodies::probeShape(int proberIndex, int shapeIndex, bool flip, int offset) {
    const RigidBody &prober = bodies_[size_t(proberIndex)], &shape = bodies_[size_t(shapeIndex)];
    const Probing q{prober, shape, flip, offset, reachOf(prober, shape), partwise(prober, shape)};
    if (q.partwise) nearParts_.find(flip, shape);
    auto nearOf = [&](int part) {
        return q.partwise ? nearParts_.of(part) : std::span<const int>();
    };
    for (size_t k = 0; k < prober.probes.size(); ++k) {
        const Probe& p = prober.probes[k];
        if (q.partwise && nearOf(p.part).empty()) continue;
        const dvec3 c = prober.pos + prober.orient * p.local;
        probePoint(q, c, p.radius, int(k), c, nearOf(p.part), p.partial);
    }
    for (size_t r = 0; r < prober.rims.size(); ++r)
        if (!q.partwise || !nearOf(prober.rims[r].part).empty())
            probeRim(q, int(r), nearOf(prober.rims[r].part));
    for (size_t k = 0; k < prober.sides.size(); ++k)
        if (!q.partwise || !nearOf(prober.sides[k].part).empty())
            probeSide(q, int(k), nearOf(prober.sides[k].part));
    if (!prober.ellipsoid) return;
    // The ellipsoid's point furthest into the shape: its support point along the shape's normal.
    const dvec3 semi(prober.shape.size);
    const double longest = std::max({semi.x, semi.y, semi.z});
    if (glm::length(prober.pos - shape.pos) >= shape.bound + longest + q.reach) return;
    if (beyondParts(shape, prober.pos, longest + q.reach)) return;
    if (distanceTo(shape, prober.pos) >= longest + q.reach) return;
    const dvec3 down = glm::conjugate(prober.orient) * -normalAt(shape, prober.pos);
    const dvec3 at = prober.pos + prober.orient * ellipsoidSupport(semi, down);
    probePoint(q, at, 0.0, supportKey(prober), at, {});
}

// A sphere of the prober at `at` against the shape: by its `near` parts where probing part by
// part, else its bounding sphere, its parts' boxes, its distance, and only then the four more
// samples of its normal (or, on a bound, the projection onto its surface).
void RigidBodies::probePoint(const Probing& q, const dvec3& at, double radius, int key,
                             const dvec3& centre, std::span<const int> near, bool partial,
                             const WallRetry* retry) {
    const RigidBody& shape = q.shape;
    ShapeSample sample;
    int part = -1;
    if (q.partwise) {
        const NearParts::Sample nearest = nearParts_.nearest(near, at, radius + q.reach);
        if (nearest.part < 0) return;
        part = nearest.part;
        bool creased;
        sample = {nearest.distance, nearParts_.normal(part, at, &creased), creased};
    } else if (const std::optional<ShapeSample> whole = sampleNear(shape, at, radius, q.reach)) {
        sample = *whole;
    } else {
        return;
    }
    const double separation = sample.distance - radius;
    if (separation >= q.reach) return;
    if (partial && !onOwnSurface(q.prober, at - radius * sample.normal)) return;
    if (retry && glm::dot(sample.normal, retry->face) < 0.5)
        return probePoint(q, at + retry->move, radius, key, centre + retry->move, near, partial);
    if (sample.creased) sample.normal = normalBesideCrease(q, at, radius, part, sample.normal);
    const dvec3 point = at - (radius + 0.5 * separation) * sample.normal;
    candidates_.push_back({point, q.flip ? -sample.normal : sample.normal, separation,
                           q.offset + key, q.flip ? centre : point, q.flip ? point : centre});
}

// A sharp probe on an edge of the shape (two cylinders standing side by side on one floor: each
// rim lies on the other's edge) may take any normal between the edge's faces, and the samples
// straddling the edge give a slanted one: (0.64, 0.64, -0.42) at a right-angled edge, which
// turned their bounce at restitution 1 into spin and lost half its energy. The contact's normal
// is the shape's a little way into the prober, along the prober's own inward normal, where the
// samples clear the edge: there the shape's nearest face is the one the prober lies against.
dvec3 RigidBodies::normalBesideCrease(const Probing& q, const dvec3& at, double radius, int part,
                                      const dvec3& normal) {
    const double inside = kBesideCrease * q.shape.bound - radius;
    if (inside <= 0.0) return normal;  // the probe's sphere holds the samples clear already
    const dvec3 beside = at - inside * normalAt(q.prober, at);
    return part >= 0 ? nearParts_.normal(part, beside) : normalAt(q.shape, beside);
}

// Rim r of the prober against the shape, or its `near` parts where probing part by part: its
// support points along the shape's normal at its centre, and against a group's shape, or for a
// torus's core, the points along it where the shape comes nearest.
void RigidBodies::probeRim(const Probing& q, int r, std::span<const int> near) {
    const RigidBody &prober = q.prober, &shape = q.shape;
    const Rim& rim = prober.rims[size_t(r)];
    const dvec3 c = prober.pos + prober.orient * rim.centre, axis = prober.orient * rim.axis;
    auto distance = [&](const dvec3& p) {
        return q.partwise ? nearParts_.nearest(near, p).distance : distanceTo(shape, p);
    };
    // Every point of the rim lies within its radius of c, and the SDF changes no faster
    // than the distance: a rim whose centre is that far out of reach has nothing to find.
    const double rimReach = rim.radius + rim.tube + q.reach;
    if (!q.partwise &&
        (glm::length(c - shape.pos) >= shape.bound + rimReach || beyondParts(shape, c, rimReach)))
        return;
    const NearParts::Sample centre =
        q.partwise ? nearParts_.nearest(near, c) : NearParts::Sample{distanceTo(shape, c), -1};
    if (centre.distance >= rimReach) return;
    const dvec3 normal = q.partwise ? nearParts_.normal(centre.part, c) : normalAt(shape, c);
    const std::array<dvec3, 4> support = rimSupport(c, axis, rim.radius, normal);
    const double inset = rimInset(rim, axis, normal);
    for (size_t k = 0; k < support.size(); ++k) {
        WallRetry retry{normal, dvec3(0.0)};
        if (inset > 0.0) retry.move = inset * glm::normalize(c - support[k]);
        probePoint(q, support[k], rim.tube, rimKey(prober, r) + int(k), support[k], near, false,
                   inset > 0.0 ? &retry : nullptr);
    }
    if (!shape.groupShape && !rim.core) return;
    // A group's shape can meet the rim in several places, each where the distance along the
    // rim is least (a rim across another cup's rim touches it where the two edges cross):
    // sixteen points of the rim, and a parabola through each least one and its neighbours.
    // So can any shape a torus's core: a bar laid across a ring crosses its tube twice, and
    // met none of the four support points of a core lying flat under it, and fell through.
    const int fixed = rimPointKey(prober, r);
    leastAlongRim(rim, prober.pos, prober.orient, distance, rimReach, [&](const dvec3& at, int k) {
        probePoint(q, at, rim.tube, fixed + k, at, near);
    });
}

// The prober's side k against the shape, by the sphere where its axis comes nearest the shape
// between the rims (nearestOnSide), keyed after the rims.
void RigidBodies::probeSide(const Probing& q, int k, std::span<const int> near) {
    const RigidBody &prober = q.prober, &shape = q.shape;
    const Side side = worldSide(prober, k);
    const dvec3 middle = 0.5 * (side.from + side.to);
    const double most = sideBound(side) + q.reach;
    if (!q.partwise &&
        (glm::length(middle - shape.pos) >= shape.bound + most || beyondParts(shape, middle, most)))
        return;
    const double noise = 1e-6 * (prober.bound + shape.bound);
    const double level = kSideLevel * settings_.linearSlop;
    SideTouch touch;
    if (q.partwise) {
        // A union's near parts are each an exact shape, searched as a convex one (a scan of the
        // whole union along each of 400 tables' legs cost a quarter of their step); the side
        // probes where the nearest of them comes nearest.
        for (size_t p = 0; p < near.size(); ++p) {
            auto distance = [&](const dvec3& x) {
                return nearParts_.nearest(near.subspan(p, 1), x).distance;
            };
            const SideTouch found = nearestOnSide(distance, side, q.reach, noise, level, 0);
            if (found.count > 0 && (touch.count == 0 || found.least < touch.least)) touch = found;
        }
    } else {
        auto distance = [&](const dvec3& x) { return distanceTo(shape, x); };
        touch =
            nearestOnSide(distance, side, q.reach, noise, level, shape.groupShape ? kSideScan : 0);
    }
    for (int e = 0; e < touch.count; ++e) {
        const dvec3 at = glm::mix(side.from, side.to, touch.t[e]);
        probePoint(q, at, sideRadius(side, touch.t[e]), sideKey(prober) + kSideIds * k + e, at,
                   near, side.partial);
    }
}

// The pair's contacts in closed form, by the pair table's routine for its two types (pair_table.h),
// normals from a to b; false where it has none, and for groups and rounded shapes.
bool RigidBodies::collideAnalytic(const RigidBody& a, const RigidBody& b) {
    if (a.groupShape || b.groupShape || a.shape.round > 0.0f || b.shape.round > 0.0f) return false;
    const PairRoutine routine = pairRoutine(a.shape.type, b.shape.type);
    if (!routine) return false;
    for (const PairContact& c : routine(a, b, reachOf(a, b)))
        candidates_.push_back(
            {c.point, c.normal, c.separation, c.feature, coreOf(a, c, -1.0), coreOf(b, c, 1.0)});
    return true;
}

// The reach finds a pair's points by the bodies' whole relative motion, the worst case for any
// point. Of a group's points, most are speculative, and many lie beyond the speculative distance
// (four slops, Box2D's) by more than they approach in the step at their own speed: unless the
// step changes the speed at such a point by over 2.4 m/s, it stays apart, and its row would only
// be swept. Dropped, they are found again the step they come within reach.
void RigidBodies::dropUnreachable(const RigidBody& a, const RigidBody& b) {
    const double speculative = 4.0 * settings_.linearSlop;
    std::erase_if(candidates_, [&](const Candidate& c) {
        const dvec3 va = a.vel + glm::cross(a.spin, c.point - a.pos);
        const dvec3 vb = b.vel + glm::cross(b.spin, c.point - b.pos);
        const double approach = std::max(0.0, -glm::dot(vb - va, c.normal));
        return c.separation >= speculative + approach * dt_;
    });
}

// The pair table's closed forms (collideAnalytic); every other pair by probing both ways.
void RigidBodies::collidePair(int i, int j) {
    candidates_.clear();
    const RigidBody &bi = bodies_[size_t(i)], &bj = bodies_[size_t(j)];
    const double reach = reachOf(bi, bj);
    const bool cached = bi.groupShape || bj.groupShape;
    if (cached && boxesApart(i, j, reach)) return;  // cheaper than the cache's lookup, and sure
    if (!cached || !pairCache_.reuse(pairKey(i, j), bi, bj, reach, &candidates_)) {
        if (!collideAnalytic(bi, bj) && (cached || !boxesApart(i, j, reach))) {
            if (partwise(bi, bj)) nearParts_.meet(boxesOf(i), boxesOf(j), boxReach(bi, bj, reach));
            probeShape(j, i, false, 0);
            probeShape(i, j, true, 128);
        }
        if (cached) pairCache_.keep(pairKey(i, j), bi, bj, reach, candidates_);
    }
    if (cached) dropUnreachable(bi, bj);
    RigidBody &a = bodies_[size_t(i)], &b = bodies_[size_t(j)];
    auto add = [&](std::uint64_t manifold) {
        keepNearest(candidates_, 4.0 * settings_.linearSlop,
                    glm::length(a.spin) * a.bound + glm::length(b.spin) * b.bound, dt_);
        reduceManifold(candidates_, a.groupShape || b.groupShape ? kGroupManifold : kMaxManifold);
        const double low = lowest(candidates_);
        for (const Candidate& c : candidates_) {
            RigidContact k = contactFrom(c, low, pairKey(i, j) | manifold << 8);
            k.a = sideOf(a, c.point, c.centreA);
            k.b = sideOf(b, c.point, c.centreB);
            setSurface(k, combine(a.surface, b.surface));
            contacts_.push_back(k);
            touching_[size_t(i)] |= b.awake && glm::length(b.vel) > settings_.sleepSpeed;
            touching_[size_t(j)] |= a.awake && glm::length(a.vel) > settings_.sleepSpeed;
        }
    };
    if (!a.groupShape && !b.groupShape) return add(0);
    // A group may touch another body in several places that face different ways (a cup's rim
    // in another's mouth, against its wall on both sides): one manifold of four points cannot
    // hold them, and which four it kept would change from step to step. A manifold for each
    // way the normals face, in a's frame: the nearest of a cube's 26 face, edge and corner
    // directions, which stays the same from step to step while the contact does.
    static const std::array<dvec3, 27> kWays = [] {
        std::array<dvec3, 27> ways;
        for (int k = 0; k < 27; ++k) {
            const dvec3 d(k % 3 - 1, k / 3 % 3 - 1, k / 9 - 1);
            ways[size_t(k)] = k == 13 ? d : d / glm::length(d);
        }
        return ways;
    }();
    std::vector<Candidate>& all = binned_;
    all.swap(candidates_);
    std::vector<int>& bins = bins_;
    bins.resize(all.size());
    for (size_t c = 0; c < all.size(); ++c) {
        const dvec3 n = glm::conjugate(a.orient) * all[c].normal;
        double best = -2.0;
        for (int k = 0; k < 27; ++k) {
            const double along = glm::dot(n, kWays[size_t(k)]);
            if (k != 13 && along > best) best = along, bins[c] = k;
        }
    }
    for (int bin = 0; bin < 27; ++bin) {
        candidates_.clear();
        for (size_t c = 0; c < all.size(); ++c)
            if (bins[c] == bin) candidates_.push_back(all[c]);
        if (!candidates_.empty()) add(std::uint64_t(bin));
    }
}

// The sphere's centre against the body's SDF: one exact contact, as a sphere meets any SDF.
// The body's own probes against the sphere are left out: the sphere's distance is exact.
void RigidBodies::collideSphere(int i, PhysicsBody& sphere, int sphereIndex) {
    RigidBody& b = bodies_[size_t(i)];
    const double reach = 4.0 * settings_.linearSlop + glm::length(sphere.vel - b.vel) * dt_ +
                         glm::length(b.spin) * b.bound * dt_;
    ShapeSample s = surfaceNear(b, sphere.pos, sphere.radius + reach);
    const double separation = s.distance - sphere.radius;
    if (separation >= reach) return;
    if (b.exact) s.normal = normalAt(b, sphere.pos);
    const dvec3 point = sphere.pos - (sphere.radius + 0.5 * separation) * s.normal;
    RigidContact k;
    k.a = sideOf(b, point, point);
    k.b.body = count() + sphereIndex;
    k.b.vel = &sphere.vel;
    k.b.spin = &sphere.spin;
    k.b.delta = &sphere.delta;
    k.b.supported = &sphere.supported;
    k.b.invMass = sphere.awake ? sphere.invMass : 0.0;
    k.b.sphereInverseInertia = sphere.invInertia;
    k.b.anchor = point - sphere.pos;
    k.normal = s.normal;
    k.separation = separation;
    k.height = point.y;
    k.key = pairKey(i, count() + sphereIndex);
    setSurface(k, combine(b.surface, {sphere.friction, sphere.restitution}));
    contacts_.push_back(k);
    if (!sphere.awake && b.awake && glm::length(b.vel) > settings_.sleepSpeed)
        touching_[size_t(i)] |= 2;
    if (sphere.awake && glm::length(sphere.vel) > settings_.sleepSpeed) touching_[size_t(i)] |= 1;
}

// A sleeping body that a moving one touches wakes: a rigid body at once (its rows were made
// with it fixed, so they are made again next step), a sphere with its island. A rigid body
// wakes the sleeping ones within reach of it, and they theirs, as an island wakes: a row of
// sleeping boxes hit at one end would otherwise hold the first against the next, still fixed,
// and stop what hit it dead. Sleeping pairs make no contacts, so reach is the broad phase's.
void RigidBodies::wake(std::vector<PhysicsBody>& spheres) {
    std::vector<int> islands;
    for (const RigidContact& c : contacts_) {
        const auto [first, second] = pairOf(c.key);
        if (second < count()) continue;
        PhysicsBody& sphere = spheres[size_t(second - count())];
        if (!sphere.awake && (touching_[size_t(first)] & 2)) islands.push_back(sphere.island);
    }
    wakeIslands(spheres, islands);
    std::vector<int> woken;
    for (size_t i = 0; i < bodies_.size(); ++i)
        if (!bodies_[i].awake && (touching_[i] & 1)) woken.push_back(int(i));
    if (woken.empty()) return;
    std::vector<std::vector<int>> near(bodies_.size());
    for (auto [i, j] : pairs_)
        if (j < count() && !(bodies_[size_t(i)].awake && bodies_[size_t(j)].awake))
            near[size_t(i)].push_back(j), near[size_t(j)].push_back(i);
    for (size_t k = 0; k < woken.size(); ++k) {  // woken grows as the island is found
        RigidBody& b = bodies_[size_t(woken[k])];
        b.awake = true;
        b.sleepTime = 0.0;
        for (int other : near[size_t(woken[k])])
            if (!bodies_[size_t(other)].awake && !(touching_[size_t(other)] & 1)) {
                touching_[size_t(other)] |= 1;  // queued once
                woken.push_back(other);
            }
    }
}

// Each point's row, from last step's push, and its approach speed; and the manifolds, each
// pair's points that face one way, in their bottom-up order. A point's friction is its
// manifold's (prepareFriction).
void RigidBodies::makeRows() {
    manifolds_.clear();
    rows_.clear();
    for (size_t i = 0; i < contacts_.size(); ++i) {
        if (i + kLookAhead < contacts_.size()) kept_.prefetch(contacts_[i + kLookAhead].key);
        RigidContact& c = contacts_[i];
        if (const WarmImpulses* warm = kept_.find(c.key)) c.normalImpulse = warm->normal;
        const NormalRow& r = rows_.emplace_back(rowOf(c));
        c.relativeVelocity = normalVelocity(c, r);
        if (r.invMassA > 0.0 && r.invMassB > 0.0)  // a static or sleeping side is not pressed in
            massRatio_ = std::max({massRatio_, r.invMassA / r.invMassB, r.invMassB / r.invMassA});
        if (i == 0 || (c.key ^ contacts_[i - 1].key) >> 8 != 0)
            manifolds_.push_back({.begin = int(i), .rows = {}});
        manifolds_.back().end = int(i) + 1;
        manifolds_.back().impact |= c.relativeVelocity < -kImpactSpeed;
    }
}

// The manifold's friction contact: its nearest point's, moved to the points' centre; and its
// rows. A fast-turning body keeps speculative points on a static box's other faces in the
// manifold: a spinning rod's far rim on a wall's end face came first, the friction's tangents
// took its normal, and along one of them the friction row pushed against the point on the
// wall's face (+30 % energy in one step).
void RigidBodies::prepareFriction(RigidManifold& m) {
    int nearest = m.begin;
    for (int i = m.begin + 1; i < m.end; ++i)
        if (contacts_[size_t(i)].separation < contacts_[size_t(nearest)].separation) nearest = i;
    RigidContact f = contacts_[size_t(nearest)];
    f.key |= 0xff;
    m.key = f.key;
    m.movesA = f.a.invMass > 0.0 ? f.a.body : -1;
    m.movesB = f.b.invMass > 0.0 ? f.b.body : -1;
    const int count = m.end - m.begin;
    dvec3 a(0.0), b(0.0);
    for (int i = m.begin; i < m.end; ++i) {
        a += contacts_[size_t(i)].a.anchor;
        b += contacts_[size_t(i)].b.anchor;
    }
    f.a.anchor = a / double(count);
    f.b.anchor = b / double(count);
    FrictionRows& r = m.rows;
    tangentsOf(f.normal, r.tangent);
    static_cast<RowBodies&>(r) = bodiesOf(f);
    r.normal = f.normal;
    r.friction = f.friction;
    r.twistArm = 0.0;
    for (int i = m.begin; i < m.end; ++i)
        r.twistArm += glm::length(contacts_[size_t(i)].b.anchor - f.b.anchor) / count;
    const WarmImpulses* warm = kept_.find(f.key);
    r.twistImpulse = warm ? warm->twist : 0.0;
    m.sweeps = warm ? warm->sweeps : 1;
    // The rolling radius: the centre's height over the contact plane. The distance to the
    // manifold's centre overstates it wherever that centre lies off to the side along the roll's
    // axis (a lying capsule's four points of five: it slowed 1.2 % fast).
    r.rollLimit = rolling_ * std::abs(glm::dot(f.b.anchor, f.normal));
    // A ball spun on the spot on a body: its one point has no spread for the twist's friction,
    // and it kept its spin for ever where on the ground it stops. Rolling resistance holds it,
    // as the spheres' own contacts hold a spin about the normal: a lever of rolling·ρ/μ. Only a
    // sphere's: a thin body's twist, made with its inverse inertia of the step's start, gave a
    // bin of thin fast bodies 16 % more energy with it.
    const int bodies = this->count();  // spheres come after them
    if ((f.a.body >= bodies || f.b.body >= bodies) && r.friction > 0.0)
        r.twistArm = std::max(r.twistArm, r.rollLimit / r.friction);
    for (int k = 0; k < 2; ++k) {
        r.tangentImpulse[k] = warm ? warm->tangent[k] : 0.0;
        r.armA[k] = glm::cross(f.a.anchor, r.tangent[k]);
        r.armB[k] = glm::cross(f.b.anchor, r.tangent[k]);
        r.rollImpulse[k] = warm ? warm->roll[k] : 0.0;
    }
    setTurns(r, inverseInertiaOf(f.a), inverseInertiaOf(f.b));
}

//-----------------------------------------------------------------------------
// Rows
//-----------------------------------------------------------------------------

void RigidBodies::warmStart() { batches_.warmStart(settings_.twoLanes); }

// The relax pass sweeps a manifold's rows until no row changes its speed by kSweepTolerance,
// at most settings.relaxSweeps times: the points of a face share one body, and one sweep in a fixed
// order leaves the first point pushing hardest, which turns a box dropped flat. Each sweep brings
// the velocities closer to the one answer that stops every point alike (the impulses may differ;
// the motion they give does not). Sixteen sweeps every time cost two thirds of the step in a
// pile of 1000 bodies; resting manifolds, warm-started, converge in one or two. The solve pass
// sweeps once: its soft rows are made for one sweep, and more would soften them again each time.
// An impact's manifold is swept in both passes until it settles, up to kImpactSweeps times the
// relax pass's most: a box landing flat at 20 m/s was stopped by its first corner alone, turned,
// and the ground's friction sent it 2 cm aside (39 cm at 60 m/s).
void RigidBodies::solve(const Softness& soft, double h, bool useBias) {
    ManifoldPass pass;
    pass.h = h;
    pass.biasRate = soft.biasRate;
    pass.massScale = soft.massScale;
    pass.impulseScale = soft.impulseScale;
    pass.maxPushSpeed = settings_.maxPushSpeed;
    pass.slop = 0.1 * settings_.linearSlop;
    pass.sweepTolerance = kSweepTolerance;
    pass.rolling = rolling_ > 0.0;
    batches_.solve(pass, useBias, settings_.twoLanes);
}

// After the substeps, approaching contacts that touched bounce: the normal velocity set to
// −e times the approach speed (Box2D's relax-then-restitution), swept as the relax pass is so
// a face bounces whole. A contact that was open when the step began met its surface within
// the step, at t* where s0 + v0·t + ½·a·t² = 0 (a: gravity along the normal, for a body on a
// static surface): it bounces with −e·(v0 + a·t*) and flies the rest of the step, so the body
// ends where the bounce at t* takes it, not where the step's speculative row held it.
void RigidBodies::restitute(double threshold, double gravity) {
    batches_.store(rows_, manifolds_);
    for (RigidManifold& m : manifolds_) {
        const double accel = m.rows.velA ? 0.0 : -gravity * m.rows.normal.y;
        if (heldEarly(m, accel)) {
            undo(m);
            continue;
        }
        // A point bounces where it came in faster than the threshold and pushed. Most of a pile's
        // manifolds have no such point, and are not swept at all.
        auto bounces = [&](int i) {
            const RigidContact& c = contacts_[size_t(i)];
            return c.relativeVelocity <= -threshold && rows_[size_t(i)].maxImpulse != 0.0 &&
                   c.restitution != 0.0;
        };
        const std::ranges::iota_view points(m.begin, m.end);
        if (std::ranges::none_of(points, bounces)) continue;
        const Bounced before = bouncing(m);
        double rise = 1e300;
        for (int sweep = 0; sweep < settings_.bounceSweeps; ++sweep)
            for (int i = m.begin; i < m.end; ++i) {
                if (!bounces(i)) continue;
                const RigidContact& c = contacts_[size_t(i)];
                NormalRow& r = rows_[size_t(i)];
                const Bounce b = bounceOf(c, accel, dt_);
                rise = std::min(rise, b.rise);
                const double impulse = -r.mass * (normalSpeed(r) - b.speed);
                const double total = std::max(r.impulse + impulse, 0.0);
                applyNormal(r, total - r.impulse);
                r.impulse = total;
            }
        const RigidContact& c = contacts_[size_t(m.begin)];
        if (rise > 0.0 && rise < 1e300 && !c.a.vel && c.b.rigid) c.b.rigid->pos += rise * c.normal;
        keepEnergy(m, before, gravity);
    }
}

// The manifold's moving bodies (rigid ones; none where a sphere moves) and its points' pushes,
// as they are before its bounce.
RigidBodies::Bounced RigidBodies::bouncing(const RigidManifold& m) const {
    Bounced was;
    for (const int side : {m.movesA, m.movesB}) {
        if (side >= count()) return {};
        const RigidBody* b = side >= 0 ? &bodies_[size_t(side)] : nullptr;
        if (b) was.bodies.push_back({side, b->vel, b->spin});
    }
    for (int i = m.begin; i < m.end; ++i) was.impulses.push_back(rows_[size_t(i)].impulse);
    return was;
}

// A bounce at several points at once, each set to leave at e times the speed it came in at, can
// give the bodies more energy than they fell with: a slab tilted 3° falling flat at e = 1 left
// with 29 % more, spinning. The bounce moved its bodies' velocities by Δ; at s·Δ their kinetic
// energy is K + s·a + s²·b, a quadratic. Where s = 1 would leave them more energy, kinetic and
// m·g·y, than they had when the step began, s is the largest that does not.
void RigidBodies::keepEnergy(const RigidManifold& m, const Bounced& was, double gravity) {
    if (was.bodies.empty()) return;
    double k = 0.0, a = 0.0, b = 0.0, budget = 0.0;
    for (const Bounced::Body& w : was.bodies) {
        const RigidBody& body = bodies_[size_t(w.index)];
        const dvec3 dv = body.vel - w.vel, dw = body.spin - w.spin;
        const dvec3 spin = glm::conjugate(body.orient) * w.spin,
                    turn = glm::conjugate(body.orient) * dw;
        k += kineticEnergyOf(body, w.vel, w.spin, body.orient);
        a += glm::dot(w.vel, dv) / body.invMass + glm::dot(spin * body.inertia, turn);
        b += kineticEnergyOf(body, dv, dw, body.orient);
        budget += kineticEnergyOf(body, body.startVel, body.startSpin, body.startOrient) +
                  gravity * (body.startPos.y - body.pos.y) / body.invMass;
    }
    if (k + a + b <= budget) return;
    // The larger root of b·s² + a·s + (k − budget) = 0; none (s = 0) where k is over already.
    const double c = k - budget;
    const double s = c >= 0.0 || b <= 0.0
                         ? 0.0
                         : std::clamp((-a + std::sqrt(a * a - 4.0 * b * c)) / (2.0 * b), 0.0, 1.0);
    for (const Bounced::Body& w : was.bodies) {
        RigidBody& body = bodies_[size_t(w.index)];
        body.vel = w.vel + s * (body.vel - w.vel);
        body.spin = w.spin + s * (body.spin - w.spin);
    }
    for (int i = m.begin; i < m.end; ++i) {
        const double old = was.impulses[size_t(i - m.begin)];
        rows_[size_t(i)].impulse = old + s * (rows_[size_t(i)].impulse - old);
    }
}

// Speculative rows look a substep ahead, so the last relax pass can stop a body short of a
// surface it would only have reached next step: every point that pushed began the step apart
// and would not have closed its gap in free flight by the step's end.
bool RigidBodies::heldEarly(const RigidManifold& m, double accel) const {
    bool pushed = false;
    for (int i = m.begin; i < m.end; ++i) {
        const RigidContact& c = contacts_[size_t(i)];
        if (rows_[size_t(i)].maxImpulse == 0.0) continue;
        const double v0 = c.relativeVelocity, s0 = c.separation;
        if (s0 <= 0.0 || s0 + v0 * dt_ + 0.5 * accel * dt_ * dt_ <= 0.0) return false;
        pushed = true;
    }
    return pushed;
}

// Takes back everything the manifold's rows applied this substep: free flight goes on.
void RigidBodies::undo(RigidManifold& m) {
    for (int i = m.begin; i < m.end; ++i) {
        NormalRow& r = rows_[size_t(i)];
        applyNormal(r, -r.impulse);
        r.impulse = 0.0;
    }
    FrictionRows& r = m.rows;
    applyCentre(r, -1.0);
    r.tangentImpulse[0] = r.tangentImpulse[1] = r.twistImpulse = 0.0;
    r.rollImpulse[0] = r.rollImpulse[1] = 0.0;
}

//-----------------------------------------------------------------------------
// Motion
//-----------------------------------------------------------------------------

void RigidBodies::integrateVelocities(double h, double gravity) {
    for (RigidBody& b : bodies_) {
        if (!b.awake) continue;
        b.vel.y -= gravity * h;
        const double speed = glm::length(b.vel);
        if (speed > settings_.maxSpeed) b.vel *= settings_.maxSpeed / speed;
    }
}

// As the spheres: x += v·h, with gravity's ½·g·h² where no contact pushed (exact free flight).
// The turn is the free body's (rotateFree): the contacts' torques came in as spin already.
void RigidBodies::integratePositions(double h, double gravity) {
    const bool exact = settings_.integrator == Integrator::ExactGravity;
    turns_.clear();
    for (RigidBody& b : bodies_) {
        if (!b.awake) continue;
        dvec3 dx = b.vel * h;
        if (exact && !b.supported)
            dx.y += 0.5 * gravity * h * h;  // v·h after v -= g·h, plus ½·g·h²
        b.pos += dx;
        b.delta += dx;
        turns_.push_back({&b.orient, &b.spin, &b.inertia});
    }
    rotateFree(turns_, h);
    for (RigidBody& b : bodies_) {
        if (!b.awake) continue;
        if (b.revolved) b.untwisted = untwist(b.orient, b.startOrient);
        b.invInertia = worldInverseInertia(b.orient, b.inertia);
        b.supported = false;
    }
    followTurns();
}

// The rows see each body through the inverse inertia it had when they were made, at the
// step's start. Where a body's inertia is far from round (a 3 m rod of 1 cm: 10⁴ between its
// axes), a turn of a few degrees makes that wrong by more than itself, and the sweeps then add
// energy rather than take it: such a rod hit by a box at 30 m/s reached 10²⁹ m/s within a
// tenth of a second. A body whose inverse inertia has moved by a tenth since its rows were made
// has them made again from it. A cube's or a ball's never moves: their rows stay as made.
void RigidBodies::followTurns() {
    bool any = false;
    for (RigidBody& b : bodies_) {
        // Equal moments, a cube's: its error is the rounding's; a third of a mixed pile's bodies.
        const bool equalMoments = b.inertia.x == b.inertia.y && b.inertia.y == b.inertia.z;
        b.turned = b.awake && !equalMoments && turnError(b) > kTurnTolerance;
        if (b.turned) b.rowInertia = b.invInertia;
        any = any || b.turned;
    }
    if (!any) return;
    // A manifold's rows and its friction move its two bodies (a sphere's index is past the
    // rigid bodies'): they are made again where either turned.
    auto turned = [this](int body) {
        return body >= 0 && body < count() && bodies_[size_t(body)].turned;
    };
    for (size_t k = 0; k < manifolds_.size(); ++k) {
        RigidManifold& m = manifolds_[k];
        if (!turned(m.movesA) && !turned(m.movesB)) continue;
        for (int i = m.begin; i < m.end; ++i) {
            const RigidContact& c = contacts_[size_t(i)];
            setTurns(rows_[size_t(i)], inverseInertiaOf(c.a), inverseInertiaOf(c.b));
            batches_.setTurns(i, rows_[size_t(i)]);
        }
        const RigidContact& c = contacts_[size_t(m.begin)];
        setTurns(m.rows, inverseInertiaOf(c.a), inverseInertiaOf(c.b));
        batches_.setTurns(int(k), m.rows);
    }
}

void RigidBodies::finishStep() {
    bool held = false;
    for (RigidBody& b : bodies_) held = holdIfOverflowed(b) || held;
    kept_.clear(contacts_.size() + manifolds_.size());
    // A held body's rows may hold NaN: no impulse of this step starts the next.
    for (size_t i = 0; i < contacts_.size() && !held;
         ++i)  // a point: its push; friction is the manifold's
        kept_.put(contacts_[i].key, {rows_[i].impulse, {0.0, 0.0}, 0.0, {0.0, 0.0}});
    for (const RigidManifold& m : manifolds_) {
        if (held) break;
        const FrictionRows& r = m.rows;
        kept_.put(m.key, {0.0,
                          {r.tangentImpulse[0], r.tangentImpulse[1]},
                          r.twistImpulse,
                          {r.rollImpulse[0], r.rollImpulse[1]},
                          m.sweeps});
    }
    for (RigidBody& b : bodies_) b.delta = dvec3(0.0);
    updateSleep();
}

// Bodies touching one another sleep together, once every one of them has been slow for
// timeToSleep and nothing moving touches them (union-find over this step's contacts).
void RigidBodies::updateSleep() {
    if (!settings_.sleep) return;
    const int n = count();
    std::vector<int> root(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) root[size_t(i)] = i;
    auto find = [&](int i) {
        while (root[size_t(i)] != i) i = root[size_t(i)] = root[size_t(root[size_t(i)])];
        return i;
    };
    for (const RigidContact& c : contacts_) {
        const auto [first, second] = pairOf(c.key);
        if (first >= 0 && second >= 0 && second < n) root[size_t(find(first))] = find(second);
    }
    std::vector<char> ready(size_t(n), 1);
    for (int i = 0; i < n; ++i) {
        RigidBody& b = bodies_[size_t(i)];
        const bool slow = glm::length(b.vel) < settings_.sleepSpeed &&
                          glm::length(b.spin) * b.bound < settings_.sleepSpeed;
        b.sleepTime = slow && b.awake ? b.sleepTime + dt_ : 0.0;
        if (b.awake && (b.sleepTime < settings_.timeToSleep || touching_[size_t(i)] != 0))
            ready[size_t(find(i))] = 0;
    }
    for (int i = 0; i < n; ++i) {
        RigidBody& b = bodies_[size_t(i)];
        if (!b.awake || !ready[size_t(find(i))]) continue;
        b.awake = false;
        b.vel = b.spin = dvec3(0.0);
    }
}

// The scene keeps the shape's own origin and turn; vel is the centre of mass's, as the body's.
void RigidBodies::writeBack(Scene& scene) const {
    auto write = [](const RigidBody& b, const Loaded& l, auto& record) {
        if (b.pos == l.statePos && b.orient == l.stateOrient && b.vel == l.stateVel &&
            b.spin == l.stateSpin) {
            std::tie(record.pos, record.rot, record.vel, record.spin, record.orient) =
                std::tie(l.pos, l.rot, l.vel, l.spin, l.orient);
            return;
        }
        record.pos = glm::vec3(b.origin());
        record.vel = glm::vec3(b.vel);
        record.spin = glm::vec3(b.spin);
        record.orient = glm::quat(b.shapeOrient());
        record.rot = anglesShowing(*record.orient, record.rot);  // shown in Edit
    };
    for (size_t i = 0; i < bodies_.size(); ++i) {
        const RigidBody& b = bodies_[i];
        if (b.group >= 0) {
            write(b, loaded_[i], scene.groups[size_t(b.group)]);
        } else {
            write(b, loaded_[i], scene.objects[size_t(b.object)]);
        }
    }
}

double RigidBodies::kineticEnergy() const {
    double e = 0.0;
    for (const RigidBody& b : bodies_) e += kineticEnergyOf(b, b.vel, b.spin, b.orient);
    return e;
}

double RigidBodies::potentialEnergy(double gravity) const {
    double e = 0.0;
    for (const RigidBody& b : bodies_) e += gravity * b.pos.y / b.invMass;
    return e;
}

double RigidBodies::deepestOverlap() const {
    double deepest = 0.0;
    for (const RigidContact& c : contacts_) deepest = std::max(deepest, -c.separation);
    return deepest;
}

}  // namespace mb
