// group_body.h — a dynamic top-level group as one rigid body: its combined shape in its own
// frame, its mass properties and its probes.
//
// The shape is the group's subtree of the scene with the group at the origin, unturned
// (GroupShape::sdf, group 0): mapGroup gives its distance, a bound where members carve or blend.
// Its mass properties come in closed form where its members are disjoint sharp unions (the
// parallel-axis sum of their moments, mass_moments.h), else from the certified integral of that
// distance; either way once, when the world is made. Its probes are points of the combined
// surface: the members' own probes and rims where they lie on it, and points found by projecting
// a lattice onto it (which gathers on its corners and edges), thinned to a spacing.
#pragma once

#include "mass_moments.h"
#include "oriented_box.h"
#include "rigid_probes.h"

#include "marchbox/scene/scene.h"
#include "marchbox/scene/sdf.h"

#include <vector>

namespace mb {

struct GroupShape {
    SceneSdf sdf;        // group 0 is the group, at the origin; no ground
    double bound = 0.0;  // radius about the origin that holds the shape
    float distance(const glm::vec3& p) const { return mapGroup(sdf, 0, p).d; }
    bool empty() const { return sdf.groups.empty() || sdf.groups[0].last == sdf.groups[0].first; }
};

// Group g of the scene (a top-level group) in its own frame.
GroupShape groupShapeOf(const Scene& scene, int g);

// The scene less the members of its dynamic groups, which move as bodies: what the static
// colliders are made from. The groups stay, those empty; a scene with none is copied whole.
Scene withoutBodyMembers(const Scene& scene);

// The moments of the group's solid in its own frame, and how they were found.
struct GroupMoments {
    Moments moments;
    bool closedForm = false;  // a disjoint union: exact to rounding
    SolidIntegral integral;   // otherwise: the estimate and its bound
};
// Disjoint sharp unions of objects (bounding boxes that at most touch) in closed form, every
// other group integrated to `depth`.
GroupMoments groupMoments(const GroupShape& shape, int depth = kIntegrationDepth);
// The union's closed form, where the group is one (false otherwise).
bool disjointUnionMoments(const GroupShape& shape, Moments* out);

// The boxes about the members of a group whose distance is the least of its members' exact
// distances (one copy, unmirrored, sharp unions of exact shapes), in its frame: no point is
// nearer the group than the nearest box. Empty for every other group.
std::vector<OrientedBox> unionParts(const GroupShape& shape);

// Probes, rims and sides on the combined surface, in the group's frame. At most
// kMaxGroupProbeIds contact keys: a probe takes one, a rim kRimIds (rimSupport's four, and its
// sixteen fixed points, which probe a group's shape), a side kSideIds.
constexpr int kMaxGroupProbeIds = 120;
constexpr int kGroupPointIds = 32;  // of them kept for points; a table's four legs leave 32
struct GroupProbes {
    std::vector<Probe> probes;
    std::vector<Rim> rims;
    std::vector<Side> sides;
};
GroupProbes groupProbes(const GroupShape& shape);

}  // namespace mb
