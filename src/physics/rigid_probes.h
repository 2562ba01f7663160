// rigid_probes.h — where a turning body can touch something: points of its shape, each the
// centre of a sphere (radius 0 for a corner) that the shape sweeps or holds.
//
// A probe at c with radius ρ meets a surface of signed distance f where f(c) < ρ, at the point
// c − ρ·∇f(c), with separation f(c) − ρ. That is exact for each shape's own geometry: a box's
// corners and edge points (ρ = 0), a capsule's segment (ρ = its radius), a torus's core circle
// (ρ = its tube), a sphere's centre, a pointed cone's apex. A cylinder's and a cone's rims are
// probed, against each surface, at the rim's lowest point along that surface's normal
// (rimSupport), so that a rolling cylinder touches exactly where a real one does; a rim lying
// flat on it, at four. A rounded shape's corners and rims are its inset shape's, each holding a
// sphere of the rounding's radius. An ellipsoid has no fixed probes: it touches at its support
// point along the surface's normal (ellipsoidSupport), found against each surface in turn.
#pragma once

#include "marchbox/scene/scene.h"
#include "marchbox/scene/sdf.h"

#include <array>
#include <glm/vec3.hpp>
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
    int part = 0;  // as a probe's
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
