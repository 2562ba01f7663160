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
//
// A group of one object is that shape's distance. A carved or blended group (max(a, −b), a smooth
// minimum) is only a bound: 1-Lipschitz, |f| <= the distance, zero on the drawn surface, but over
// an opening it reads the gap to the subtractor's cap, a lid that is not drawn. For such a group
// the bound only culls: where it says a sphere may touch, the gap is taken from the nearest drawn
// point (measure()), which the bound itself proves in the common case and a search finds
// otherwise. A sphere across an opening narrower than itself gets a contact for each side of the
// rim the search met in reach, not one.
#pragma once

#include "marchbox/scene/scene.h"
#include "marchbox/scene/sdf.h"
#include "rigid_probes.h"
#include "surface.h"

#include <array>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

namespace mb {

// A point of a static object's own surface that its group's drawn surface holds: a corner, an
// edge's midpoint, a point of a rim, or the centre of a sphere of the surface. Probed against a
// body's shape, as a body's probes are against the statics: a face lands on a post's top, on a
// dome's crown, or past a table's edge, where none of its own points touch.
struct StaticProbe {
    glm::dvec3 centre;  // world
    double radius;      // of the sphere about it that the static surface holds
    int feature;        // StaticHit::feature of the group it lies on
    int key = 0;        // its contact's among its feature's: probes, then sides, then rings
};

// A static cylinder's or cone's side (rigid_probes.h's Side, in the world) that its group's drawn
// surface holds: a box's edge laid across a static pipe meets no point of the pipe's rims.
struct StaticSide {
    Side side;
    int feature;  // StaticHit::feature of the group it lies on
    int key = 0;  // its first contact's (kSideIds of them) among its feature's
};

// A static torus's core (rigid_probes.h's Rim, in the world) that its group's drawn surface holds
// all round: a bar laid across a static ring crosses its tube between the core's fixed points.
struct StaticRing {
    Rim core;
    int feature;
    int key = 0;  // its first contact's (kRimPoints of them) among its feature's
};

struct StaticHit {
    // 0 the ground plane, g + 1 static group g; g + 1 + G·k (G groups) for the contacts with a
    // carved group that its search found, k = 1 the nearest, k > 1 the others in reach (query()).
    int feature;
    double separation;     // centre distance minus radius; negative when overlapping
    glm::dvec3 normal;     // unit, out of the static surface towards the sphere
    bool creased = false;  // the normal's samples straddled an edge or corner (isCreased)
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
    // Its signed distance at p alone: its group's SDF, a bound where the group is loose.
    double surfaceDistance(int feature, const glm::dvec3& p);
    // Whether a feature is a static group's surface: neither the ground nor one of the further
    // contacts that a carved group's search found (StaticHit::feature).
    bool isGroupSurface(int feature) const {
        return feature >= 1 && feature <= int(groups_.size());
    }

    // How far a sphere at `centre` moving by `move` ends from surface `feature`, less the linear
    // guess s + n·move from hit(): the surface's curvature along the move, 0 on a flat face,
    // < 0 where the surface curves towards the sphere (a bowl). For contacts that follow a curve.
    double bend(int feature, const glm::dvec3& centre, const glm::dvec3& normal,
                const glm::dvec3& move);
    // The largest bend() that float noise alone gives over a move of length `move`: the normal's
    // noise times the move, and the distances' rounding at the size of the group's objects.
    double bendNoise(int feature, double move) const;

    // How far the centre may travel from `from` along unit `dir`, up to `length`, before it comes
    // within `radius` of a static surface (conservative advancement on the SDF; where the bound of
    // a carved group stops it, only a drawn surface within reach holds it).
    double cast(const glm::dvec3& from, const glm::dvec3& dir, double length, double radius);

    double distance(const glm::dvec3& p);  // to the nearest static surface, ground included

    // The friction and restitution of a surface (StaticHit::feature): the world's for the
    // ground, a group's first object's (its own or the world's) for a group, which is one
    // surface however many objects shape it.
    const Surface& surface(int feature) const { return surfaces_[size_t(feature)]; }

    // The top-level static objects' probes on the drawn surface, sorted by centre.x for near().
    const std::vector<StaticProbe>& probes() const { return probes_; }
    const std::vector<StaticSide>& sides() const { return sides_; }
    const std::vector<StaticRing>& rings() const { return rings_; }
    // The probes whose spheres come within `reach` of a sphere at `centre` of radius `radius`,
    // by x; the caller tests the rest of the reach.
    std::span<const StaticProbe> near(const glm::dvec3& centre, double radius, double reach) const;

private:
    struct Group {
        int first, last;     // objects [first, last) of statics_
        double size = 0.0;   // largest bounding radius of its objects, m
        bool loose = false;  // its SDF is a bound, not a distance (CSG, a blend, a bound shape)
        std::vector<int> sdfGroups;  // the scene groups that shape it, indices in sdfGroups_
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
    void localise(const Group& g, const glm::dvec3& origin, SceneSdf& into, bool append);
    // Every group within `reach` of `centre`, moved to `origin` into path_, in chain order; their
    // indices in near_. Whether one of them is loose.
    bool localiseNear(const glm::dvec3& origin, const glm::dvec3& centre, double reach);
    double groundDistance(const glm::dvec3& p) const;
    double localDistance() const;  // to the localised group, from the local origin
    // The group localised at the centre, `d` its localDistance(); a loose group's surface is
    // searched for within radius + reach (asker: see measure()).
    StaticHit localHit(int group, double radius, double d, double size, double reach, int asker);

