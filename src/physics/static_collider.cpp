// static_collider.cpp — contacts and sweeps against the static scene's SDF.
#include "static_collider.h"

#include "rigid_probes.h"

#include "tetra_gradient.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>

namespace mb {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kMaxCastSteps = 64;

// The search for a loose group's drawn surface (StaticCollider::measure). Lengths are scaled by
// the search's limit and the group's size, so that they stay above the float noise of f.
constexpr double kProof = 1e-4;       // × scale: how far past f = 0 the other side is looked for
constexpr int kLevels = 3;            // the cube about the point split 3 times: cells of limit/8
constexpr int kRaySteps = 96;         // sphere-tracing steps of one ray
constexpr int kRefineSteps = 40;      // regula falsi steps on a ray's sign change
constexpr int kWalkSteps = 12;        // steps of a walk to the nearest point
constexpr int kNewtonSteps = 6;       // of one projection onto f = 0
constexpr double kOtherFace = 0.985;  // normals more than 10° apart belong to two faces
constexpr double kApart = 0.25;       // × limit: seeds further apart are walked from both
constexpr double kRecallNear = 0.5;   // × limit: a recalled point seeds a walk from so near

bool sharpUnion(const SdfObject& o) { return o.op == CsgOp::Union && o.blend <= 0.0f; }

}  // namespace

// The static scene: top-level objects and groups that do not move, with every member of a
// static group, in tree order; a group's indices move to sdfGroups_.
StaticCollider::StaticCollider(const Scene& scene)
    : ground_(scene.world.ground), floor_(scene.world.floor) {
    const SceneSdf all = makeSceneSdf(scene);
    auto still = [&](int top, bool dynamic) {
        return top < 0 ? !dynamic : !scene.groups[size_t(top)].dynamic();
    };
    std::vector<int> index(scene.groups.size(), -1);
    std::vector<int> before(scene.objects.size() + 1, 0);  // static objects before each one
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        before[i + 1] = before[i] + int(still(topGroupOf(scene, o), o.dynamic()));
    }
    for (size_t g = 0; g < scene.groups.size(); ++g) {
        int top = int(g);
        while (scene.groups[size_t(top)].parent >= 0) top = scene.groups[size_t(top)].parent;
        if (!still(top, true)) continue;
        SdfGroup s = all.groups[g];
        s.parent = s.parent < 0 ? -1 : index[size_t(s.parent)];
        s.first = before[size_t(s.first)];
        s.last = before[size_t(s.last)];
        index[g] = int(sdfGroups_.size());
        sdfGroups_.push_back(s);
    }
    std::vector<Surface> own;  // per static object: its top-level object's or group's
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        const int top = topGroupOf(scene, o);
        if (!still(top, o.dynamic())) continue;
        SdfObject s = all.objects[i];
        s.group = o.group < 0 ? -1 : index[size_t(o.group)];
        statics_.push_back(s);
        if (top < 0) {
            own.push_back(surfaceOf(o, scene.world));
        } else {
            const mb::Group& g = scene.groups[size_t(top)];
            own.push_back({double(g.friction.value_or(scene.world.friction)),
                           double(g.restitution.value_or(scene.world.restitution))});
        }
    }
    chainGroups(scene.world, own);
    local_.ground = false;
    path_.ground = false;
    findProbes();
}

