// oriented_box.cpp — boxes about shapes, their distances and overlaps (oriented_box.h).
#include "oriented_box.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_access.hpp>

namespace mb {

using glm::dmat3;
using glm::dvec3;

namespace {

dvec3 halfExtents(const SdfObject& o) {
    const double r = o.radius, h = 0.5 * double(o.height);
    switch (o.type) {
        case ShapeType::Sphere:
            return dvec3(r);
        case ShapeType::Box:
        case ShapeType::Ellipsoid:
            return dvec3(o.size);
        case ShapeType::Torus:
            return dvec3(r + o.minor, o.minor, r + o.minor);
        case ShapeType::Capsule:
            return dvec3(r, h + r, r);
        case ShapeType::Cylinder:
            return dvec3(r, h, r);
        case ShapeType::Cone:  // widest at its base or at its top
            return dvec3(std::max(r, double(o.top)), h, std::max(r, double(o.top)));
    }
    return dvec3(o.bound);
}

}  // namespace

OrientedBox boxAbout(const SdfObject& o) {
    return {dvec3(o.pos), glm::transpose(dmat3(o.toLocal)), halfExtents(o)};
}

OrientedBox placed(const OrientedBox& b, const glm::dquat& turn, const dvec3& shift) {
    return {shift + turn * b.centre, glm::mat3_cast(turn) * b.axes, b.half};
}

// Each box reaches Σ_k half_k·|axis_k| from its centre along the parent's axes.
OrientedBox boxAround(const std::vector<OrientedBox>& boxes) {
    if (boxes.empty()) return {};
    dvec3 lo(1e300), hi(-1e300);
    for (const OrientedBox& b : boxes) {
        dvec3 reach(0.0);
        for (int k = 0; k < 3; ++k) reach += b.half[k] * glm::abs(b.axes[k]);
        lo = glm::min(lo, b.centre - reach);
        hi = glm::max(hi, b.centre + reach);
    }
    return {0.5 * (lo + hi), dmat3(1.0), 0.5 * (hi - lo)};
}

double distanceToBox(const OrientedBox& b, const dvec3& p) {
    const dvec3 local = glm::transpose(b.axes) * (p - b.centre);
    return glm::length(glm::max(glm::abs(local) - b.half, dvec3(0.0)));
}

bool boxesOverlap(const OrientedBox& a, const OrientedBox& b, double slack) {
    if (!facesOverlap(a, b, -slack)) return false;
    // The nine crosses of their edges, left as long as they are: each reach and the gap are in
    // the cross's units, so no axis needs a quotient. Each reach is its axes projected on the
    // cross, as for a face. A float turn leaves a part's axes a little out of square, and the
    // turn between the boxes, which would give the reaches without those products, is then off
    // by that error over the sine between the edges: boxes that overlapped came out apart.
    const dvec3 d = b.centre - a.centre;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const dvec3 axis = glm::cross(a.axes[i], b.axes[j]);
            const double length = glm::length(axis);
            if (length < 1e-9) continue;  // parallel edges: the faces' axes have tested theirs
            double ra = 0.0, rb = 0.0;
            for (int k = 0; k < 3; ++k) {
                ra += a.half[k] * std::abs(glm::dot(a.axes[k], axis));
                rb += b.half[k] * std::abs(glm::dot(b.axes[k], axis));
            }
            if (std::abs(glm::dot(d, axis)) >= ra + rb - slack * length) return false;
        }
    return true;
}

bool facesOverlap(const OrientedBox& a, const OrientedBox& b, double gap) {
    const dvec3 d = b.centre - a.centre;
    dmat3 turn;  // turn[j][k]: a's axis k against b's axis j, found along a's axes first
    for (int k = 0; k < 3; ++k) {
        for (int j = 0; j < 3; ++j) turn[j][k] = glm::dot(a.axes[k], b.axes[j]);
        const double bAcross = glm::dot(b.half, glm::abs(glm::row(turn, k)));
        if (std::abs(glm::dot(a.axes[k], d)) >= a.half[k] + bAcross + gap) return false;
    }
    for (int j = 0; j < 3; ++j) {
        const double aAcross = glm::dot(a.half, glm::abs(turn[j]));
        if (std::abs(glm::dot(b.axes[j], d)) >= b.half[j] + aAcross + gap) return false;
    }
    return true;
}

}  // namespace mb
