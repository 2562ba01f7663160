// group_body.cpp — a dynamic group's shape, mass properties and probes (group_body.h).
#include "group_body.h"

#include "marchbox/scene/shapes.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace mb {

using glm::dmat3;
using glm::dvec3;

namespace {

bool inside(const Scene& scene, int group, int g) {
    for (; group >= 0; group = scene.groups[size_t(group)].parent)
        if (group == g) return true;
    return false;
}

dmat3 toGroup(const SdfObject& o) { return glm::transpose(dmat3(o.toLocal)); }

dvec3 copyOffset(const SdfGroup& g, int copy) {
    const glm::ivec3 index(copy % g.repeat.x, copy / g.repeat.x % g.repeat.y,
                           copy / (g.repeat.x * g.repeat.y));
    return (dvec3(index) - 0.5 * (dvec3(g.repeat) - 1.0)) * dvec3(g.spacing);
}

// An object's moments in its own frame: closed form, or its SDF integrated.
Moments objectMoments(const SdfObject& o) {
    Moments m;
    if (closedFormMoments(o, &m)) return m;
    return integrateSolid([&](const glm::vec3& p) { return sdObjectLocal(o, p); }, double(o.bound),
                          kIntegrationDepth)
        .value;
}

//-----------------------------------------------------------------------------
// Probes
//-----------------------------------------------------------------------------
// A place on a member (a point, and a direction that goes with it: a rim's axis) and its images
// through the groups that hold it: each mirror's reflections, then each repeat's copies.
struct Feature {
    dvec3 point, axis;
};

constexpr int kMostImages = 512;

void imagesIn(const SceneSdf& sdf, int g, const Feature& f, std::vector<Feature>& out) {
    const SdfGroup& group = sdf.groups[size_t(g)];
    const dmat3 toLocal(group.toLocal), back = glm::transpose(toLocal);
    const dvec3 q = toLocal * (f.point - dvec3(group.pos)), axis = toLocal * f.axis;
    int mirrors = 0;
    for (int a = 0; a < 3; ++a) mirrors += group.mirror[a] ? 1 : 0;
    std::vector<Feature> here;
    for (int signs = 0; signs < 1 << mirrors; ++signs) {
        dvec3 flip(1.0);
        for (int a = 0, bit = 0; a < 3; ++a)
            if (group.mirror[a]) flip[a] = signs >> bit++ & 1 ? -1.0 : 1.0;
        for (int copy = 0; copy < copyCount(group) && int(here.size()) < kMostImages; ++copy)
            here.push_back({dvec3(group.pos) + back * (flip * q + copyOffset(group, copy)),
                            back * (flip * axis)});
    }
    for (const Feature& image : here) {
        if (group.parent < 0) {
            out.push_back(image);
        } else {
            imagesIn(sdf, group.parent, image, out);
        }
        if (int(out.size()) >= kMostImages) return;
    }
}

std::vector<Feature> imagesOf(const SceneSdf& sdf, const SdfObject& o, const Feature& f) {
    std::vector<Feature> out;
    if (o.group < 0) return {f};
    imagesIn(sdf, o.group, f, out);
    return out;
}

struct Candidate {
    dvec3 point;
    double radius;
    int weight;            // lattice points that projected onto it: corners gather most
    int part;              // the member whose surface or solid holds it
    bool partial = false;  // a member's sphere the solid holds only in part (Probe::partial)
};

struct Sampler {
    const GroupShape& shape;
    double tol;  // a point within tol of f = 0 lies on the surface (the float SDF's noise)

    double f(const dvec3& p) const { return double(shape.distance(glm::vec3(p))); }

    // A sphere of radius ρ about p that the solid holds and whose surface it touches: f(p) is
    // −ρ (no more than ρ inside: a bound only underestimates, so the ball is held).
    bool holds(const dvec3& p, double radius) const {
        const double d = f(p);
        return d <= -radius + tol && d >= -radius - std::max(tol, 0.25 * radius);
    }

