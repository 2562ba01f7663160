// rigid_probes.cpp — the probes of each shape, in its local frame (shapes as in sdf.h).
#include "rigid_probes.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace mb {

using glm::dvec3;

namespace {

// A box's 8 corners and its 12 edges' midpoints: two boxes crossing edge to edge touch first
// near the middle of an edge, where no corner is.
std::vector<Probe> boxProbes(const dvec3& half) {
    std::vector<Probe> probes;
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            for (int z = -1; z <= 1; ++z) {
                const int zeros = (x == 0) + (y == 0) + (z == 0);
                if (zeros <= 1) probes.push_back({half * dvec3(x, y, z), 0.0});
            }
    return probes;
}

// Points around a circle of radius r in the plane y = y0, starting on +x.
void addCircle(std::vector<Probe>& probes, int count, double r, double y0, double radius) {
    for (int k = 0; k < count; ++k) {
        const double phi = 2.0 * M_PI * k / count;
        probes.push_back({dvec3(r * std::cos(phi), y0, r * std::sin(phi)), radius});
    }
}

}  // namespace

std::vector<Probe> probesOf(const Object& o) {
    std::vector<Probe> probes;
    const double h = 0.5 * double(o.height);
    switch (o.type) {
        case ShapeType::Sphere:
            probes.push_back({dvec3(0.0), double(o.radius)});
            break;
        case ShapeType::Box:
            probes = boxProbes(dvec3(o.size));
            break;
        case ShapeType::Capsule:  // the segment, every quarter: exact against flat faces at its
                                  // ends
            for (int k = 0; k <= 4; ++k)
                probes.push_back({dvec3(0.0, h * (k / 2.0 - 1.0), 0.0), double(o.radius)});
            break;
        case ShapeType::Cylinder:  // the rims alone, through rimSupport
            break;
        case ShapeType::Torus:  // the core circle, swept by the tube
            addCircle(probes, 24, double(o.radius), 0.0, double(o.minor));
            break;
    }
    return probes;
}

std::vector<Rim> rimsOf(const Object& o) {
    if (o.type != ShapeType::Cylinder) return {};
    const double h = 0.5 * double(o.height);
    return {{dvec3(0.0, -h, 0.0), double(o.radius)}, {dvec3(0.0, h, 0.0), double(o.radius)}};
}

std::vector<dvec3> rimSupport(const dvec3& centre, const dvec3& axis, double radius,
                              const dvec3& normal) {
    const dvec3 across = -normal + glm::dot(normal, axis) * axis;  // −normal, in the rim's plane
    const double len = glm::length(across);
    if (len > kFlat) {  // the lowest point first, then the rest of its quarter turns
        const dvec3 down = across / len, side = glm::cross(axis, down);
        return {centre + radius * down, centre + radius * side, centre - radius * side,
                centre - radius * down};
    }
    // Flat: four points a quarter turn apart, from any direction across the axis.
    const dvec3 u =
        glm::normalize(glm::cross(axis, std::abs(axis.x) < 0.57 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
    const dvec3 v = glm::cross(axis, u);
    return {centre + radius * u, centre + radius * v, centre - radius * u, centre - radius * v};
}

bool rimLiesFlat(const dvec3& axis, const dvec3& normal) {
    return glm::length(-normal + glm::dot(normal, axis) * axis) <= kFlat;
}

}  // namespace mb
