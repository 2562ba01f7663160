// capsule_contacts.cpp — closest points of segments and boxes, and the lines they lie along.
#include "capsule_contacts.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace mb {

using glm::dvec3;

namespace {

// How much deeper than both line ends the closest point must lie to be kept as well, as a part
// of the radii: less is the ends' own depth again, or rounding.
constexpr double kDip = 1e-3;

struct Segment {
    dvec3 centre, axis;  // unit axis
    double half;
};

dvec3 at(const Segment& s, double t) { return s.centre + t * s.axis; }

Segment segmentOf(const CapsulePose& c) { return {c.centre, c.orient * dvec3(0, 1, 0), c.half}; }

struct Params {
    double s, t;  // along a and along b, from their centres
};

// Ericson 5.1.9 about the centres: the lines' closest points with s clamped to a, then t
// clamped to b and s found again from it. Parallel lines: from a's centre.
Params closestParams(const Segment& a, const Segment& b) {
    const dvec3 r = a.centre - b.centre;
    const double k = glm::dot(a.axis, b.axis), c = glm::dot(a.axis, r), f = glm::dot(b.axis, r);
    const double denom = 1.0 - k * k;
    double s = denom > 1e-12 ? std::clamp((k * f - c) / denom, -a.half, a.half) : 0.0;
    double t = k * s + f;
    if (std::abs(t) > b.half) {
        t = std::clamp(t, -b.half, b.half);
        s = std::clamp(k * t - c, -a.half, a.half);
    }
    return {s, t};
}

// Spheres of radius ra about pa and rb about pb; `fallback` the normal where the centres meet.
PairContact sphereContact(const dvec3& pa, double ra, const dvec3& pb, double rb,
                          const dvec3& fallback, int feature) {
    const dvec3 d = pb - pa;
    const double len = glm::length(d);
    const dvec3 n = len > 1e-12 ? d / len : fallback;
    const double separation = len - ra - rb;
    return {pa + (ra + 0.5 * separation) * n, n, separation, feature};
}

// The ends closer than reach; the closest point first where it lies deeper than both by more
// than `dip`, where the ends alone would let it sink.
std::vector<PairContact> lineContacts(const PairContact& closest, const PairContact (&ends)[2],
                                      double reach, double dip) {
    std::vector<PairContact> out;
    if (closest.separation < std::min(ends[0].separation, ends[1].separation) - dip)
        out.push_back(closest);
    for (const PairContact& e : ends)
        if (e.separation < reach) out.push_back(e);
    return out;
}

// Where the segments cross (or lie along one line): across both, toward b.
dvec3 crossingNormal(const Segment& a, const Segment& b) {
    dvec3 w = glm::cross(a.axis, b.axis);
    if (glm::length(w) < 1e-9) w = glm::cross(a.axis, dvec3(1, 0, 0));
    if (glm::length(w) < 1e-9) w = glm::cross(a.axis, dvec3(0, 0, 1));
    w = glm::normalize(w);
    return glm::dot(w, b.centre - a.centre) < 0.0 ? -w : w;
}

// Where b's projection onto a's axis overlaps a, as a's parameters; false where it covers no
// more than a quarter of the shorter segment (crossing near square, or end to end).
bool overlapOnA(const Segment& a, const Segment& b, double& lo, double& hi) {
    const double q = glm::dot(b.centre - a.centre, a.axis);
    const double e = b.half * std::abs(glm::dot(a.axis, b.axis));
    lo = std::max(-a.half, q - e);
    hi = std::min(a.half, q + e);
    return hi - lo > 0.5 * std::min(a.half, b.half);
}

//-----------------------------------------------------------------------------
// Segment and box, in the box's frame: the box is [−half, half]
//-----------------------------------------------------------------------------

// The part of s with |p[m]| ≤ half[m] on every axis m but `skip`, as [lo, hi] of its
// parameter; false where there is none.
bool clipToSlabs(const Segment& s, const dvec3& half, int skip, double& lo, double& hi) {
    lo = -s.half;
    hi = s.half;
    for (int m = 0; m < 3; ++m) {
        if (m == skip) continue;
        if (std::abs(s.axis[m]) < 1e-12) {
            if (std::abs(s.centre[m]) > half[m]) return false;
            continue;
        }
        const double t1 = (-half[m] - s.centre[m]) / s.axis[m];
        const double t2 = (half[m] - s.centre[m]) / s.axis[m];
        lo = std::max(lo, std::min(t1, t2));
        hi = std::min(hi, std::max(t1, t2));
    }
    return lo <= hi;
}

// The segment over face k of the box (outward normal sign·e_k), clipped to the face's sides:
// its two ends, each separated from the face's plane. False where no part is over the face.
bool faceLine(const Segment& s, double radius, const dvec3& half, int k, double sign,
              PairContact (&ends)[2]) {
    double lo, hi;
    if (!clipToSlabs(s, half, k, lo, hi)) return false;
    dvec3 n(0.0);
    n[k] = -sign;  // from the capsule into the box
    for (int i = 0; i < 2; ++i) {
        const dvec3 p = at(s, i == 0 ? lo : hi);
        const double separation = sign * p[k] - half[k] - radius;
        ends[i] = {p + (radius + 0.5 * separation) * n, n, separation, 1 + i};
    }
    return true;
}

// A lower bound on the distance from the segment to the box: the gap between the box and the
// segment's own box. Half the capsules and boxes that the broad phase pairs in a mixed pile
// meet nothing, and this is a twentieth of the cost of the twelve edges that tell them so.
double boxesGap(const Segment& s, const dvec3& half) {
    const dvec3 gap = glm::max(glm::abs(s.centre) - s.half * glm::abs(s.axis) - half, 0.0);
    return glm::length(gap);
}

// The segment (outside the box) against the box: its closest point is an end's, or lies on one
// of the twelve edges (on a face's inside only where the segment runs parallel to the face, at
// the same distance as on an edge or at an end).
PairContact closestToBox(const Segment& s, double radius, const dvec3& half) {
    dvec3 bestP(0.0), bestQ(0.0);
    double best = 1e300;
    auto consider = [&](const dvec3& p, const dvec3& q) {
        const double d = glm::dot(p - q, p - q);
        if (d < best) best = d, bestP = p, bestQ = q;
    };
    for (double t : {-s.half, s.half}) consider(at(s, t), glm::clamp(at(s, t), -half, half));
    for (int m = 0; m < 3; ++m)
        for (int corner = 0; corner < 4; ++corner) {
            Segment edge{dvec3(0.0), dvec3(0.0), half[m]};
            edge.axis[m] = 1.0;
            edge.centre[(m + 1) % 3] = corner & 1 ? half[(m + 1) % 3] : -half[(m + 1) % 3];
            edge.centre[(m + 2) % 3] = corner & 2 ? half[(m + 2) % 3] : -half[(m + 2) % 3];
            const Params p = closestParams(s, edge);
            consider(at(s, p.s), at(edge, p.t));
        }
    return sphereContact(bestP, radius, bestQ, 0.0, -glm::normalize(s.centre), 0);
}

// A segment outside the box: its closest point, or the line along the face the normal comes
// through, where the segment lies along that face.
std::vector<PairContact> segmentOutside(const Segment& s, double radius, const dvec3& half,
                                        double reach) {
    const PairContact closest = closestToBox(s, radius, half);
    if (closest.separation >= reach) return {};
    int k = 0;
    for (int m = 1; m < 3; ++m)
        if (std::abs(closest.normal[m]) > std::abs(closest.normal[k])) k = m;
    const double sign = closest.normal[k] < 0.0 ? 1.0 : -1.0;  // the face's, against the normal
    PairContact ends[2];
    if (std::abs(closest.normal[k]) < 1.0 - kAligned || std::abs(s.axis[k]) >= kAligned ||
        !faceLine(s, radius, half, k, sign, ends))
        return {closest};
    return lineContacts(closest, ends, reach, kDip * radius);
}

// A segment reaching into the box: out through the face of least overlap along its axis.
std::vector<PairContact> segmentInside(const Segment& s, double radius, const dvec3& half,
                                       double reach) {
    int k = 0;
    double least = 1e300;
    for (int m = 0; m < 3; ++m) {
        const double overlap = half[m] + s.half * std::abs(s.axis[m]) - std::abs(s.centre[m]);
        if (overlap < least) least = overlap, k = m;
    }
    PairContact ends[2];
    faceLine(s, radius, half, k, s.centre[k] < 0.0 ? -1.0 : 1.0, ends);
    std::vector<PairContact> out;
    for (const PairContact& e : ends)
        if (e.separation < reach) out.push_back(e);
    return out;
}

}  // namespace