    dvec3 gradient(const dvec3& p, double step) const {
        dvec3 g;
        for (int k = 0; k < 3; ++k) {
            dvec3 e(0.0);
            e[k] = step;
            g[k] = (f(p + e) - f(p - e)) / (2.0 * step);
        }
        return g;
    }

    // Whether the surface at x (on it) has an edge or corner there: moving a little across the
    // gradient leaves it to first order (a smooth surface only to second, by its curvature).
    // `convex`: where smooth, whether it curves away from the tangent plane (f > 0 around x).
    bool sharp(const dvec3& x, bool* convex) const {
        const double step = 0.01 * shape.bound;
        dvec3 n = gradient(x, 1e-4 * shape.bound);
        const double len = glm::length(n);
        n = len > 0.0 ? n / len : dvec3(0, 1, 0);
        const dvec3 u =
            glm::normalize(glm::cross(n, std::abs(n.x) < 0.57 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
        const dvec3 v = glm::cross(n, u);
        double most = 0.0, mean = 0.0;
        for (int k = 0; k < 8; ++k) {
            const double phi = M_PI / 4.0 * k;
            const double d = f(x + step * (std::cos(phi) * u + std::sin(phi) * v));
            most = std::max(most, std::abs(d));
            mean += d / 8.0;
        }
        *convex = mean > 1e-4 * step;  // a curvature radius under 50 bounds: far above rounding
        return most > 0.05 * step;
    }

    // Newton's steps along the gradient onto f = 0; false where they do not land on it.
    bool project(dvec3& p) const {
        const double step = 1e-4 * shape.bound;
        for (int k = 0; k < 24; ++k) {
            const double d = f(p);
            if (std::abs(d) <= tol) return true;
            const dvec3 g = gradient(p, step);
            const double g2 = glm::dot(g, g);
            if (g2 < 1e-12) return false;
            p -= d * g / g2;
        }
        return std::abs(f(p)) <= tol;
    }
};

// Two rims, in one frame, that are one circle within `tol`.
bool sameCircle(const Rim& a, const Rim& b, double tol) {
    return glm::length(a.centre - b.centre) <= tol && std::abs(a.radius - b.radius) <= tol &&
           a.tube == b.tube && std::abs(glm::dot(a.axis, b.axis)) >= 1.0 - 1e-9;
}

// A side of revolution between flat caps: a cylinder's or a cone's.
bool revolved(const SdfObject& o) { return shapeRow(o.type).revolved && shapeRow(o.type).edges; }

// Distance from p to a rim's circle (and the sphere it sweeps).
double toRim(const Rim& r, const dvec3& p) {
    const dvec3 d = p - r.centre;
    const double along = glm::dot(d, r.axis);
    const double across = glm::length(d - along * r.axis);
    return std::hypot(across - r.radius, along);
}

}  // namespace

GroupShape groupShapeOf(const Scene& scene, int g) {
    Scene local;
    local.world.ground = false;
    const Group& root = scene.groups[size_t(g)];
    const int first = root.first, last = groupEnd(scene, g);
    for (int k = g; k < int(scene.groups.size()) && inside(scene, k, g); ++k) {
        Group c = scene.groups[size_t(k)];
        c.first -= first;
        if (k == g) {
            c.parent = -1;
            c.pos = glm::vec3(0.0f);
            c.rot = glm::vec3(0.0f);
            c.orient = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
        } else {
            c.parent -= g;
        }
        local.groups.push_back(c);
    }
    for (int i = first; i < last; ++i) {
        Object o = scene.objects[size_t(i)];
        o.group -= g;
        local.objects.push_back(o);
    }
    GroupShape shape;
    shape.sdf = makeSceneSdf(local);
    shape.bound = double(shape.sdf.groups[0].bound);
    return shape;
}

Scene withoutBodyMembers(const Scene& scene) {
    Scene out = scene;
    out.objects.clear();
    std::vector<int> kept(scene.objects.size() + 1, 0);  // objects kept before each one
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        const int top = topGroupOf(scene, o);
        const bool member = top >= 0 && scene.groups[size_t(top)].dynamic();
        if (!member) out.objects.push_back(o);
        kept[i + 1] = kept[i] + (member ? 0 : 1);
    }
    for (Group& g : out.groups) g.first = kept[size_t(g.first)];
    return out;
}

namespace {

// One group, unmirrored, whose members all join it by a sharp union: its distance is the least
// of theirs (its copies' too).
bool sharpUnion(const SceneSdf& sdf) {
    if (sdf.groups.size() != 1 || glm::any(sdf.groups[0].mirror)) return false;
    for (const SdfObject& o : sdf.objects)
        if (o.op != CsgOp::Union || o.blend > 0.0f) return false;
    return true;
}

}  // namespace

bool disjointUnionMoments(const GroupShape& shape, Moments* out) {
    const SceneSdf& sdf = shape.sdf;
    const SdfGroup& group = sdf.groups[0];
    if (!sharpUnion(sdf) || copyCount(group) > 64) return false;
    std::vector<OrientedBox> boxes;
    for (int copy = 0; copy < copyCount(group); ++copy)
        for (const SdfObject& o : sdf.objects) {
            boxes.push_back(boxAbout(o));
            boxes.back().centre += copyOffset(group, copy);
        }
    // Faces that meet (a chair's legs under its seat) touch to the floats' rounding.
    const double slack = 1e-6 * shape.bound;
    for (size_t i = 0; i < boxes.size(); ++i)
        for (size_t j = i + 1; j < boxes.size(); ++j)
            if (boxesOverlap(boxes[i], boxes[j], slack)) return false;
    Moments sum;
    for (const SdfObject& o : sdf.objects) {
        const Moments own = objectMoments(o);
        for (int copy = 0; copy < copyCount(group); ++copy)
            sum += moved(own, toGroup(o), dvec3(o.pos) + copyOffset(group, copy));
    }
    *out = sum;
    return true;
}

std::vector<OrientedBox> unionParts(const GroupShape& shape) {
    const SceneSdf& sdf = shape.sdf;
    if (shape.empty() || !sharpUnion(sdf) || copyCount(sdf.groups[0]) != 1) return {};
    std::vector<OrientedBox> parts;
    for (const SdfObject& o : sdf.objects) {
        if (!exactShape(o)) return {};
        parts.push_back(boxAbout(o));
    }
    return parts;
}

GroupMoments groupMoments(const GroupShape& shape, int depth) {
    GroupMoments g;
    if (shape.empty()) return g;
    if (disjointUnionMoments(shape, &g.moments)) {
        g.closedForm = true;
        return g;
    }
    g.integral =
        integrateSolid([&](const glm::vec3& p) { return shape.distance(p); }, shape.bound, depth);
    g.moments = g.integral.value;
    return g;
}

// A member whose smooth surface its own probes follow as they should: a cylinder's or cone's
// lateral face between rims kept whole (their support points), a sphere's, capsule's or torus's
// by the spheres they hold. Points sampled on that surface would only make it a polygon: a tube
// rolling over them loses energy at each.
struct Cover {
    int wanted = 0, kept = 0;
    bool covered() const { return wanted > 0 && kept == wanted; }
};

namespace {

// A member's side (`side`, in the group's frame) is kept where its middle's circle lies on the
// combined surface, as a probe's, partial where the surface does not hold each of its spheres
// (a tube's outer wall, whose axis is hollow): its contacts then count only where they touch
// the group's own surface. Only a member that adds to the solid: a subtracted one's side faces
// into the hole it carves.
void considerSide(Side side, const Sampler& s, std::vector<Side>* sides) {
    dvec3 u, v;
    rimBasis({side.from, 0.0, glm::normalize(side.to - side.from)}, &u, &v);
    for (int k = 0; k < 8; ++k) {
        const double phi = 2.0 * M_PI * k / 8.0;
        const dvec3 p = sideSurfacePoint(side, 0.5, std::cos(phi) * u + std::sin(phi) * v);
        if (std::abs(s.f(p)) > s.tol) return;
    }
    for (const double t : {0.1, 0.5, 0.9})
        side.partial |= !s.holds(glm::mix(side.from, side.to, t), sideRadius(side, t));
    sides->push_back(side);
}

}  // namespace

GroupProbes groupProbes(const GroupShape& shape) {
    GroupProbes out;
    if (shape.empty()) return out;
    const SceneSdf& sdf = shape.sdf;
    const Sampler s{shape, 1e-5 * shape.bound};
    // Corners and points that hold spheres first, then edges' midpoints, the points of rims
    // that the surface cuts, and the lattice's points by how many gathered on each.
    std::vector<Candidate> first, second, third;
    std::vector<Rim> rims;
    std::vector<Side> sides;
    std::vector<Cover> cover(sdf.objects.size());
    // The rims' and coaxial circles' before their images, each with the group whose mirrors and
    // copies make those: one circle is the same edge only where it goes through the same ones.
    std::vector<std::pair<Rim, int>> circles;
    // A rim is kept whole where all of its circle lies on the surface, on a convex edge (or a
    // rounded one's sphere); a concave edge (a cup's inner floor) can touch nothing first. Where
    // the surface cuts it, the points that lie on an edge of it are kept as points.
    auto considerRim = [&](const Rim& rim, int member, Cover* counts) {
        dvec3 u, v;
        rimBasis(rim, &u, &v);
        bool whole = true;
        std::vector<Candidate> on;
        for (int k = 0; k < 16; ++k) {
            const double phi = 2.0 * M_PI * k / 16.0;
            const dvec3 p = rim.centre + rim.radius * (std::cos(phi) * u + std::sin(phi) * v);
            bool convex = true;
            const bool ok = rim.tube > 0.0
                                ? s.holds(p, rim.tube)
                                : std::abs(s.f(p)) <= s.tol && s.sharp(p, &convex) && convex;
            whole &= ok;
            if (ok) on.push_back({p, rim.tube, 0, member});
        }
        if (counts) ++counts->wanted;
        if (whole) {
            rims.push_back(rim);
            rims.back().part = member;
            if (counts) ++counts->kept;
        } else {
            third.insert(third.end(), on.begin(), on.end());
        }
    };
    for (size_t i = 0; i < sdf.objects.size(); ++i) {
        const SdfObject& o = sdf.objects[i];
        const dmat3 turn = toGroup(o);
        const bool smooth = o.type == ShapeType::Sphere || o.type == ShapeType::Capsule ||
                            o.type == ShapeType::Torus;
        for (const Probe& p : probesOf(o)) {
            const bool edge = o.type == ShapeType::Box &&
                              (p.local.x == 0.0 || p.local.y == 0.0 || p.local.z == 0.0);
            for (const Feature& f : imagesOf(sdf, o, {dvec3(o.pos) + turn * p.local, dvec3(0.0)})) {
                const bool on =
                    p.radius > 0.0 ? s.holds(f.point, p.radius) : std::abs(s.f(f.point)) <= s.tol;
                if (on) (edge ? second : first).push_back({f.point, p.radius, 0, int(i)});
                // A sphere carved or hollowed is still the surface where it was not cut: kept,
                // its contacts checked against the solid (a ball with a notch in its top sank
                // 11 % of its radius, resting on the lattice's points 27° apart).
                else if (p.radius > 0.0) first.push_back({f.point, p.radius, 0, int(i), true});
                if (smooth) ++cover[i].wanted, cover[i].kept += on ? 1 : 0;
            }
        }
        if (o.type == ShapeType::Ellipsoid)
            for (int k = 0; k < 6; ++k) {
                dvec3 tip(0.0);
                tip[k % 3] = (k < 3 ? 1.0 : -1.0) * double(o.size[k % 3]);
                for (const Feature& f : imagesOf(sdf, o, {dvec3(o.pos) + turn * tip, dvec3(0.0)}))
                    if (std::abs(s.f(f.point)) <= s.tol)
                        second.push_back({f.point, 0.0, 0, int(i)});
            }
        for (const Rim& r : rimsOf(o)) {
            const Feature own{dvec3(o.pos) + turn * r.centre, turn * r.axis};
            circles.push_back({{own.point, r.radius, own.axis, r.tube}, o.group});
            for (const Feature& f : imagesOf(sdf, o, own))
                considerRim({f.point, r.radius, glm::normalize(f.axis), r.tube, 0, r.core}, int(i),
                            &cover[i]);
        }
        if (const std::optional<Side> side = sideOf(o); side && o.op == CsgOp::Union)
            for (const Feature& f : imagesOf(
                     sdf, o, {dvec3(o.pos) + turn * side->from, turn * (side->to - side->from)})) {
                Side image = *side;
                image.from = f.point;
                image.to = f.point + f.axis;
                image.part = int(i);
                for (int end = 0; end < 2; ++end)
                    image.open[end] = std::none_of(rims.begin(), rims.end(), [&](const Rim& r) {
                        return r.part == int(i) &&
                               glm::length(r.centre - (end ? image.to : image.from)) <= s.tol;
                    });
                considerSide(image, s, &sides);
            }
    }
    // The circles where a cylinder's or cone's side meets a coaxial one's cap: a cup's inner
    // rim, where the carved cylinder leaves the top; a tube's inner edges. Each circle once: in
    // a stack of forty coins, every cap lies inside twenty coins, each naming it again, and the
    // twenty went through all of the group's copies (forty coins repeated 512 times: minutes).
    for (size_t ia = 0; ia < sdf.objects.size(); ++ia)
        for (const SdfObject& b : sdf.objects) {
            const SdfObject& a = sdf.objects[ia];
            if (&a == &b || !revolved(a) || !revolved(b) || a.round > 0.0f || b.round > 0.0f)
                continue;
            const dvec3 axis = toGroup(a)[1], other = toGroup(b)[1];
            const dvec3 offset = dvec3(b.pos) - dvec3(a.pos);
            if (std::abs(glm::dot(axis, other)) < 1.0 - 1e-9 ||
                glm::length(offset - glm::dot(offset, axis) * axis) > 1e-6 * shape.bound)
                continue;
            const double h = 0.5 * double(a.height);
            for (const double side : {-0.5, 0.5}) {
                const double t = glm::dot(offset + side * double(b.height) * other, axis);
                if (std::abs(t) >= h - 1e-6 * shape.bound) continue;
                const double top = a.type == ShapeType::Cone ? double(a.top) : double(a.radius);
                const double radius = a.radius + (top - double(a.radius)) * (t + h) / (2.0 * h);
                const Rim circle{dvec3(a.pos) + t * axis, radius, axis};
                if (std::any_of(circles.begin(), circles.end(), [&](const auto& c) {
                        return c.second == a.group && sameCircle(c.first, circle, s.tol);
                    }))
                    continue;
                circles.push_back({circle, a.group});
                for (const Feature& f : imagesOf(sdf, a, {circle.centre, axis}))
                    considerRim({f.point, radius, glm::normalize(f.axis), 0.0}, int(ia), nullptr);
            }
        }
    // A lattice over the bounding cube; its points just outside the surface, projected onto it,
    // kept at edges and corners, and on convex smooth surface that no member's probes follow.
    constexpr int kLattice = 16;
    const double cell = 2.0 * shape.bound / kLattice;
    std::vector<Candidate> found;
    for (int i = 0; i < kLattice; ++i)
        for (int j = 0; j < kLattice; ++j)
            for (int k = 0; k < kLattice; ++k) {
                dvec3 p = (dvec3(i, j, k) + 0.5) * cell - shape.bound;
                const double d = s.f(p);
                if (d <= 0.0 || d >= 1.5 * cell || !s.project(p)) continue;
                if (glm::length(p) > shape.bound) continue;
                auto same = std::find_if(found.begin(), found.end(), [&](const Candidate& c) {
                    return glm::length(c.point - p) < 0.125 * cell;
                });
                if (same != found.end()) {
                    ++same->weight;
                    continue;
                }
                bool convex = false;
                const int member = mapGroup(sdf, 0, glm::vec3(p)).object;
                if (!s.sharp(p, &convex) &&
                    (!convex || member < 0 || cover[size_t(member)].covered()))
                    continue;
                found.push_back({p, 0.0, 1, std::max(member, 0)});
            }
    std::stable_sort(found.begin(), found.end(),
                     [](const Candidate& a, const Candidate& b) { return a.weight > b.weight; });
    // The contact keys (kRimIds a rim, kSideIds a side) keep kGroupPointIds for points: the
    // members' corners and the lattice's are the body's own surface, which rims and sides only
    // follow more closely. Six wheels' rims took every key, and a cart's chassis, with no point
    // left, sank upside down onto its wheels; sixty rungs' sides left nothing either, and the
    // spacing below grew for ever. A rim that does not fit is kept as its points, as a rim the
    // surface cuts is; a side that does not fit is left out, as before.
    const int forLines = kMaxGroupProbeIds - kGroupPointIds;
    const size_t rimsFit = size_t(forLines / kRimIds);
    for (size_t r = rimsFit; r < rims.size(); ++r)
        for (const dvec3& p : rimPoints(rims[r]))
            third.push_back({p, rims[r].tube, 0, rims[r].part});
    rims.resize(std::min(rims.size(), rimsFit));
    const int left = forLines - kRimIds * int(rims.size());
    sides.resize(std::min(sides.size(), size_t(left / kSideIds)));
    const int room = kMaxGroupProbeIds - kRimIds * int(rims.size()) - kSideIds * int(sides.size());
    std::vector<Candidate> all = first;
    for (const auto* list : {&second, &third, &found})
        all.insert(all.end(), list->begin(), list->end());
    // The closest spacing whose probes fit the keys left. The members' corners and held spheres,
    // where they fit, are kept however near each other (a thin top's upper corners lie a
    // thickness from its lower ones): the body's own shape. The spacing thins every other point,
    // and only ever-closer copies of one corner.
    const bool keepFirst = int(first.size()) <= room;
    // From a sixth of the group's size, which counts its unions alone: a group of subtractions
    // has none, and at a spacing of 0 its points never came nearer. Then from the points' own
    // reach, or a metre where they all lie at the origin, growing until they fit.
    double size = shape.bound;
    if (!(size > 0.0))
        for (const Candidate& c : all) size = std::max(size, glm::length(c.point));
    for (double spacing = (size > 0.0 ? size : 1.0) / 6.0;; spacing *= 1.15) {
        std::vector<Probe> kept;
        for (size_t k = 0; k < all.size(); ++k) {
            const Candidate& c = all[k];
            const double apart = keepFirst && k < first.size() ? 1e-6 * shape.bound : spacing;
            bool near = false;
            for (const Probe& p : kept) near |= glm::length(p.local - c.point) < apart;
            for (const Rim& r : rims) near |= toRim(r, c.point) < 0.25 * apart;
            if (near) continue;
            kept.push_back({c.point, c.radius, c.part, c.partial});
            if (int(kept.size()) > room) break;
        }
        if (int(kept.size()) <= room) {
            out.probes = kept;
            break;
        }
    }
    out.rims = rims;
    out.sides = sides;
    return out;
}

}  // namespace mb
