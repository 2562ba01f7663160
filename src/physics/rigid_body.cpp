// rigid_body.cpp — closed-form mass properties and the free rigid body's rotation (rigid_body.h).
#include "rigid_body.h"

#include "marchbox/scene/sdf.h"
#include "marchbox/scene/shapes.h"

#include <string>

#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace mb {

using glm::dquat;
using glm::dvec3;

namespace {

constexpr double kPi = std::numbers::pi;

//-----------------------------------------------------------------------------
// Mass properties: each shape's moments about its centre, for mass m spread uniformly.
//-----------------------------------------------------------------------------
dvec3 sphereInertia(double m, double r) { return dvec3(0.4 * m * r * r); }

// Half extents (a, b, c): Ix = m(b² + c²)/3, and so on round.
dvec3 boxInertia(double m, const dvec3& half) {
    const dvec3 s = half * half;
    return m / 3.0 * dvec3(s.y + s.z, s.x + s.z, s.x + s.y);
}

// Axis y, length h: Iy = m r²/2, Ix = Iz = m(3r² + h²)/12.
dvec3 cylinderInertia(double m, double r, double h) {
    const double across = m * (3.0 * r * r + h * h) / 12.0;
    return dvec3(across, 0.5 * m * r * r, across);
}

// A cylinder (radius r, length h, along y) capped by two hemispheres; masses by volume share:
//   mc = m·πr²h / V, ms = m·(4/3)πr³ / V (both caps: one sphere), V = πr²h + (4/3)πr³.
// Along y the caps together are a sphere: Iy = mc r²/2 + (2/5) ms r².
// Across (x, z), each cap of mass ms/2 has (2/5)(ms/2)r² about a diameter of its flat face (half
// a sphere's, by symmetry); its centroid lies 3r/8 from that face, so about its centroid it has
// (ms/2)(2r²/5 − 9r²/64), and the centroid is d = h/2 + 3r/8 from the capsule's centre. Both caps:
//   ms (2r²/5 − 9r²/64 + d²) = ms (2r²/5 + h²/4 + 3hr/8),
// the 9r²/64 cancelling against d²'s (3r/8)² term; Ix = Iz = mc(3r² + h²)/12 + that.
dvec3 capsuleInertia(double m, double r, double h) {
    const double cylinderVolume = kPi * r * r * h, sphereVolume = 4.0 / 3.0 * kPi * r * r * r;
    const double mc = m * cylinderVolume / (cylinderVolume + sphereVolume), ms = m - mc;
    const double across =
        mc * (3.0 * r * r + h * h) / 12.0 + ms * (0.4 * r * r + 0.25 * h * h + 0.375 * h * r);
    return dvec3(across, 0.5 * mc * r * r + 0.4 * ms * r * r, across);
}

// Ring radius R in the x-z plane, tube radius a: Iy = m(R² + 3a²/4), Ix = Iz = m(R²/2 + 5a²/8).
dvec3 torusInertia(double m, double ring, double tube) {
    const double R2 = ring * ring, a2 = tube * tube;
    const double across = m * (0.5 * R2 + 0.625 * a2);
    return dvec3(across, m * (R2 + 0.75 * a2), across);
}

//-----------------------------------------------------------------------------
// Free rotation: a Lie–Poisson splitting (McLachlan 1993; Touma & Wisdom 1994).
//-----------------------------------------------------------------------------
// The kinetic energy T = Σ L_k²/(2 I_k) in body momentum L splits into three axis terms. The
// term of axis k alone keeps L_k and spins the body about its axis k at rate ω_k = L_k/I_k, so
// its flow is exact: L turns about body axis k by −ω_k t (L' = L × ω, Euler's equations) while
// q turns by +ω_k t about the same axis, which leaves the world momentum q·L unchanged. Every
// sub-flow therefore keeps |L| and world L to rounding; only T drifts, by the splitting error.
//
// T's error, measured over 10 s at h = 1/480 for the box of half extents (0.1, 0.2, 0.4) and its
// two other orientations in the body, ω = (3, 5, 7), (−6, 2, 4), (1, −8, 3), (5.77, 5.77, 5.77)
// rad/s (worst relative error of all):
//   Strang X(h/2) Y(h/2) Z(h) Y(h/2) X(h/2), best to worst axis order:  3.7e-6 .. 1.0e-4
//   three Strang steps of h/3 (the triple jump's cost), axes in x, y, z order:  up to 5.0e-6
//   Yoshida's triple jump of Strang, worst of the six axis orders:         up to 6.5e-8
//   the same, smallest moment outermost, intermediate in the middle:        3.9e-10
// Strang is second order and misses the 1e-6 goal, even at the triple jump's cost; the triple
// jump is fourth order and symmetric (time-reversible, so the error oscillates instead of
// growing). Ordering the axes by moment costs two comparisons and was the best of the six orders
// for each body measured, so no body depends on how its shape happens to lie in its frame.

// 1/n! for n = 0 … 13, each n! exact in a double.
constexpr std::array<double, 14> kInverseFactorial = [] {
    std::array<double, 14> inverse{};
    double factorial = 1.0;
    for (size_t n = 0; n < inverse.size(); ++n) {
        inverse[n] = 1.0 / factorial;
        factorial *= double(n + 1);
    }
    return inverse;
}();

// sin and cos of x. A flow turns a body by ω·t/2, rarely a tenth of a radian; up to 0.25 the
// Taylor series to x¹³ and x¹² are exact to rounding (the next terms are below 1e-19 of them)
// and cost a third of the library's call, which was a third of the flow's cost.
void sinCos(double x, double* s, double* c) {
    if (std::abs(x) > 0.25) {
        *s = std::sin(x);
        *c = std::cos(x);
        return;
    }
    const double y = -x * x;
    double sine = 0.0, cosine = 0.0;  // Horner's, in −x²: sin x / x and cos x
    for (size_t n = 7; n-- > 0;) {
        sine = sine * y + kInverseFactorial[2 * n + 1];
        cosine = cosine * y + kInverseFactorial[2 * n];
    }
    *s = x * sine;
    *c = cosine;
}

// Axis k's exact flow for time t, at rate ω_k = L_k·rate (rate = 1/I_k). With (i, j, k) cyclic,
// turning i towards j is +; q·(c, s·e_k) written out, which has the one axis alone.
template <int k>
void flowAbout(dquat& q, dvec3& bodyMomentum, double rate, double t) {
    constexpr int i = (k + 1) % 3, j = (k + 2) % 3;
    double s, c;
    sinCos(0.5 * bodyMomentum[k] * rate * t, &s, &c);
    const double sinAngle = 2.0 * s * c, cosAngle = 1.0 - 2.0 * s * s;
    const double li = bodyMomentum[i], lj = bodyMomentum[j];
    bodyMomentum[i] = cosAngle * li + sinAngle * lj;  // turned by −angle
    bodyMomentum[j] = cosAngle * lj - sinAngle * li;
    const double w = q.w, qi = q[i], qj = q[j], qk = q[k];  // turned by +angle, in the body frame
    q.w = w * c - qk * s;
    q[k] = qk * c + w * s;
    q[i] = qi * c + qj * s;
    q[j] = qj * c - qi * s;
}

void flowAboutAxis(dquat& q, dvec3& bodyMomentum, const dvec3& rate, int k, double t) {
    if (k == 0) flowAbout<0>(q, bodyMomentum, rate.x, t);
    else if (k == 1) flowAbout<1>(q, bodyMomentum, rate.y, t);
    else flowAbout<2>(q, bodyMomentum, rate.z, t);
}

// One body's free turn in the making: the body, its angular momentum in its own frame, its
// moments' inverses, and the order of its axes' flows (axisOrder).
struct Turning {
    const FreeTurn* body;
    dvec3 bodyMomentum, rate;
    std::array<int, 3> order;
};

// The triple jump's three Strang steps, outer(w·h/2) middle(w·h/2) inner(w·h) middle(w·h/2)
// outer(w·h/2) for weights w1, w0, w1, with the two pairs of outer flows that meet between
// them made one each (a flow about one axis twice is one flow for the sum): 13 flows, not 15.
// Each flow waits on the one before, a hundred instructions in a chain, so the bodies go
// through them side by side: one body's flow runs while another's waits. Each body's own
// operations are the same as alone.
void tripleJump(std::span<Turning> bodies, double h) {
    static const double w1 = 1.0 / (2.0 - std::cbrt(2.0)), w0 = 1.0 - 2.0 * w1;
    constexpr int outer = 0, middle = 1, inner = 2;
    const double weights[3] = {w1, w0, w1};
    auto flow = [&](int axis, double t) {
        for (Turning& b : bodies)
            flowAboutAxis(*b.body->q, b.bodyMomentum, b.rate, b.order[axis], t);
    };
    flow(outer, 0.5 * w1 * h);
    for (int step = 0; step < 3; ++step) {
        const double w = weights[step] * h, next = step < 2 ? weights[step + 1] * h : 0.0;
        flow(middle, 0.5 * w);
        flow(inner, w);
        flow(middle, 0.5 * w);
        flow(outer, 0.5 * (w + next));
    }
}

// Smallest moment outermost, then the largest, the intermediate inside: the best order measured.
// Ties go to the lower axis, so the order is a pure function of `inertia`.
std::array<int, 3> axisOrder(const dvec3& inertia) {
    int least = 0, most = 0;  // the first of the least and the last of the most, as sorted
    for (int k = 1; k < 3; ++k) {
        if (inertia[k] < inertia[least]) least = k;
        if (inertia[k] >= inertia[most]) most = k;
    }
    return {least, most, 3 - least - most};
}

// The symmetric top (two equal moments I⊥, the third I_k about axis k) turns exactly: its
// energy T = |L|²/(2I⊥) + L_k²·(1/I_k − 1/I⊥)/2 is two terms whose flows commute (|L| does not
// change as the body turns about k). The first turns the body about the fixed world momentum at
// |L|/I⊥ and leaves the body's L alone; the second is axis k's flow at the rate the difference
// gives. Two turns instead of the splitting's fifteen, and no splitting error: every box with
// equal sides, every capsule, cylinder and torus. Returns false for a body with three moments.
bool rotateSymmetric(dquat& q, dvec3& bodyMomentum, const dvec3& inertia, double h) {
    int k = -1;
    for (int axis = 0; axis < 3; ++axis)
        if (inertia[(axis + 1) % 3] == inertia[(axis + 2) % 3]) k = axis;
    if (k < 0) return false;
    const double across = inertia[(k + 1) % 3];
    dvec3 rate(0.0);
    rate[k] = 1.0 / inertia[k] - 1.0 / across;  // axis k's flow at L_k·(1/I_k − 1/I⊥)
    flowAboutAxis(q, bodyMomentum, rate, k, h);
    const dvec3 world = q * bodyMomentum;
    const double size = glm::length(world);
    if (size > 0.0) q = glm::angleAxis(size / across * h, world / size) * q;
    return true;
}

// A cone's, an ellipsoid's, a rounded or a shelled shape's: from its moments, in closed form
// where mass_moments.cpp has one, else integrated over its SDF. The shape is symmetric about its
// local planes (and round about y where its section is a circle), so the moments are made so:
// the integral's rounding must not tilt the body's axes or move its centre off the axis.
MassProperties symmetricMass(const Object& o) {
    Object at = o;
    at.pos = glm::vec3(0.0f);
    const SdfObject shape = makeSdfObject(at);
    Moments m;
    if (!closedFormMoments(shape, &m)) {
        std::string key;
        for (const float v : {float(o.type), o.size.x, o.size.y, o.size.z, o.radius, o.height,
                              o.top, o.round, o.shell})
            key.append(reinterpret_cast<const char*>(&v), sizeof v);
        m = rememberedMoments(key, [&] {
            return integrateSolid([&](const glm::vec3& p) { return sdObjectLocal(shape, p); },
                                  double(shape.bound), kIntegrationDepth)
                .value;
        });
    }
    m.first = dvec3(0.0, shapeRow(o.type).centred ? 0.0 : m.first.y, 0.0);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (r != c) m.second[c][r] = 0.0;
    if (shapeRow(o.type).revolved)
        m.second[0][0] = m.second[2][2] = 0.5 * (m.second[0][0] + m.second[2][2]);
    return massFromMoments(m, double(o.mass));
}

}  // namespace

