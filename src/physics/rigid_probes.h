// rigid_probes.h — where a turning body can touch something: points of its shape, each the
// centre of a sphere (radius 0 for a corner) that the shape sweeps or holds.
//
// A probe at c with radius ρ meets a surface of signed distance f where f(c) < ρ, at the point
// c − ρ·∇f(c), with separation f(c) − ρ. That is exact for each shape's own geometry: a box's
// corners and edge points (ρ = 0), a capsule's segment (ρ = its radius), a torus's core circle
// (ρ = its tube), a sphere's centre, a pointed cone's apex. A cylinder's and a cone's rims are
// probed, against each surface, at the rim's lowest point along that surface's normal
// (rimSupport), so that a rolling cylinder touches exactly where a real one does; a rim lying
// flat on it, at four; their sides, where a surface crosses them between the rims (Side). A
// rounded shape's corners and rims are its inset shape's, each holding a sphere of the rounding's
// radius. An ellipsoid has no fixed probes: it touches at its support point along the surface's
// normal (ellipsoidSupport), found against each surface in turn.
#pragma once

#include "marchbox/scene/scene.h"
#include "marchbox/scene/sdf.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

namespace mb {

struct Probe {
    glm::dvec3 local;  // centre, in the body's frame
    double radius;     // of the sphere about it that the shape holds
    int part = 0;      // the body's part it lies on (RigidBody::parts; a group's member)
    // The shape holds the sphere only in part (a group's member carved or hollowed): a contact
    // counts only where its point on the sphere lies on the shape's surface.
    bool partial = false;
};

// In the shape's own frame (sdObjectLocal's).
std::vector<Probe> probesOf(const SdfObject& o);
std::vector<Probe> probesOf(const Object& o);

// A cylinder's or a cone's rims: centre and axis (the shape's frame), the rim circle's radius,
// and the radius of the sphere it sweeps (a rounded edge's; 0 for a sharp one); none for other
// shapes. They carry no fixed probes: a rolling rim would meet each as the corner of a polygon.
struct Rim {
    glm::dvec3 centre;
    double radius;
    glm::dvec3 axis{0.0, 1.0, 0.0};  // unit, normal to the rim's plane
    double tube = 0.0;
    int part = 0;       // as a probe's
    bool core = false;  // a torus's core: searched along against every shape (leastAlongRim)
};
std::vector<Rim> rimsOf(const SdfObject& o);
std::vector<Rim> rimsOf(const Object& o);

// A rim's contact keys: its four support points (rimSupport) and, against a group's shape, whose
// concave parts one support point may miss (a rim inside a cup's mouth touches its wall on
// either side), one for each of sixteen points a sixteenth of a turn apart (rimPoint), where
// the shape comes nearest.
constexpr int kRimPoints = 16;
constexpr int kRimIds = 4 + kRimPoints;
// The rim's plane: unit u and v across its axis, the frame of every point of it.
void rimBasis(const Rim& rim, glm::dvec3* u, glm::dvec3* v);
glm::dvec3 rimPoint(const Rim& rim, double k);  // in the rim's frame, k sixteenths of a turn
std::array<glm::dvec3, kRimPoints> rimPoints(const Rim& rim);  // rimPoint at k = 0, 1, … 15

// A cylinder's or a cone's side: the surface that spheres centred on its axis sweep, from `from`
// to `to` (its rims' centres), of radius `radius[0]` to `radius[1]`, each touching the side all
// round (a cone's inscribed spheres, r·cos α). A surface that crosses the side between the rims,
// as another cylinder lying across it does or a box's edge, meets neither rim: a column of
// cylinders laid crosswise sank through itself. The side is probed by the sphere where the axis
// comes nearest such a surface (nearestOnSide).
struct Side {
    glm::dvec3 from, to;
    double radius[2];
    int part = 0;                   // as a probe's
    bool partial = false;           // as a probe's: a tube's outer side holds no sphere on its axis
    bool open[2] = {false, false};  // an end with no rim (a table's leg under its top)
};
inline double sideRadius(const Side& s, double t) {
    return s.radius[0] + t * (s.radius[1] - s.radius[0]);
}
// The radius about the side's middle that holds its spheres.
inline double sideBound(const Side& s) {
    return 0.5 * glm::length(s.to - s.from) + std::max(s.radius[0], s.radius[1]);
}

std::optional<Side> sideOf(const SdfObject& o);  // in its own frame; none for other shapes
// An ellipsoid's longest semi-axis c (along its frame's axis `along`) and the least of the
// other two, a. One at least 1.5 times as long as it is thick is elongated: its tips are probed
// by the spheres of their own curvature (radius tip(), inside the surface), for its support
// point at the step's start is one tip, and a rod turning within the step brought the other
// one down through the ground.
struct Elongation {
    int along;
    double c, a;
    bool elongated() const { return c >= 1.5 * a; }
    double tip() const { return a * a / c; }
};
Elongation elongationOf(const glm::dvec3& semi);
// An elongated ellipsoid's sides (none for another): the spheres inscribed on its longest axis,
// whose radius falls from a at the centre to tip() where the tip's sphere takes over; each half
// as kEllipsoidChords chords of that curve, spaced evenly in the angle of an ellipse's point
// (within a tenth of a of the curve, less for a thicker one). Its support point meets a face,
// not an edge that crosses its length (a rod laid across a wall's top fell through it), nor two
// rails under it: the sides' search finds those. Each joint is probed by the chord beyond it.
constexpr int kEllipsoidChords = 4;
std::vector<Side> ellipsoidSides(const glm::dvec3& semi);
// A side's contact keys: its nearest point, or the two ends of a level stretch (nearestOnSide).
constexpr int kSideIds = 2;
// Where the side's sphere at t touches it, in the direction `across` (unit, normal to the axis).
glm::dvec3 sideSurfacePoint(const Side& s, double t, const glm::dvec3& across);

// Where along a side (in the world) F(t) = f(point) − radius(t) is least: one t in (0, 1), found
// by golden sections to kSideStep; or, where F stays within `level` of its least along a stretch
// (a side lying across a box's face), the two ends of that stretch: a bar laid on two pipes
// rocked on one point a pipe, crept along them and never slept. A curved surface crossing the
// side comes within `level` over a stretch too, whose ends then let it in up to `level` past its
// nearest point. For f convex along the axis (`scan` 0), none where F is least at an end, whose
// rim meets the surface there (F does not fall by `noise`, f's rounding, a kSideStep in from it:
// a side along a face never probes). A carved group's f is not convex (along a table's leg
// under another table, the whole table's rose from one end, then fell below 0 near the other):
// the least of `scan` samples between the ends brackets the search, or names the end. An `open`
// end, with no rim, is probed itself where F is least there. None where the side lies out of
// `reach` by f's values at the ends.
constexpr double kSideStep = 1e-3;  // of the axis
// Of the side's mean radius: F within `level` this far to one side of its least is a stretch.
constexpr double kLevelSpan = 0.25;
struct SideTouch {
    double t[2];
    int count = 0;
    double least = 0.0;  // F there
};
template <class Distance>
SideTouch nearestOnSide(Distance f, const Side& side, double reach, double noise, double level,
                        int scan) {
    auto F = [&](double t) { return f(glm::mix(side.from, side.to, t)) - sideRadius(side, t); };
    const double f0 = F(0.0), f1 = F(1.0);
    // F changes no faster than the axis's length and the radii's difference together.
    const double steepest =
        glm::length(side.to - side.from) + std::abs(side.radius[1] - side.radius[0]);
    if (0.5 * (f0 + f1 - steepest) >= reach) return {};
    auto atEnd = [&](int end) {
        return side.open[end] ? SideTouch{{double(end), double(end)}, 1, end ? f1 : f0}
                              : SideTouch{};
    };
    double lo = kSideStep, hi = 1.0 - kSideStep;
    if (scan == 0) {
        const double in0 = F(kSideStep), in1 = F(1.0 - kSideStep);
        const bool least0 = in0 >= f0 - noise, least1 = in1 >= f1 - noise;
        if (least0 || least1) return atEnd(least0 ? 0 : 1);
        // A convex F lies above each end's secant, extended: where the two lines cross, F's
        // least is no lower. Most of the leasts between the ends lie out of reach so.
        const double s0 = (in0 - f0) / kSideStep, s1 = (f1 - in1) / kSideStep;
        const double cross = (f1 - s1 - f0) / (s0 - s1);
        if (f0 + s0 * cross >= reach) return {};
    } else {
        int best = 0;
        double least = f0;
        for (int i = 1; i <= scan + 1; ++i) {
            const double value = i == scan + 1 ? f1 : F(double(i) / (scan + 1));
            if (value < least) least = value, best = i;
        }
        // Least at an end, but falling inwards from it: least between it and the next sample.
        if (best == 0 && F(kSideStep) >= f0 - noise) return atEnd(0);
        if (best == scan + 1 && F(1.0 - kSideStep) >= f1 - noise) return atEnd(1);
        lo = std::max(lo, double(best - 1) / (scan + 1));
        hi = std::min(hi, double(best + 1) / (scan + 1));
    }
    const double gold = 0.5 * (std::sqrt(5.0) - 1.0);
    double x1 = hi - gold * (hi - lo), x2 = lo + gold * (hi - lo);
    double F1 = F(x1), F2 = F(x2);
    while (hi - lo > kSideStep) {
        if (F1 < F2) {
            hi = x2, x2 = x1, F2 = F1;
            x1 = hi - gold * (hi - lo), F1 = F(x1);
        } else {
            lo = x1, x1 = x2, F1 = F2;
            x2 = lo + gold * (hi - lo), F2 = F(x2);
        }
    }
    const double t = 0.5 * (lo + hi), least = std::min(F1, F2) + level;
    const double span = kLevelSpan * (side.radius[0] + side.radius[1]) / std::max(steepest, 1e-300);
    if (F(std::max(t - span, 0.0)) > least && F(std::min(t + span, 1.0)) > least)
        return {{t, t}, 1, least - level};
    // Level: each end of the stretch where F ≤ least, by bisection between t and the side's end.
    auto edge = [&](double inside, double outside) {
        while (std::abs(outside - inside) > kSideStep) {
            const double mid = 0.5 * (inside + outside);
            (F(mid) <= least ? inside : outside) = mid;
        }
        return inside;
    };
    return {{edge(t, 0.0), edge(t, 1.0)}, 2, least - level};
}

// Where a distance f comes nearest a rim (of a body at `pos`, turned by `orient`) along it, in
// as many places as it has leasts: each of its sixteen points lower than the one before it and
// no higher than the one after, its tube within `reach`, moved by the parabola through the
// three. `found(point, k)` for each, k the point's index.
template <class Distance, class Found>
void leastAlongRim(const Rim& rim, const glm::dvec3& pos, const glm::dquat& orient, Distance f,
                   double reach, Found found) {
    const std::array<glm::dvec3, kRimPoints> points = rimPoints(rim);
    double d[kRimPoints];
    for (int k = 0; k < kRimPoints; ++k) d[k] = f(pos + orient * points[size_t(k)]);
    for (int k = 0; k < kRimPoints; ++k) {
        const double before = d[(k + kRimPoints - 1) % kRimPoints], after = d[(k + 1) % kRimPoints];
        if (d[k] > before || d[k] >= after || d[k] - rim.tube >= reach) continue;
        const double bend = before - 2.0 * d[k] + after;
        const double shift =
            bend > 0.0 ? std::clamp(0.5 * (before - after) / bend, -0.5, 0.5) : 0.0;
        found(pos + orient * rimPoint(rim, double(k) + shift), k);
    }
}

// The point of an ellipsoid (semi-axes, its own frame) furthest along unit `dir`: A²·d / |A·d|.
glm::dvec3 ellipsoidSupport(const glm::dvec3& semiAxes, const glm::dvec3& dir);

// Four points of the rim (world centre, world unit axis) a quarter turn apart. The first is the
// one furthest along −normal, where the rim first meets a surface facing `normal`; the others
// meet it too when the rim is tilted less than the contact's reach, so that a disc landing
// nearly flat stands on them rather than rocking from one lowest point to the next (at 1/30 s
// a pile pressed one 10 cm into the ground that way). Where the rim lies flat on the surface
// (rimLiesFlat: within kFlat of parallel, 0.6°) the four come from any direction across the
// axis, so a standing cylinder rests on a square.
constexpr double kFlat = 0.01;
std::array<glm::dvec3, 4> rimSupport(const glm::dvec3& centre, const glm::dvec3& axis,
                                     double radius, const glm::dvec3& normal);
bool rimLiesFlat(const glm::dvec3& axis, const glm::dvec3& normal);

// How far inside a sharp rim its support points look again where one meets a wall across the
// face the rim stands on (`face`, the surface's normal at the rim's centre). Two cylinders of one
// radius stacked have each rim on the other's edge, where the distance inside is the side
// wall's (0), not the face's: every point of the rim met a wall, none held the weight, and a
// column of eight sank through itself in half a second. A tenth of the radius in, the points meet
// the face. None for a rim on its edge (tilted over 60° from the face, a wheel's) or a rounded one.
double rimInset(const Rim& rim, const glm::dvec3& axis, const glm::dvec3& face);

}  // namespace mb