std::vector<PairContact> collideCapsules(const CapsulePose& pa, const CapsulePose& pb,
                                         double reach) {
    const Segment a = segmentOf(pa), b = segmentOf(pb);
    const Params p = closestParams(a, b);
    const PairContact closest =
        sphereContact(at(a, p.s), pa.radius, at(b, p.t), pb.radius, crossingNormal(a, b), 0);
    if (closest.separation >= reach) return {};
    double lo, hi;
    if (!overlapOnA(a, b, lo, hi)) return {closest};
    PairContact ends[2];
    for (int i = 0; i < 2; ++i) {
        const dvec3 end = at(a, i == 0 ? lo : hi);
        const double t = std::clamp(glm::dot(end - b.centre, b.axis), -b.half, b.half);
        ends[i] = sphereContact(end, pa.radius, at(b, t), pb.radius, closest.normal, 1 + i);
    }
    return lineContacts(closest, ends, reach, kDip * (pa.radius + pb.radius));
}

std::vector<PairContact> collideCapsuleBox(const CapsulePose& a, const BoxPose& b, double reach) {
    const glm::dquat toBox = glm::conjugate(b.orient);
    const Segment s{toBox * (a.centre - b.centre), toBox * (a.orient * dvec3(0, 1, 0)), a.half};
    // A hair over the reach: rounding cannot drop a point the edges would find at its limit.
    if (boxesGap(s, b.half) >= (a.radius + reach) * (1.0 + 1e-9)) return {};
    double lo, hi;
    std::vector<PairContact> out = clipToSlabs(s, b.half, -1, lo, hi)
                                       ? segmentInside(s, a.radius, b.half, reach)
                                       : segmentOutside(s, a.radius, b.half, reach);
    for (PairContact& c : out) {
        c.point = b.centre + b.orient * c.point;
        c.normal = b.orient * c.normal;
    }
    return out;
}

}  // namespace mb
