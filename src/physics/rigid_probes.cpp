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

// A cone with every face moved in by r, as sdf.cpp's rounding draws it (its `inset`): the base
// radius r1 at y0, the top r2 at y1; where the slant passes a pointed top, it ends at its apex.
struct InsetCone {
    double y0, y1, r1, r2;
};

InsetCone insetCone(const SdfObject& o, double r) {
    const double h = double(o.height), slope = (double(o.radius) - double(o.top)) / h;
    const double side = r * std::sqrt(1.0 + slope * slope);
    const double r1 = double(o.radius) - slope * r - side, r2 = double(o.top) + slope * r - side;
    const double y0 = -0.5 * h + r;
    if (r2 >= 0.0) return {y0, 0.5 * h - r, r1, r2};
    return {y0, y0 + (h - 2.0 * r) * r1 / (r1 - r2), r1, 0.0};
}

}  // namespace

Elongation elongationOf(const dvec3& semi) {
    const int along = semi.y >= semi.x && semi.y >= semi.z ? 1 : semi.x >= semi.z ? 0 : 2;
    return {along, semi[along], std::min(semi[(along + 1) % 3], semi[(along + 2) % 3])};
}

std::vector<Probe> probesOf(const SdfObject& o) {
    std::vector<Probe> probes;
    const double h = 0.5 * double(o.height), round = double(o.round);
    switch (o.type) {
        case ShapeType::Sphere:
            probes.push_back({dvec3(0.0), double(o.radius)});
            break;
        case ShapeType::Box:
            probes = boxProbes(dvec3(o.size) - round);
            for (Probe& p : probes) p.radius = round;
            break;
        case ShapeType::Capsule:  // the segment, every quarter: exact against flat faces at its
                                  // ends
            for (int k = 0; k <= 4; ++k)
                probes.push_back({dvec3(0.0, h * (k / 2.0 - 1.0), 0.0), double(o.radius)});
            break;
        case ShapeType::Cylinder:  // the rims alone, through rimSupport
            break;
        case ShapeType::Cone:  // the rims, and a pointed top's apex
            if (const InsetCone c = insetCone(o, round); c.r2 <= 0.0)
                probes.push_back({dvec3(0.0, c.y1, 0.0), round});
            break;
        case ShapeType::Torus:  // its core circle, a rim swept by the tube
            break;
        case ShapeType::Ellipsoid:  // its support point, against each surface; a long one's tips
            if (const Elongation e = elongationOf(dvec3(o.size)); e.elongated())
                for (const double end : {-1.0, 1.0}) {
                    dvec3 centre(0.0);
                    centre[e.along] = end * (e.c - e.tip());
                    probes.push_back({centre, e.tip()});
                }
            break;
    }
    return probes;
}

std::vector<Probe> probesOf(const Object& o) { return probesOf(makeSdfObject(o)); }

std::vector<Rim> rimsOf(const SdfObject& o) {
    // A torus is its core circle swept by its tube: a rim, whose support point rolls round it,
    // where 24 fixed points rolled as a polygon (on its edge at 2 m/s it slowed to 1 m/s in 2 s).
    if (o.type == ShapeType::Torus)
        return {{dvec3(0.0), double(o.radius), dvec3(0, 1, 0), double(o.minor), 0, true}};
    const double round = double(o.round);
    if (o.type == ShapeType::Cylinder) {
        const double h = 0.5 * double(o.height) - round, r = double(o.radius) - round;
        return {{dvec3(0.0, -h, 0.0), r, dvec3(0, 1, 0), round},
                {dvec3(0.0, h, 0.0), r, dvec3(0, 1, 0), round}};
    }
    if (o.type != ShapeType::Cone) return {};
    const InsetCone c = insetCone(o, round);
    std::vector<Rim> rims = {{dvec3(0.0, c.y0, 0.0), c.r1, dvec3(0, 1, 0), round}};
    if (c.r2 > 0.0) rims.push_back({dvec3(0.0, c.y1, 0.0), c.r2, dvec3(0, 1, 0), round});
    return rims;
}

std::vector<Rim> rimsOf(const Object& o) { return rimsOf(makeSdfObject(o)); }