// Each top-level static object's probes, and sixteen points of each rim (a static rim does not
// roll), kept where its group's drawn surface holds them: a corner carved away, or inside
// another object of its group, touches nothing. Members of static groups are left to the
// bodies' own probes.
void StaticCollider::findProbes() {
    // A probe is checked against its whole group: a chain of thousands of objects before a
    // subtract, checked probe by probe, took a minute to set up. Such a group keeps to the
    // bodies' own probes.
    constexpr int kMostObjects = 64;
    for (size_t g = 0; g < groups_.size(); ++g) {
        if (groups_[g].last - groups_[g].first > kMostObjects) continue;
        for (int i = groups_[g].first; i < groups_[g].last; ++i) {
            const SdfObject& o = statics_[size_t(i)];
            if (o.group >= 0) continue;
            const glm::dmat3 toWorld = glm::transpose(glm::dmat3(o.toLocal));
            std::vector<Probe> local = probesOf(o);
            for (const Rim& rim : rimsOf(o))
                for (const glm::dvec3& p : rimPoints(rim)) local.push_back({p, rim.tube});
            if (o.type == ShapeType::Ellipsoid)
                for (int k = 0; k < 6; ++k) {
                    glm::dvec3 tip(0.0);
                    tip[k % 3] = (k < 3 ? 1.0 : -1.0) * double(o.size[k % 3]);
                    local.push_back({tip, 0.0});
                }
            const double tol = 1e-5 * std::max(double(o.bound), 1.0);
            // Its own group's surface: another group's solid it lies in holds no body there.
            auto held = [&](const glm::dvec3& centre, double radius) {
                const double d = groupDistance(int(g), centre, radius + 2.0 * groups_[g].size);
                return d <= -radius + tol && d >= -radius - std::max(tol, 0.25 * radius);
            };
            for (const Probe& p : local) {
                const glm::dvec3 centre = glm::dvec3(o.pos) + toWorld * p.local;
                if (!held(centre, p.radius)) continue;
                probes_.push_back({centre, p.radius, int(g) + 1});
                probeRadius_ = std::max(probeRadius_, p.radius);
            }
            if (std::optional<Side> side = sideOf(o)) {  // held where its middle sphere is
                side->from = glm::dvec3(o.pos) + toWorld * side->from;
                side->to = glm::dvec3(o.pos) + toWorld * side->to;
                if (held(0.5 * (side->from + side->to), sideRadius(*side, 0.5)))
                    sides_.push_back({*side, int(g) + 1});
            }
            if (o.type != ShapeType::Torus) continue;
            Rim core = rimsOf(o)[0];  // held where all its points are
            core.centre = glm::dvec3(o.pos) + toWorld * core.centre;
            core.axis = toWorld * core.axis;
            const std::array<glm::dvec3, kRimPoints> points = rimPoints(core);
            if (std::all_of(points.begin(), points.end(),
                            [&](const glm::dvec3& p) { return held(p, core.tube); }))
                rings_.push_back({core, int(g) + 1});
        }
    }
    std::sort(probes_.begin(), probes_.end(),
              [](const StaticProbe& a, const StaticProbe& b) { return a.centre.x < b.centre.x; });
    // Each feature's contacts are one manifold, keyed apart: numbered through the whole scene,
    // two probes of one floor of tiles (ten to each x, sorted by x) came 127 keys apart, which
    // the probe byte wraps, and shared a warm start.
    std::vector<int> next(surfaces_.size(), 0);
    auto take = [&next](int feature, int keys) {
        const int first = next[size_t(feature)];
        next[size_t(feature)] += keys;
        return first;
    };
    for (StaticProbe& p : probes_) p.key = take(p.feature, 1);
    for (StaticSide& s : sides_) s.key = take(s.feature, kSideIds);
    for (StaticRing& r : rings_) r.key = take(r.feature, kRimPoints);
}

std::span<const StaticProbe> StaticCollider::near(const glm::dvec3& centre, double radius,
                                                  double reach) const {
    const double most = radius + reach + probeRadius_;
    const auto x = [](const StaticProbe& p, double v) { return p.centre.x < v; };
    const auto begin = std::lower_bound(probes_.begin(), probes_.end(), centre.x - most, x);
    const auto end = std::lower_bound(begin, probes_.end(), centre.x + most, x);
    return {begin, end};
}

// The chain is split into groups whose union is the whole: the records up to the last one that
// is not a sharp union, then each later one on its own, a scene group being one record.
void StaticCollider::chainGroups(const World& world, const std::vector<Surface>& own) {
    struct Record {
        int first, last;
        bool sharp;
    };
    std::vector<Record> records;
    for (int i = 0; i < int(statics_.size());) {
        const SdfObject& o = statics_[size_t(i)];
        if (o.group < 0) {
            records.push_back({i, i + 1, sharpUnion(o)});
            ++i;
            continue;
        }
        int top = o.group;
        while (sdfGroups_[size_t(top)].parent >= 0) top = sdfGroups_[size_t(top)].parent;
        const SdfGroup& g = sdfGroups_[size_t(top)];
        records.push_back({g.first, g.last, g.op == CsgOp::Union && g.blend <= 0.0f});
        i = g.last;
    }
    int chainEnd = 0;  // one past the last record that is not a sharp union
    for (const Record& r : records)
        if (!r.sharp) chainEnd = r.last;
    if (chainEnd > 0) groups_.push_back({0, chainEnd, 0.0, false, {}});
    for (const Record& r : records)
        if (r.first >= chainEnd) groups_.push_back({r.first, r.last, 0.0, false, {}});
    slot_.assign(sdfGroups_.size(), -1);
    for (Group& g : groups_) {
        for (int i = g.first; i < g.last; ++i) g.size = std::max(g.size, double(statics_[i].bound));
        g.loose = g.last - g.first > 1 || !exactShape(statics_[size_t(g.first)]);
        for (size_t s = 0; s < sdfGroups_.size(); ++s) {
            const SdfGroup& sg = sdfGroups_[s];
            if (sg.first < g.first || sg.last > g.last || sg.first == sg.last) continue;
            slot_[s] = int(g.sdfGroups.size());
            g.sdfGroups.push_back(int(s));
            g.size = std::max(g.size, double(sg.bound));
            g.loose = g.loose || glm::any(sg.mirror);
        }
    }
    // A top-level object adds material by its own op; a group's first member carries its top
    // group's op and bounding sphere for them all, and the others add nothing of their own.
    for (size_t i = 0; i < statics_.size(); ++i) {
        int top = statics_[i].group;
        if (top < 0) {
            bounds_.push_back(boundOf(statics_[i]));
            adds_.push_back(statics_[i].op == CsgOp::Union);
            continue;
        }
        while (sdfGroups_[size_t(top)].parent >= 0) top = sdfGroups_[size_t(top)].parent;
        const SdfGroup& g = sdfGroups_[size_t(top)];
        bounds_.push_back({glm::dvec3(g.pos), glm::dmat3(1.0), glm::dvec3(0.0), double(g.bound),
                           0.25 * g.blend, false, false});
        adds_.push_back(g.first == int(i) && g.op == CsgOp::Union);
    }
    surfaces_.push_back({world.friction, world.restitution});
    for (int end = 0; end <= kKeptEnds; ++end)  // a group's own, then its ends' (StaticHit)
        for (const Group& g : groups_) surfaces_.push_back(own[size_t(g.first)]);
}

