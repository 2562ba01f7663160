// near_parts.cpp — the parts of two bodies near each other, by the sphere about each box
// against the other box: cheaper than the boxes' fifteen separating axes, and a thin part's
// probes that it lets through are culled by the part's own distance.
#include "near_parts.h"

#include "group_body.h"
#include "rigid_bodies.h"
#include "tetra_gradient.h"

#include <glm/gtc/quaternion.hpp>

namespace mb {

namespace {

using glm::dmat3;
using glm::dvec3;

// Whether the boxes may come within `reach` of each other: the spheres about them first, then
// neither box further than that from the sphere about the other.
bool near(const OrientedBox& a, const OrientedBox& b, double reach) {
    const double ra = glm::length(a.half), rb = glm::length(b.half);
    return glm::length(b.centre - a.centre) < ra + rb + reach &&
           distanceToBox(b, a.centre) < ra + reach && distanceToBox(a, b.centre) < rb + reach;
}

}  // namespace

void appendPlacedBoxes(const RigidBody& b, std::vector<OrientedBox>& out) {
    out.push_back(placed(b.hull, b.orient, b.pos));
    for (const OrientedBox& part : b.parts) out.push_back(placed(part, b.orient, b.pos));
}

void NearParts::find(std::span<const OrientedBox> proberBoxes, const RigidBody& shape,
                     std::span<const OrientedBox> shapeBoxes, double reach) {
    const OrientedBox& hull = shapeBoxes[0];
    const std::span<const OrientedBox> shapeParts = shapeBoxes.subspan(1);
    first_.assign(1, 0);
    parts_.clear();
    framed_.assign(shapeParts.size(), 0);
    for (const OrientedBox& part : proberBoxes.subspan(1)) {
        if (near(part, hull, reach))
            for (size_t q = 0; q < shapeParts.size(); ++q)
                if (near(part, shapeParts[q], reach)) parts_.push_back(int(q)), framed_[q] = 1;
        first_.push_back(int(parts_.size()));
    }
    // World to the shape's frame (localPoint's), then to each member's (sdObject's).
    const dmat3 toShape = glm::mat3_cast(shape.framed ? shape.axes * glm::conjugate(shape.orient)
                                                      : glm::conjugate(shape.orient));
    const dvec3 shift = (shape.framed ? shape.centre : dvec3(0.0)) - toShape * shape.pos;
    frames_.resize(shapeParts.size());
    for (size_t q = 0; q < shapeParts.size(); ++q) {
        if (!framed_[q]) continue;
        if (!shape.groupShape) {
            frames_[q] = {&shape.shape, toShape, shift};
            continue;
        }
        const SdfObject& member = shape.groupShape->sdf.objects[q];
        const dmat3 toMember(member.toLocal);
        frames_[q] = {&member, toMember * toShape, toMember * (shift - dvec3(member.pos))};
    }
    step_ = float(kTetraStep * shape.bound);
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

// The gradient in the part's frame (tetra_gradient.h); its turn is a rotation, so its transpose
// takes the gradient back to the world.
dvec3 NearParts::normal(int part, const dvec3& x, bool* creased) const {
    const Frame& f = frames_[size_t(part)];
    const dvec3 g = tetraGradient([&f](const glm::vec3& m) { return sdObjectLocal(*f.shape, m); },
                                  glm::vec3(f.turn * x + f.shift), step_);
    const double len = glm::length(g);
    if (creased) *creased = isCreased(len, double(step_));
    return len > 0.0 ? glm::transpose(f.turn) * (g / len) : dvec3(0.0, 1.0, 0.0);
}

}  // namespace mb