MassProperties massProperties(const Object& o) {
    const double m = o.mass, r = o.radius, h = o.height;
    if (o.round <= 0.0f && o.shell <= 0.0f) switch (o.type) {
            case ShapeType::Sphere:
                return {m, sphereInertia(m, r)};
            case ShapeType::Box:
                return {m, boxInertia(m, dvec3(o.size))};
            case ShapeType::Torus:
                return {m, torusInertia(m, r, o.minor)};
            case ShapeType::Capsule:
                return {m, capsuleInertia(m, r, h)};
            case ShapeType::Cylinder:
                return {m, cylinderInertia(m, r, h)};
            case ShapeType::Cone:
            case ShapeType::Ellipsoid:
                break;
        }
    return symmetricMass(o);
}

// Yoshida's triple jump: Strang steps of w1·h, w0·h, w1·h with w1 = 1/(2 − ∛2), w0 = 1 − 2·w1
// cancel the third-order error of the symmetric step, leaving a fourth-order one.
void rotateFree(std::span<const FreeTurn> turns, double h) {
    constexpr size_t kSideBySide = 4;
    std::array<Turning, kSideBySide> jumping;
    size_t count = 0;
    auto finish = [](const FreeTurn& t, const dvec3& bodyMomentum) {
        *t.q = glm::normalize(*t.q);
        *t.spin = *t.q * (bodyMomentum / *t.inertia);
    };
    auto jump = [&] {
        tripleJump({jumping.data(), count}, h);
        for (size_t k = 0; k < count; ++k) finish(*jumping[k].body, jumping[k].bodyMomentum);
        count = 0;
    };
    for (const FreeTurn& t : turns) {
        dvec3 bodyMomentum = *t.inertia * (glm::conjugate(*t.q) * *t.spin);
        if (rotateSymmetric(*t.q, bodyMomentum, *t.inertia, h)) {
            finish(t, bodyMomentum);
            continue;
        }
        jumping[count++] = {&t, bodyMomentum, 1.0 / *t.inertia, axisOrder(*t.inertia)};
        if (count == kSideBySide) jump();
    }
    if (count > 0) jump();
}

void rotateFree(dquat& q, dvec3& spin, const dvec3& inertia, double h) {
    const FreeTurn turn{&q, &spin, &inertia};
    rotateFree({&turn, 1}, h);
}

dquat untwist(const dquat& q, const dquat& from) {
    const dvec3 was = from * dvec3(0.0, 1.0, 0.0), now = q * dvec3(0.0, 1.0, 0.0);
    const double cosine = glm::dot(was, now);
    if (cosine < -1.0 + 1e-12) return q;  // turned right round: no least turn
    const dvec3 sine = glm::cross(was, now);
    return glm::normalize(dquat(1.0 + cosine, sine.x, sine.y, sine.z) * from);
}

}  // namespace mb