// Subtract and intersect only remove material and a smooth union of radius k adds at most k/4,
// so the group lies inside its union members grown by k/4: a box is its own bound (the walls of a
// well, where a bounding sphere would reach every sphere in the well), any other shape its
// bounding sphere. In double, once: the query asks for every sphere, every step.
StaticCollider::Bound StaticCollider::boundOf(const SdfObject& o) {
    // The float rotation may place a box a few ulps off: keep the bound below the true distance.
    constexpr double kRounding = 1e-5;
    const bool box = o.type == ShapeType::Box;
    return {glm::dvec3(o.pos),
            glm::dmat3(o.toLocal),
            box ? glm::dvec3(o.size) : glm::dvec3(0.0),
            box ? kRounding * o.bound : double(o.bound),
            0.25 * o.blend,
            box,
            o.toLocal != glm::mat3(1.0f)};
}

double StaticCollider::lowerBound(const Group& g, const glm::dvec3& p) const {
    double bound = kInf;
    for (int i = g.first; i < g.last; ++i) {
        const Bound& b = bounds_[size_t(i)];
        if (!adds_[size_t(i)]) continue;
        const glm::dvec3 d = p - b.centre;
        const glm::dvec3 local = b.rotated ? b.toLocal * d : d;  // the same |components| either way
        // glm::abs and glm::max branch per axis; std::abs and std::max are an instruction each.
        const glm::dvec3 outside{std::max(std::abs(local.x) - b.half.x, 0.0),
                                 std::max(std::abs(local.y) - b.half.y, 0.0),
                                 std::max(std::abs(local.z) - b.half.z, 0.0)};
        const double distance = b.box ? glm::length(outside) : glm::length(d);
        bound = std::min(bound, distance - b.less - b.grow);
    }
    return bound;
}

void StaticCollider::localise(const Group& g, const glm::dvec3& origin, SceneSdf& into,
                              bool append) {
    if (!append) into.objects.clear();
    if (&into == &local_) {
        localGroup_ = int(&g - groups_.data());
        localOrigin_ = origin;
    }
    if (!append) into.groups.clear();
    const int objects = int(into.objects.size()), groups = int(into.groups.size());
    for (int i = g.first; i < g.last; ++i) {
        SdfObject o = statics_[i];
        o.pos = glm::vec3(glm::dvec3(o.pos) - origin);
        if (o.group >= 0) o.group = groups + slot_[size_t(o.group)];
        into.objects.push_back(o);
    }
    for (int s : g.sdfGroups) {
        SdfGroup sg = sdfGroups_[size_t(s)];
        sg.pos = glm::vec3(glm::dvec3(sg.pos) - origin);
        if (sg.parent >= 0) sg.parent = groups + slot_[size_t(sg.parent)];
        sg.first += objects - g.first;
        sg.last += objects - g.first;
        into.groups.push_back(sg);
    }
}

bool StaticCollider::localiseNear(const glm::dvec3& origin, const glm::dvec3& centre,
                                  double reach) {
    path_.objects.clear();
    near_.clear();
    bool loose = false;
    for (size_t g = 0; g < groups_.size(); ++g)
        if (lowerBound(groups_[g], centre) < reach) {
            localise(groups_[g], origin, path_, true);
            near_.push_back(int(g));
            loose = loose || groups_[g].loose;
        }
    return loose;
}

double StaticCollider::groundDistance(const glm::dvec3& p) const {
    return ground_ ? p.y - floor_ : kInf;
}

