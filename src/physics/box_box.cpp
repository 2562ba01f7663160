// box_box.cpp — separating axes and face clipping for two boxes.
#include "box_box.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

namespace mb {

using glm::dmat3;
using glm::dvec3;

namespace {

struct Frame {
    dvec3 centre, axis[3], half;
};

Frame frameOf(const BoxPose& b) {
    const dmat3 r = glm::mat3_cast(b.orient);
    return {b.centre, {r[0], r[1], r[2]}, b.half};
}

// Half the box's extent along unit l.
double radiusAlong(const Frame& f, const dvec3& l) {
    return f.half.x * std::abs(glm::dot(f.axis[0], l)) +
           f.half.y * std::abs(glm::dot(f.axis[1], l)) +
           f.half.z * std::abs(glm::dot(f.axis[2], l));
}

struct Axis {
    double separation = -1e300;
    dvec3 normal{0.0};  // from a to b
    int kind = -1;      // 0..2 a's face, 3..5 b's face, 6.. edge i·3 + j
};

void consider(Axis& best, const Frame& a, const Frame& b, dvec3 l, int kind) {
    const double len = glm::length(l);
    if (len < 1e-9) return;  // parallel edges: a face axis covers them
    l /= len;
    const double d = glm::dot(b.centre - a.centre, l);
    const double separation = std::abs(d) - radiusAlong(a, l) - radiusAlong(b, l);
    if (separation > best.separation) best = {separation, d < 0.0 ? -l : l, kind};
}

// The face of f whose outward normal is most against n, as four corners in order.
std::vector<dvec3> incidentFace(const Frame& f, const dvec3& n) {
    int k = 0;
    for (int i = 1; i < 3; ++i)
        if (std::abs(glm::dot(f.axis[i], n)) > std::abs(glm::dot(f.axis[k], n))) k = i;
    const double sign = glm::dot(f.axis[k], n) > 0.0 ? -1.0 : 1.0;
    const dvec3 centre = f.centre + sign * f.half[k] * f.axis[k];
    const dvec3 u = f.half[(k + 1) % 3] * f.axis[(k + 1) % 3],
                v = f.half[(k + 2) % 3] * f.axis[(k + 2) % 3];
    return {centre + u + v, centre - u + v, centre - u - v, centre + u - v};
}

// Sutherland–Hodgman: the polygon's part where dot(p, n) <= offset.
std::vector<dvec3> clip(const std::vector<dvec3>& polygon, const dvec3& n, double offset) {
    std::vector<dvec3> out;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const dvec3 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
        const double dp = glm::dot(p, n) - offset, dq = glm::dot(q, n) - offset;
        if (dp <= 0.0) out.push_back(p);
        if ((dp < 0.0) != (dq < 0.0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
    }
    return out;
}

// Reference face of `ref` (axis k) facing n; the other box's incident face clipped to its sides.
std::vector<PairContact> clipFaces(const Frame& ref, int k, const dvec3& n, const Frame& inc,
                                   double reach, bool flip, int base) {
    std::vector<dvec3> polygon = incidentFace(inc, n);
    for (int side = 1; side <= 2; ++side) {
        const dvec3& s = ref.axis[(k + side) % 3];
        const double h = ref.half[(k + side) % 3], c = glm::dot(ref.centre, s);
        polygon = clip(polygon, s, c + h);
        polygon = clip(polygon, -s, -c + h);
    }
    const double face = glm::dot(ref.centre, n) + ref.half[k] * std::abs(glm::dot(ref.axis[k], n));
    std::vector<PairContact> out;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const double separation = glm::dot(polygon[i], n) - face;
        if (separation >= reach) continue;
        out.push_back(
            {polygon[i] - 0.5 * separation * n, flip ? -n : n, separation, base + int(i)});
    }
    return out;
}

// The point of edge direction i of f that sticks out furthest along n: its middle.
dvec3 supportEdge(const Frame& f, int i, const dvec3& n) {
    dvec3 p = f.centre;
    for (int m = 0; m < 3; ++m)
        if (m != i) p += (glm::dot(f.axis[m], n) > 0.0 ? 1.0 : -1.0) * f.half[m] * f.axis[m];
    return p;
}

// Closest points of the lines p + s·u and q + t·v (not parallel), each clamped to its edge.
PairContact edgeContact(const Frame& a, int i, const Frame& b, int j, const dvec3& n,
                        double separation) {
    const dvec3 p = supportEdge(a, i, n), q = supportEdge(b, j, -n), u = a.axis[i], v = b.axis[j];
    const dvec3 w = p - q;
    const double uv = glm::dot(u, v), denom = 1.0 - uv * uv;
    double s = denom > 1e-12 ? (uv * glm::dot(v, w) - glm::dot(u, w)) / denom : 0.0;
    s = glm::clamp(s, -a.half[i], a.half[i]);
    const double t = glm::clamp(glm::dot(v, p + s * u - q), -b.half[j], b.half[j]);
    const dvec3 mid = 0.5 * (p + s * u + q + t * v);
    return {mid, n, separation, 100 + i * 3 + j};
}

}  // namespace

std::vector<PairContact> collideBoxes(const BoxPose& pa, const BoxPose& pb, double reach) {
    const Frame a = frameOf(pa), b = frameOf(pb);
    Axis face, edge;
    for (int i = 0; i < 3; ++i) consider(face, a, b, a.axis[i], i);
    for (int i = 0; i < 3; ++i) consider(face, a, b, b.axis[i], 3 + i);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            consider(edge, a, b, glm::cross(a.axis[i], b.axis[j]), 6 + 3 * i + j);
    const double size = glm::length(a.half) + glm::length(b.half);
    const bool useEdge = edge.separation > face.separation + 1e-3 * size;
    const Axis& best = useEdge ? edge : face;
    if (best.separation >= reach) return {};
    if (useEdge)
        return {edgeContact(a, (best.kind - 6) / 3, b, (best.kind - 6) % 3, best.normal,
                            best.separation)};
    if (best.kind < 3) return clipFaces(a, best.kind, best.normal, b, reach, false, 10 * best.kind);
    return clipFaces(b, best.kind - 3, -best.normal, a, reach, true, 10 * best.kind);
}

}  // namespace mb
