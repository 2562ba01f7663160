// near_parts.h — which parts of two bodies can meet within a reach, and the distance to those
// parts: for each part of one body (the prober), the other body's parts whose boxes come that
// near its box.
//
// A union's distance is the least of its members' (unionParts), and a member whose box lies
// beyond reach of a part's box lies beyond reach of every probe of that part, which the box
// holds. So a part with no near parts has nothing to probe, and the others' probes are measured
// against their near parts alone, each an exact SDF in its own frame: the children of a
// compound shape paired one by one where their boxes meet, as Bullet's and Jolt's are.
#pragma once

#include "oriented_box.h"

#include "marchbox/scene/sdf.h"

#include <glm/mat3x3.hpp>
#include <limits>
#include <span>
#include <vector>

namespace mb {

struct RigidBody;

// The body's hull and then its parts where the body is now, appended to `out`: what
// NearParts::find takes of each body.
void appendPlacedBoxes(const RigidBody& b, std::vector<OrientedBox>& out);

class NearParts {
public:
    // The parts of bodies a and b where they are now (neither without parts), `reach` apart or
    // nearer by their boxes (each body's placed hull, then its placed parts): each pair of parts
    // tested once, for both ways round. The pair's probes both ways then take their lists from it.
    void meet(std::span<const OrientedBox> boxesA, std::span<const OrientedBox> boxesB,
              double reach);
    // The lists for the met pair's probes one way round: a's parts against `shape`, body b, where
    // `proberIsA`, else b's against a.
    void find(bool proberIsA, const RigidBody& shape);
    // The shape's parts near the prober's part p, in the shape's order.
    std::span<const int> of(int p) const {
        return {parts_.data() + first_[size_t(p)], parts_.data() + first_[size_t(p) + 1]};
    }

    struct Sample {
        double distance;
        int part;  // −1: none nearer than the limit
    };
    // The nearest of the listed parts to world point x, and its distance.
    Sample nearest(std::span<const int> parts, const glm::dvec3& x,
                   double limit = std::numeric_limits<double>::infinity()) const;
    // The unit normal (world) of the part's surface at x; `creased`, where asked, as isCreased.
    glm::dvec3 normal(int part, const glm::dvec3& x, bool* creased = nullptr) const;

private:
    // A part of the shape as the probes see it: x (world) → turn·x + shift in its own frame.
    struct Frame {
        const SdfObject* shape;
        glm::dmat3 turn;
        glm::dvec3 shift;
    };
    float distanceIn(const Frame& f, const glm::dvec3& x) const {
        return sdObjectLocal(*f.shape, glm::vec3(f.turn * x + f.shift));
    }
    // Where near_ holds a's part p against b's part q.
    size_t nearIndex(size_t p, size_t q) const { return p * nearHullB_.size() + q; }
    // meet's: whether a's part p and b's part q are near (near_[nearIndex(p, q)], set only where
    // each is near the other's hull), and whether each part is near the other's hull.
    std::vector<char> near_, nearHullA_, nearHullB_;
    std::vector<int> first_, parts_;  // part p's list is parts_[first_[p], first_[p + 1])
    std::vector<Frame> frames_;       // one per shape part, set where a list holds it
    std::vector<char> framed_;
    float step_ = 0.0f;  // of the normal's differences, in the shape's units
};

}  // namespace mb