// A distance bound is 1-Lipschitz: the groups are at least clearance − |move| from the sphere
// once it has moved. While that leaves them out of reach, none is measured; the slack is far
// above the rounding of the bounds, so a group left out would have been left out measured.
void StaticCollider::query(int body, const glm::dvec3& centre, double radius, double reach,
                           std::vector<StaticHit>& out, double size) {
    out.clear();
    if (groundDistance(centre) - radius < reach)
        out.push_back({0, groundDistance(centre) - radius, glm::dvec3(0, 1, 0)});
    if (size_t(body) >= clearance_.size()) clearance_.resize(size_t(body) + 1);
    Clearance& clear = clearance_[size_t(body)];
    const double slack = 1e-9 * (glm::length(centre) + std::abs(clear.distance) + 1.0);
    if (clear.distance >= 0.0 &&
        clear.distance - glm::length(centre - clear.at) - radius >= reach + slack)
        return;
    clear = {centre, kInf};
    for (size_t g = 0; g < groups_.size(); ++g) {
        const double bound = lowerBound(groups_[g], centre);
        clear.distance = std::min(clear.distance, bound);
        if (bound - radius >= reach) continue;
        localise(groups_[g], centre, local_, false);
        // The distance alone rules most groups out (a pile's far walls); only a surface in
        // reach pays for the four samples of its normal. A loose group's bound may be nearer
        // than what is drawn: its hit says.
        const double d = localDistance();
        if (d - radius >= reach) continue;
        const StaticHit hit = localHit(int(g), radius, d, size, reach, body);
        if (hit.separation < reach) out.push_back(hit);
        // A sphere across an opening narrower than itself meets it all round: each other end
        // of the search in reach is a contact too, so that the rim holds it from every side.
        if (hit.feature > int(g) + 1 && hit.separation < reach)
            for (size_t k = 1; k < ends_.size(); ++k) {
                const double separation = ends_[k].distance - radius;
                if (separation >= reach || !(ends_[k].distance > 0.0)) continue;
                const glm::dvec3 n = (glm::dvec3(0.0) - ends_[k].point) / ends_[k].distance;
                out.push_back(
                    {int(g) + 1 + int(groups_.size()) * int(k + 1), separation, d < 0.0 ? -n : n});
            }
    }
}

// A contact followed through the substeps stays within the step's margin, well inside a
// radius, of where it was found: the search reaches a radius past the sphere, and walks from the
// nearest point that the step's query found.
StaticHit StaticCollider::hit(int feature, const glm::dvec3& centre, double radius) {
    localise(groups_[size_t(groupOf(feature))], centre, local_, false);
    return localHit(groupOf(feature), radius, localDistance(), 0.0, radius, kRecall);
}

double StaticCollider::surfaceDistance(int feature, const glm::dvec3& p) {
    localise(groups_[size_t(groupOf(feature))], p, local_, false);
    return localDistance();
}

double StaticCollider::localDistance() const { return mapObjects(local_, glm::vec3(0.0f)).d; }

StaticHit StaticCollider::localHit(int group, double radius, double d, double size, double reach,
                                   int asker) {
    // The normal from four samples about the sphere's centre (tetra_gradient.h); h scales with
    // the sphere so it stays above the float noise of the local distances.
    const float h = float(1e-3 * (std::max(radius, size) + std::abs(d)));
    const glm::dvec3 n = tetraGradient(
        [this](const glm::vec3& q) { return mapObjects(local_, q).d; }, glm::vec3(0.0f), h);
    const double len = glm::length(n);
    const glm::dvec3 normal = len > 0.0 ? n / len : glm::dvec3(0, 1, 0);
    const Group& g = groups_[size_t(group)];
    if (!g.loose) return {group + 1, d - radius, normal, isCreased(len, double(h))};
    const Measure m = measure(glm::dvec3(0.0), d, normal, radius + reach, g.size, asker);
    // Nothing drawn in reach: out of it, whatever the rounding of (radius + reach) − radius.
    return {group + 1 + (m.searched ? int(groups_.size()) : 0),
            m.within ? m.distance - radius : std::max(m.distance - radius, reach), m.normal};
}

// Both distances come from the same localised group, so the float noise of the far-away
// coordinates cancels: what is left is the curvature term ½·moveᵀ·H·move of the SDF's Taylor
// series (an SDF has no curvature along its gradient, so only the tangential move counts).
//
// A loose group's bound is followed so only where the certificate (measure()) proves it the
// distance at both ends, as on a bowl carved into a box. The contacts that a search found (a
// rim's edge, a hole's) keep their normals for the step, each a contact of its own.
double StaticCollider::bend(int feature, const glm::dvec3& centre, const glm::dvec3& normal,
                            const glm::dvec3& move) {
    const Group& g = groups_[size_t(groupOf(feature))];
    localise(g, centre, local_, false);
    const double here = mapObjects(local_, glm::vec3(0.0f)).d;
    const double there = mapObjects(local_, glm::vec3(move)).d;
    if (!g.loose) return there - here - glm::dot(normal, move);
    const double proof = kProof * (std::abs(here) + glm::length(move) + g.size);
    auto exact = [&](const glm::dvec3& q, double d) {
        return (d < 0.0 ? -1.0 : 1.0) * field(q - (d + (d < 0.0 ? -proof : proof)) * normal) <= 0.0;
    };
    return exact(glm::dvec3(0.0), here) && exact(move, there)
               ? there - here - glm::dot(normal, move)
               : 0.0;
}