void rimBasis(const Rim& rim, dvec3* u, dvec3* v) {
    *u = glm::normalize(
        glm::cross(rim.axis, std::abs(rim.axis.x) < 0.57 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
    *v = glm::cross(rim.axis, *u);
}

dvec3 rimPoint(const Rim& rim, double k) {
    dvec3 u, v;
    rimBasis(rim, &u, &v);
    const double phi = 2.0 * M_PI * k / kRimPoints;
    return rim.centre + rim.radius * (std::cos(phi) * u + std::sin(phi) * v);
}

// The same points as rimPoint's, with the plane and the turns' cosines found once.
std::array<dvec3, kRimPoints> rimPoints(const Rim& rim) {
    static const std::array<std::array<double, 2>, kRimPoints> kTurns = [] {
        std::array<std::array<double, 2>, kRimPoints> turns;
        for (int k = 0; k < kRimPoints; ++k) {
            const double phi = 2.0 * M_PI * double(k) / kRimPoints;
            turns[size_t(k)] = {std::cos(phi), std::sin(phi)};
        }
        return turns;
    }();
    dvec3 u, v;
    rimBasis(rim, &u, &v);
    std::array<dvec3, kRimPoints> points;
    for (size_t k = 0; k < points.size(); ++k)
        points[k] = rim.centre + rim.radius * (kTurns[k][0] * u + kTurns[k][1] * v);
    return points;
}

// None where the rims meet (a rounding of half the height): its rims' spheres are all of it.
std::optional<Side> sideOf(const SdfObject& o) {
    const double round = double(o.round);
    if (o.type == ShapeType::Cylinder) {
        const double h = 0.5 * double(o.height) - round, r = double(o.radius);
        if (!(h > 0.0)) return std::nullopt;
        return Side{dvec3(0.0, -h, 0.0), dvec3(0.0, h, 0.0), {r, r}};
    }
    if (o.type != ShapeType::Cone) return std::nullopt;
    const InsetCone c = insetCone(o, round);
    if (!(c.y1 > c.y0)) return std::nullopt;
    const double slope = (c.r1 - c.r2) / (c.y1 - c.y0),
                 cosine = 1.0 / std::sqrt(1.0 + slope * slope);
    return Side{dvec3(0.0, c.y0, 0.0),
                dvec3(0.0, c.y1, 0.0),
                {c.r1 * cosine + round, c.r2 * cosine + round}};
}

std::vector<Side> ellipsoidSides(const dvec3& semi) {
    const Elongation e = elongationOf(semi);
    if (!e.elongated()) return {};
    const double end = e.c - e.tip();  // where the inscribed spheres' centres end
    auto radius = [&](double along) {  // of the sphere inscribed about that point of the axis
        return e.a * std::sqrt(std::max(0.0, 1.0 - along * along / (e.c * e.c - e.a * e.a)));
    };
    std::vector<Side> sides;
    for (const double sign : {1.0, -1.0})
        for (int k = 0; k < kEllipsoidChords; ++k) {
            Side s{dvec3(0.0), dvec3(0.0), {0.0, 0.0}};
            for (int i = 0; i < 2; ++i) {
                const double along = end * std::sin(0.5 * M_PI * (k + i) / kEllipsoidChords);
                (i ? s.to : s.from)[e.along] = sign * along;
                s.radius[i] = radius(along);
            }
            s.open[0] = sign > 0.0 || k > 0;  // each joint probed by one chord
            sides.push_back(s);
        }
    return sides;
}

// The inscribed sphere of radius ρ touches a cone's side along its normal, tilted from `across`
// towards the narrow end by α, where sin α is how fast ρ falls along the axis.
dvec3 sideSurfacePoint(const Side& s, double t, const dvec3& across) {
    const dvec3 axis = s.to - s.from;
    const double length = glm::length(axis);
    const double sine = length > 0.0 ? (s.radius[0] - s.radius[1]) / length : 0.0;
    const dvec3 normal = std::sqrt(std::max(0.0, 1.0 - sine * sine)) * across +
                         (length > 0.0 ? sine / length : 0.0) * axis;
    return glm::mix(s.from, s.to, t) + sideRadius(s, t) * normal;
}

dvec3 ellipsoidSupport(const dvec3& a, const dvec3& dir) {
    const dvec3 scaled = a * dir;
    const double len = glm::length(scaled);
    return len > 0.0 ? a * scaled / len : dvec3(0.0);
}

std::array<dvec3, 4> rimSupport(const dvec3& centre, const dvec3& axis, double radius,
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

double rimInset(const Rim& rim, const dvec3& axis, const dvec3& face) {
    if (rim.tube > 0.0 || std::abs(glm::dot(axis, face)) < 0.5) return 0.0;
    return 0.1 * rim.radius;
}

bool rimLiesFlat(const dvec3& axis, const dvec3& normal) {
    return glm::length(-normal + glm::dot(normal, axis) * axis) <= kFlat;
}

}  // namespace mb
