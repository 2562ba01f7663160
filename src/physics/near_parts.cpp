// near_parts.cpp — the parts of two bodies near each other, by the sphere about each box
// against the other box: cheaper than the boxes' fifteen separating axes, and a thin part's
// probes that it lets through are culled by the part's own distance.
#include "near_parts.h"

#include "group_body.h"
#include "rigid_bodies.h"

#include <glm/gtc/quaternion.hpp>

namespace mb {

namespace {

using glm::dmat3;
using glm::dvec3;

// Whether the boxes may come within `reach` of each other: neither box lies further than that
// from the sphere about the other.
bool near(const OrientedBox& a, const OrientedBox& b, double reach) {
    return distanceToBox(b, a.centre) < glm::length(a.half) + reach &&
           distanceToBox(a, b.centre) < glm::length(b.half) + reach;
}

}  // namespace

void NearParts::find(const RigidBody& prober, const RigidBody& shape, double reach) {
    const OrientedBox hull = placed(shape.hull, shape.orient, shape.pos);
    shapeParts_.clear();
    for (const OrientedBox& part : shape.parts)
        shapeParts_.push_back(placed(part, shape.orient, shape.pos));
    first_.assign(1, 0);
    parts_.clear();
    for (const OrientedBox& local : prober.parts) {
        const OrientedBox part = placed(local, prober.orient, prober.pos);
        if (near(part, hull, reach))
            for (size_t q = 0; q < shapeParts_.size(); ++q)
                if (near(part, shapeParts_[q], reach)) parts_.push_back(int(q));
        first_.push_back(int(parts_.size()));
    }
    // World to the shape's frame (localPoint's), then to each member's (sdObject's).
    const dmat3 toShape = glm::mat3_cast(shape.framed ? shape.axes * glm::conjugate(shape.orient)
                                                      : glm::conjugate(shape.orient));
    const dvec3 shift = (shape.framed ? shape.centre : dvec3(0.0)) - toShape * shape.pos;
    frames_.clear();
    for (size_t q = 0; q < shape.parts.size(); ++q) {
        if (!shape.groupShape) {
            frames_.push_back({&shape.shape, toShape, shift});
            continue;
        }
        const SdfObject& member = shape.groupShape->sdf.objects[q];
        const dmat3 toMember(member.toLocal);
        frames_.push_back({&member, toMember * toShape, toMember * (shift - dvec3(member.pos))});
    }
    step_ = float(1e-3 * shape.bound);
}

NearParts::Sample NearParts::nearest(std::span<const int> parts, const dvec3& x,
                                     double limit) const {
    Sample best{limit, -1};
    for (const int q : parts) {
        const double d = distanceIn(frames_[size_t(q)], x);
        if (d < best.distance) best = {d, q};
    }
    return best;
}

// Σ k·f(m + h·k) over a tetrahedron's corners k is 4h·∇f in the part's frame; its turn is a
// rotation, so its transpose takes the gradient back to the world.
dvec3 NearParts::normal(int part, const dvec3& x) const {
    const Frame& f = frames_[size_t(part)];
    const glm::vec3 m(f.turn * x + f.shift);
    const glm::vec3 k[4] = {{1, -1, -1}, {-1, -1, 1}, {-1, 1, -1}, {1, 1, 1}};
    dvec3 g(0.0);
    for (const glm::vec3& c : k) g += dvec3(c) * double(sdObjectLocal(*f.shape, m + c * step_));
    const double len = glm::length(g);
    return len > 0.0 ? glm::transpose(f.turn) * (g / len) : dvec3(0.0, 1.0, 0.0);
}

}  // namespace mb