// Measured on a tilted 40 m box: 0.5 ulp of its size; the tetrahedral normal is good to ~4e-5.
double StaticCollider::bendNoise(int feature, double move) const {
    constexpr double kNormalNoise = 1e-4, kUlps = 4.0 * std::numeric_limits<float>::epsilon();
    return kNormalNoise * move + kUlps * groups_[size_t(groupOf(feature))].size;
}

double StaticCollider::cast(const glm::dvec3& from, const glm::dvec3& dir, double length,
                            double radius) {
    const bool loose = localiseNear(from, from + 0.5 * length * dir, 0.5 * length + radius);
    const double tolerance = 1e-3 * radius;
    double t = 0.0;
    // Sphere tracing: an SDF is 1-Lipschitz, so stepping by (distance − radius) never carries the
    // centre closer than `radius` to any surface. A capped march stops short, which is safe.
    // Where a loose group's bound stops it, the drawn surfaces within a radius say whether
    // something is there; if not, the march goes on by the clearance they leave.
    for (int i = 0; i < kMaxCastSteps; ++i) {
        const double objects =
            path_.objects.empty() ? kInf : double(mapObjects(path_, glm::vec3(dir * t)).d);
        double d = std::min(objects, groundDistance(from + dir * t)) - radius;
        if (d < tolerance) {
            if (!loose) return t;
            d = drawnDistance(from + dir * t, 2.0 * radius) - radius;
            if (d < tolerance) return t;
        }
        t += d;
        if (t >= length) return length;
    }
    return t;
}

// A loose group is searched within its bound's reading and twice its size: carving only raises
// the bound (max(a, −b) >= a), and the drawn points left of a union member lie within its
// bounding sphere, at most twice the size from the member's nearest point.
double StaticCollider::distance(const glm::dvec3& p) {
    if (!localiseNear(p, p, kInf)) {
        const double objects =
            path_.objects.empty() ? kInf : double(mapObjects(path_, glm::vec3(0)).d);
        return std::min(objects, groundDistance(p));
    }
    double nearest = groundDistance(p);
    const std::vector<int> groups = near_;
    for (int g : groups) {
        localise(groups_[size_t(g)], p, local_, false);
        const double limit = std::abs(localDistance()) + 2.0 * groups_[size_t(g)].size;
        nearest = std::min(nearest, groupDistance(g, p, limit));
    }
    return nearest;
}

double StaticCollider::groupDistance(int group, const glm::dvec3& p, double limit) {
    const Group& g = groups_[size_t(group)];
    localise(g, p, local_, false);
    const double d = localDistance();
    if (!g.loose || std::abs(d) >= limit) return d;
    const double h = 1e-3 * (limit + g.size);
    return measure(glm::dvec3(0.0), d, slope(glm::dvec3(0.0), h), limit, g.size, kAnyone).distance;
}

double StaticCollider::drawnDistance(const glm::dvec3& p, double limit) {
    double nearest = groundDistance(p);
    for (size_t g = 0; g < groups_.size(); ++g)
        if (lowerBound(groups_[g], p) < std::min(nearest, limit))
            nearest = std::min(nearest, groupDistance(int(g), p, limit));
    return nearest;
}

//-----------------------------------------------------------------------------
// [SECTION] The drawn surface of a loose group
//-----------------------------------------------------------------------------
double StaticCollider::field(const glm::dvec3& x) const {
    return double(mapObjects(local_, glm::vec3(x)).d);
}

// Central differences along the axes. At a crease f = max(a, b) through x they give (a + b)/2,
// in the plane of both normals; the tetrahedron's four samples lean along the crease.
glm::dvec3 StaticCollider::gradient(const glm::dvec3& x, double h) const {
    glm::dvec3 n;
    for (int k = 0; k < 3; ++k) {
        glm::dvec3 e(0.0);
        e[k] = h;
        n[k] = (field(x + e) - field(x - e)) / (2.0 * h);
    }
    return n;
}

glm::dvec3 StaticCollider::slope(const glm::dvec3& x, double h) const {
    const glm::dvec3 n = gradient(x, h);
    const double len = glm::length(n);
    return len > 0.0 ? n / len : glm::dvec3(0, 1, 0);
}

