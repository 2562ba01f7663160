// static_collider.h — what a dynamic sphere sees of the static scene: the ground plane
// and the static objects' CSG chain, through the SDF mirror (marchbox/scene/sdf.h).
//
// The chain is split into groups whose union is the whole: the objects up to the last one that
// is not a sharp union form one group (a subtract or intersect changes everything before it);
// each later sharp-union object is a group of its own. A sphere gets one contact per group it
// is near, so it can rest in a corner between two boxes, or in a hole carved out of one.
//
// mapObjects works in float world coordinates, which at 1e5 m resolve only 8 mm. Every query
// here first moves the group to a local origin at the query point, in double, so the float
// evaluation sees small numbers and keeps its relative precision.
#pragma once

#include "marchbox/scene/scene.h"
#include "marchbox/scene/sdf.h"
#include "surface.h"

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace mb {

struct StaticHit {
    int feature;        // 0 the ground plane, g + 1 static group g
    double separation;  // centre distance minus radius; negative when overlapping
    glm::dvec3 normal;  // unit, out of the static surface towards the sphere
};

class StaticCollider {
public:
    explicit StaticCollider(const Scene& scene);  // the non-dynamic objects and the ground

    // Every surface within `reach` of the sphere's surface. `body` names the sphere from one call
    // to the next: how far its groups were when last measured spares most calls measuring again.
    // `size`: the body's size, where its radius is no measure of it (a corner has radius 0): the
    // normal's difference step scales with the larger of the two.
    void query(int body, const glm::dvec3& centre, double radius, double reach,
               std::vector<StaticHit>& out, double size = 0.0);

    // One surface (StaticHit::feature, not the ground) seen from a sphere at `centre`.
    StaticHit hit(int feature, const glm::dvec3& centre, double radius);

    // How far a sphere at `centre` moving by `move` ends from surface `feature`, less the linear
    // guess s + n·move from hit(): the surface's curvature along the move, 0 on a flat face,
    // < 0 where the surface curves towards the sphere (a bowl). For contacts that follow a curve.
    double bend(int feature, const glm::dvec3& centre, const glm::dvec3& normal,
                const glm::dvec3& move);
    // The largest bend() that float noise alone gives over a move of length `move`: the normal's
    // noise times the move, and the distances' rounding at the size of the group's objects.
    double bendNoise(int feature, double move) const;

    // How far the centre may travel from `from` along unit `dir`, up to `length`, before it comes
    // within `radius` of a static surface (conservative advancement on the SDF).
    double cast(const glm::dvec3& from, const glm::dvec3& dir, double length, double radius);

    double distance(const glm::dvec3& p);  // to the nearest static surface, ground included

    // The friction and restitution of a surface (StaticHit::feature): the world's for the
    // ground, a group's first object's (its own or the world's) for a group, which is one
    // surface however many objects shape it.
    const Surface& surface(int feature) const { return surfaces_[size_t(feature)]; }

private:
    struct Group {
        int first, last;    // objects [first, last) of statics_
        double size = 0.0;  // largest bounding radius of its objects, m
    };
    struct Bound {  // an object's shape lies within `less` of its box or centre
        glm::dvec3 centre;
        glm::dmat3 toLocal;
        glm::dvec3 half;  // the box's half extents; 0 for a shape bound by a sphere
        double less;      // the distance's shortfall: the sphere's radius, or rounding
        double grow;      // what a smooth union adds, k/4
        bool box;
        bool rotated;  // toLocal is not the identity (an upright box needs no product)
    };
    static Bound boundOf(const SdfObject& o);
    double lowerBound(const Group& g, const glm::dvec3& p) const;  // <= distance to the group
    void localise(const Group& g, const glm::dvec3& origin, bool append);
    // Every group within `reach` of `centre`, moved to `origin`, in chain order.
    void localiseNear(const glm::dvec3& origin, const glm::dvec3& centre, double reach);
    double groundDistance(const glm::dvec3& p) const;
    double localDistance() const;  // to the localised group, from the local origin
    // The group localised at the centre, `d` its localDistance().
    StaticHit localHit(int group, double radius, double d, double size = 0.0) const;

    struct Clearance {  // a lower bound on every group's distance from `at`
        glm::dvec3 at{0.0};
        double distance = -1.0;  // none yet
    };
    std::vector<Clearance> clearance_;  // per body given to query()
    std::vector<SdfObject> statics_;
    std::vector<Bound> bounds_;  // per static object
    std::vector<Group> groups_;
    std::vector<Surface> surfaces_;  // per feature: the ground, then each group
    bool ground_ = true;
    double floor_ = 0.0;
    SceneSdf local_;  // scratch: groups moved to a local origin
};

}  // namespace mb