    // The drawn surface of a loose group, localised in local_; points are local. `side` = ±1, the
    // sign of f at the query point q, so that side·f > 0 at q and side·f <= 0 past the surface.
    struct Measure {
        double distance;        // signed, to the nearest drawn point; negative inside
        glm::dvec3 normal;      // unit, out of the surface towards the point
        bool within = true;     // false: nothing drawn within the limit; distance is ±limit
        bool searched = false;  // the bound alone did not say
    };
    // From q, where the bound reads d and `n` is its unit gradient (or a guess of it), searched
    // within `limit` of q. `size`: the group's, which scales the roundings. `asker`: a body, whose
    // last search near q starts the next; kRecall, a contact's follow-up within the step, which
    // walks from the nearest point a search found near q instead of searching again; kAnyone.
    static constexpr int kRecall = -1, kAnyone = -2;
    Measure measure(const glm::dvec3& q, double d, const glm::dvec3& n, double limit, double size,
                    int asker);
    // The nearest drawn point to q within limit, where clear = side·f(q) > 0, and the normal
    // there; false if none. hint: `point` holds a drawn point found near q before, to start from.
    // The drawn points about q that it ended on stay in ends_, nearest first.
    bool nearest(const glm::dvec3& q, double side, double clear, const glm::dvec3& n, double limit,
                 double size, bool hint, glm::dvec3& point, double& distance, glm::dvec3& normal);
    struct Touch {         // where a ray from q first meets the drawn surface
        double t;          // along the ray
        glm::dvec3 dir;    // the ray's unit direction
        glm::dvec3 point;  // q + t·dir, on the far side by at most `tolerance`
    };
    bool touch(const glm::dvec3& q, const glm::dvec3& dir, double side, double clear, double limit,
               double least, double tolerance, Touch& out) const;
    // Newton's steps from x onto f = 0, a drawn point, with `out` the unit gradient of side·f
    // there; false where they do not arrive.
    enum class Haste {
        None,  // to the end of its steps
        Cell,  // from a cell's centre where side·f is `known`: forward differences, and giving
               // up once |f| fails to fall by a tenth in a step, as over a lid
    };
    bool project(glm::dvec3& x, double side, double h, double tolerance, double proof,
                 glm::dvec3& out, Haste haste, double known) const;
    // From a drawn point at `distance` from q to a nearer one, the nearest it can reach.
    double walk(const glm::dvec3& q, double side, double h, double tolerance, double proof,
                glm::dvec3& point, double distance) const;
    double field(const glm::dvec3& x) const;                   // the localised group's f
    glm::dvec3 gradient(const glm::dvec3& x, double h) const;  // its gradient, step h
    glm::dvec3 slope(const glm::dvec3& x, double h) const;     // unit
    // A group's signed distance from world p: a loose one's drawn surface searched within limit.
    double groupDistance(int group, const glm::dvec3& p, double limit);
    // The nearest drawn surface from world p, the ground included, searched within limit.
    double drawnDistance(const glm::dvec3& p, double limit);

    struct Clearance {  // a lower bound on every group's distance from `at`
        glm::dvec3 at{0.0};
        double distance = -1.0;  // none yet
    };
    std::vector<Clearance> clearance_;  // per body given to query()
    std::vector<SdfObject> statics_;    // `group`: an index in sdfGroups_
    std::vector<SdfGroup> sdfGroups_;   // the static top-level groups and their subgroups
    std::vector<int> slot_;             // per sdfGroups_: its place in its Group's sdfGroups
    std::vector<Bound> bounds_;         // per static object; a member's is its top group's
    std::vector<char> adds_;            // per static object: whether lowerBound counts it
    void chainGroups(const World& world, const std::vector<Surface>& own);
    std::vector<Group> groups_;
    std::vector<Surface> surfaces_;  // per feature: the ground, then each group, again per k
    int groupOf(int feature) const { return (feature - 1) % int(groups_.size()); }

    void findProbes();  // probes_, sides_ and rings_, once the groups are known
    std::vector<StaticProbe> probes_;
    std::vector<StaticSide> sides_;
    std::vector<StaticRing> rings_;
    double probeRadius_ = 0.0;  // the largest probe's
    bool ground_ = true;
    double floor_ = 0.0;
    SceneSdf local_;       // scratch: one group moved to a local origin
    int localGroup_ = -1;  // which, and where to
    glm::dvec3 localOrigin_{0.0};
    SceneSdf path_;          // scratch: the groups along a sweep, moved to its start
    std::vector<int> near_;  // the groups in path_
    struct Cell {            // of the search: a cube about `centre`
        glm::dvec3 centre;
        double half, lower;  // half its side; its distance from the query point
        int level, order;
    };
    std::vector<Cell> cells_;  // scratch: the search's cells, a heap
    struct Seed {              // a drawn point to walk from
        double distance;
        glm::dvec3 point;
        bool walked;  // already the end of a walk
    };
    std::vector<Seed> seeds_;  // scratch
    std::vector<Seed> ends_;   // scratch: where walks ended
    static constexpr int kKeptEnds = 5;
    struct Recall {  // a search's answer, in the world
        int group = -1, asker = kAnyone;
        double side = 0.0;
        glm::dvec3 at{0.0};                          // asked from
        std::array<glm::dvec3, kKeptEnds> points{};  // the ends it kept, nearest first
        std::array<double, kKeptEnds> distances{};
        int count = 0;
        double limit = 0.0;
        Measure measure{0.0, glm::dvec3(0.0), false};
    };
    std::array<Recall, 32> recalls_{};  // the latest, replaced in turn
    int nextRecall_ = 0;
};

}  // namespace mb