// With g = side·f (positive at q, where it is `clear`): sphere tracing from q along `dir`, each
// step g (which the bound allows) but at least `least`, to the first point where g <= 0: a point
// of the drawn surface's other side, since f's zero set is the drawn surface. Then regula falsi
// (Illinois) on the sign change, to `tolerance`; the point kept is on the far side.
bool StaticCollider::touch(const glm::dvec3& q, const glm::dvec3& dir, double side, double clear,
                           double limit, double least, double tolerance, Touch& out) const {
    double ta = 0.0, ga = clear, t = clear, tb = 0.0, gb = 0.0;
    bool crossed = false;
    for (int i = 0; i < kRaySteps && !crossed; ++i) {
        const bool last = t >= limit;
        if (last) t = limit;
        const double g = side * field(q + t * dir);
        if (g <= 0.0) {
            tb = t;
            gb = g;
            crossed = true;
        } else if (last) {
            return false;
        } else {
            ta = t;
            ga = g;
            t += std::max(g, least);
        }
    }
    if (!crossed) return false;
    int kept = 0;  // which end the last two steps moved: +1 a, −1 b
    for (int i = 0; i < kRefineSteps && tb - ta > tolerance; ++i) {
        double m = ta + (tb - ta) * ga / (ga - gb);
        if (!(m > ta && m < tb)) m = 0.5 * (ta + tb);
        const double g = side * field(q + m * dir);
        if (g <= 0.0) {
            tb = m;
            gb = g;
            if (kept == -1) ga *= 0.5;
            kept = -1;
        } else {
            ta = m;
            ga = g;
            if (kept == 1) gb *= 0.5;
            kept = 1;
        }
    }
    out.t = tb;
    out.dir = dir;
    out.point = q + tb * dir;
    return true;
}

// Where the certificate fails the bound is loose here (over an opening, by the cap of what
// carved it). Newton's projection from q would swing between the rim's plane and the cap, so:
// 1. A ray from q down the gradient; the first point of the other side it meets is drawn.
// 2. A cube of side 2·limit about q is split best-first, nearest cells first. A cell whose bound
//    at its centre exceeds its half-diagonal holds no surface (1-Lipschitz); so does one inside
//    the ball of radius |d| about q, or one beyond the nearest drawn point found so far. A centre
//    on the other side sends a ray from q towards it; a finest cell (limit/8) that may hold
//    surface is projected onto f = 0 by Newton's steps, which fail over a lid. Each drawn point
//    found prunes the cells beyond it.
// 3. From the nearest point found, and from the nearest one well apart from it (a hole's other
//    edge), a walk to the nearest drawn point.
bool StaticCollider::nearest(const glm::dvec3& q, double side, double clear, const glm::dvec3& n,
                             double limit, double size, bool hint, glm::dvec3& point,
                             double& distance, glm::dvec3& normal) {
    const double least = 1e-3 * limit, tolerance = 1e-7 * (limit + size);
    const double normalStep = 1e-4 * (limit + size), proof = kProof * (limit + size);
    double upper = limit;
    seeds_.clear();
    if (hint) {  // a drawn point found near q before: walked from, it bounds the search at once
        const double d = walk(q, side, normalStep, tolerance, proof, point, glm::length(point - q));
        if (d < upper) {
            seeds_.push_back({d, point, true});
            upper = d;
        }
    }
    auto ray = [&](const glm::dvec3& towards) {
        const double len = glm::length(towards);
        Touch t;
        if (len > 0.0 && touch(q, towards / len, side, clear, upper, least, least, t)) {
            seeds_.push_back({t.t, t.point, false});
            upper = std::min(upper, t.t);
        }
    };
    // 1. Down the gradient.
    ray(-side * n);
    // 2. The cells.
    int order = 0;
    cells_.clear();
    auto later = [](const Cell& a, const Cell& b) {
        return a.lower != b.lower ? a.lower > b.lower : a.order > b.order;
    };
    auto push = [&](const glm::dvec3& c, double half, int level) {
        const glm::dvec3 off = glm::abs(c - q);
        const double lower = glm::length(glm::max(off - half, 0.0));
        if (lower >= upper || glm::length(off + half) <= clear) return;
        cells_.push_back({c, half, lower, level, order++});
        std::push_heap(cells_.begin(), cells_.end(), later);
    };
    push(q, limit, 0);
    while (!cells_.empty()) {
        std::pop_heap(cells_.begin(), cells_.end(), later);
        const Cell cell = cells_.back();
        cells_.pop_back();
        if (cell.lower >= upper) break;
        const double g = cell.level == 0 ? clear : side * field(cell.centre);
        if (g > cell.half * std::sqrt(3.0)) continue;
        if (g <= 0.0) ray(cell.centre - q);  // meets f = 0 before the centre, maybe before upper
        if (cell.level < kLevels) {
            const double half = 0.5 * cell.half;
            for (int k = 0; k < 8; ++k)
                push(
                    cell.centre + half * glm::dvec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1),
                    half, cell.level + 1);
        } else if (g > 0.0) {
            glm::dvec3 x = cell.centre, out;
            if (project(x, side, normalStep, tolerance, proof, out, Haste::Cell, g)) {
                const double dist = glm::length(x - q);
                if (dist < upper) {
                    seeds_.push_back({dist, x, false});
                    upper = dist;
                }
            }
        }
    }
    if (seeds_.empty()) return false;
    // 3. The walks.
    std::stable_sort(seeds_.begin(), seeds_.end(),
                     [](const Seed& a, const Seed& b) { return a.distance < b.distance; });
    ends_.clear();
    glm::dvec3 first = seeds_[0].point;
    ends_.push_back({seeds_[0].walked
                         ? seeds_[0].distance
                         : walk(q, side, normalStep, tolerance, proof, first, seeds_[0].distance),
                     first, true});
    for (size_t i = 1; i < seeds_.size(); ++i)
        if (glm::length(seeds_[i].point - seeds_[0].point) > kApart * limit) {
            glm::dvec3 there = seeds_[i].point;
            ends_.push_back({seeds_[i].walked ? seeds_[i].distance
                                              : walk(q, side, normalStep, tolerance, proof, there,
                                                     seeds_[i].distance),
                             there, true});
            break;
        }
    // 4. Across an opening narrower than the sphere (a ball on a cup's mouth, on a square hole)
    // the nearest points lie all round it. The bound's gradient there is the opening's axis:
    // rays from q turned about it by quarter turns find the other sides.
    const glm::dvec3 towards = glm::normalize(first - q), axis = -side * n;
    const glm::dvec3 across = towards - glm::dot(towards, axis) * axis;
    if (glm::length(across) > 0.1) {
        const glm::dvec3 side1 = glm::normalize(across), side2 = glm::cross(axis, side1);
        const glm::dvec3 turns[3] = {side2, -side1, -side2};
        for (const glm::dvec3& turn : turns) {
            Touch t;
            const glm::dvec3 dir = glm::dot(towards, axis) * axis + glm::length(across) * turn;
            if (!touch(q, dir, side, clear, limit, least, least, t)) continue;
            glm::dvec3 there = t.point;
            ends_.push_back({walk(q, side, normalStep, tolerance, proof, there, t.t), there, true});
        }
    }
    // Keep the ends once each, nearest first: each is a contact of its own (query()).
    std::stable_sort(ends_.begin(), ends_.end(),
                     [](const Seed& a, const Seed& b) { return a.distance < b.distance; });
    size_t kept = 0;
    for (const Seed& e : ends_) {
        bool again = false;
        for (size_t k = 0; k < kept && !again; ++k)
            again = glm::length(ends_[k].point - e.point) <= kApart * limit;
        if (!again && kept < size_t(kKeptEnds)) ends_[kept++] = e;
    }
    ends_.resize(kept);
    point = ends_[0].point;
    distance = ends_[0].distance;
    normal = side * (q - point) / distance;
    return true;
}

// From a drawn point, steps to the foot of q on its tangent plane, projected back onto f = 0; a
// step that comes no nearer is halved. Where the foot lies over an opening beside a face (a rim's
// edge), the projection lands on that face's edge. Once a step has met a second face, a step
// along the edge the two make (across both normals), to the point of that line nearest q, walks
// along a curved edge (a rim) where the foot is too far over the opening to land on it.
double StaticCollider::walk(const glm::dvec3& q, double side, double h, double tolerance,
                            double proof, glm::dvec3& point, double distance) const {
    glm::dvec3 out, start = point;  // out of the other side, at point
    if (project(start, side, h, tolerance, proof, out, Haste::None, 0.0)) {
        point = start;  // a seed is on the other side, by up to a ray's last step
        distance = glm::length(point - q);
    } else {
        out = side * slope(point, h);
    }
    glm::dvec3 otherOut(0.0);  // the other face's, beyond an edge
    bool other = false, arrived = false;
    double gain = kInf;  // of the last step taken
    // Whether x, projected, is nearer; then it is the point.
    auto tryPoint = [&](glm::dvec3 x) {
        glm::dvec3 there;
        if (!project(x, side, h, tolerance, proof, there, Haste::None, 0.0)) return false;
        const double dist = glm::length(x - q);
        const bool turned = glm::dot(there, out) < kOtherFace;
        if (turned) {
            otherOut = dist < distance ? out : there;
            other = true;
        }
        if (dist >= distance) return false;
        gain = distance - dist;
        arrived = gain <= tolerance;
        point = x;
        out = there;
        distance = dist;
        return true;
    };
    double step = 1.0;
    for (int i = 0; i < kWalkSteps && !arrived; ++i) {
        const glm::dvec3 foot = q - glm::dot(out, q - point) * out;
        if (glm::length(foot - point) <= tolerance) break;
        if (tryPoint(point + step * (foot - point))) {
            step = 1.0;
            continue;
        }
        if (other) {
            // At an edge `out` leans between both faces: the foot on the other face's plane.
            const glm::dvec3 onOther = q - glm::dot(otherOut, q - point) * otherOut;
            if (glm::length(onOther - point) > tolerance && tryPoint(onOther)) continue;
            const glm::dvec3 edge = glm::cross(out, otherOut);
            const double len = glm::length(edge);
            if (len > 1e-6) {
                const glm::dvec3 along = point + glm::dot(q - point, edge) / (len * len) * edge;
                if (glm::length(along - point) > tolerance && tryPoint(along)) continue;
            }
        }
        // Halving helps a walk still far out, whose foot overshoots on a curved face; one that
        // has nearly arrived (a last gain of under a thousandth) is at the nearest point.
        if (gain < 1e-3 * distance || (step *= 0.5) < 0.125) break;
    }
    return distance;
}

// Newton's steps onto f = 0 from x, each at most twice the bound (a bound's gradient is at most
// 1, so the surface is at least |f| away; a step much longer than that crossed a ridge, the lid's
// or a crease's). A point where |f| falls within `tolerance` is a drawn point only if the other
// side lies just past it: a lid's positive minimum has none. `out`: the unit gradient of side·f
// there. Over a lid the steps swing between two planes and |f| stays: a hasty projection gives
// up there at once.
bool StaticCollider::project(glm::dvec3& x, double side, double h, double tolerance, double proof,
                             glm::dvec3& out, Haste haste, double known) const {
    const bool hasty = haste == Haste::Cell;
    double g = hasty ? known : side * field(x);
    for (int k = 0; k < kNewtonSteps; ++k) {
        glm::dvec3 grad;
        if (hasty) {
            for (int a = 0; a < 3; ++a) {
                glm::dvec3 e(0.0);
                e[a] = h;
                grad[a] = (side * field(x + e) - g) / h;
            }
        } else {
            grad = side * gradient(x, h);
        }
        const double len2 = glm::dot(grad, grad);
        if (!(len2 > 0.0)) return false;
        if (std::abs(g) <= tolerance) {
            out = grad / std::sqrt(len2);
            return side * field(x - proof * out) <= 0.0;
        }
        glm::dvec3 move = -g / len2 * grad;
        const double len = glm::length(move), most = 2.0 * std::abs(g);
        if (len > most) move *= most / len;
        x += move;
        const double next = side * field(x);
        if (hasty && std::abs(next) > 0.9 * std::abs(g)) return false;
        g = next;
    }
    return false;
}

// The certificate: where the segment from q to q − (d + δ)·n ends on the other side of f = 0, a
// drawn point lies within |d| + δ of q (f is continuous and zero only on the drawn surface); and
// since |f| <= the distance, none lies nearer than |d|. Then d is the distance, to δ, and it is
// kept as it is, normal and all: a ball resting on the cup's floor costs one sample more. Any
// unit n will do for the proof; the gradient makes it hold wherever the bound is exact. Else the
// search (nearest()), whose normal points from the nearest drawn point to q.
StaticCollider::Measure StaticCollider::measure(const glm::dvec3& q, double d, const glm::dvec3& n,
                                                double limit, double size, int asker) {
    const bool recall = asker == kRecall;
    const double side = d < 0.0 ? -1.0 : 1.0, clear = std::abs(d);
    if (clear >= limit) return {d, n, false};
    const double proof = kProof * (limit + size);
    if (side * field(q - (d + side * proof) * n) <= 0.0) return {d, n};
    const glm::dvec3 at = localOrigin_ + q;
    const Recall* near = nullptr;
    for (const Recall& r : recalls_) {
        if (r.group != localGroup_ || r.side != side) continue;
        const double from = glm::length(at - r.at);
        if (from == 0.0) {  // asked again (a contact's bend after its query): the same answer
            ends_.clear();
            for (int k = 0; k < r.count; ++k)
                ends_.push_back({r.distances[size_t(k)], r.points[size_t(k)] - localOrigin_, true});
            if (r.measure.within && std::abs(r.measure.distance) < limit) return r.measure;
            if (!r.measure.within && limit <= r.limit) return {side * limit, n, false, true};
        }
        if (r.measure.within && from <= kRecallNear * limit && (recall || r.asker == asker) &&
            (!near || from < glm::length(at - near->at)))
            near = &r;
    }
    glm::dvec3 point = near ? near->points[0] - localOrigin_ : glm::dvec3(0.0), normal;
    double distance;
    bool found;
    if (recall && near) {
        const double tolerance = 1e-7 * (limit + size), h = 1e-4 * (limit + size);
        distance = walk(q, side, h, tolerance, proof, point, glm::length(point - q));
        found = distance < limit;
        ends_.assign(1, {distance, point, true});
        normal = side * (q - point) / distance;
    } else {
        found = nearest(q, side, clear, n, limit, size, near != nullptr, point, distance, normal);
    }
    const Measure m = found ? Measure{side * std::max(distance, clear), normal, true, true}
                            : Measure{side * limit, n, false, true};
    if (!recall || !near) {  // a search's answer, for the step's follow-ups to start from
        Recall& r = recalls_[size_t(nextRecall_)];
        r = {localGroup_, asker, side, at, {}, {}, 0, limit, m};
        if (found)
            for (const Seed& e : ends_) {
                r.points[size_t(r.count)] = localOrigin_ + e.point;
                r.distances[size_t(r.count++)] = e.distance;
            }
        nextRecall_ = (nextRecall_ + 1) % int(recalls_.size());
    }
    return m;
}

}  // namespace mb
