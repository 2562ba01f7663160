// pair_cache.cpp — the kept points of each pair, found again only once the pair has moved.
#include "pair_cache.h"

#include "rigid_bodies.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace mb {

namespace {

using glm::dquat;
using glm::dvec3;

template <class Body>
dvec3 toFrame(const Body& body, const dvec3& world) {
    return glm::conjugate(body.orient) * (world - body.pos);
}

dvec3 toWorld(const RigidBody& body, const dvec3& local) { return body.pos + body.orient * local; }

}  // namespace

void PairCache::nextStep() {
    last_.swap(now_);
    now_.clear();
}

bool PairCache::reuse(std::uint64_t pair, const RigidBody& a, const RigidBody& b, double reach,
                      std::vector<PairCandidate>* out) {
    const auto found = last_.find(pair);
    if (found == last_.end()) return false;
    const Entry& e = found->second;
    // b's origin and turn in a's frame now and when the points were found.
    const double shift = glm::length(toFrame(a, b.pos) - toFrame(e.a, e.b.pos));
    // The angle between the two turns is 2·acos|q·q'|.
    const double cosHalf = std::min(std::abs(glm::dot(glm::conjugate(a.orient) * b.orient,
                                                      glm::conjugate(e.a.orient) * e.b.orient)),
                                    1.0);
    const double turned = 2.0 * std::acos(cosHalf);
    const double came = shift + turned * b.bound;  // the most any point of b came towards a
    if (e.points.empty()
            ? reach + came > e.reach
            : shift > kMovedMost || turned > glm::radians(kTurnedMost) || came > 0.5 * e.reach)
        return false;
    out->clear();
    for (const PairCandidate& c : e.points) {
        const dvec3 half = 0.5 * c.separation * c.normal;
        const dvec3 onA = toWorld(a, toFrame(e.a, c.point - half));
        const dvec3 onB = toWorld(b, toFrame(e.b, c.point + half));
        const dvec3 n = a.orient * (glm::conjugate(e.a.orient) * c.normal);
        out->push_back({0.5 * (onA + onB), n, glm::dot(onB - onA, n), c.probe,
                        toWorld(a, toFrame(e.a, c.centreA)), toWorld(b, toFrame(e.b, c.centreB))});
    }
    now_.insert(last_.extract(found));
    return true;
}

void PairCache::keep(std::uint64_t pair, const RigidBody& a, const RigidBody& b, double reach,
                     const std::vector<PairCandidate>& found) {
    // The pair's entry of the last step, where it had one, is rewritten in place: its node and
    // its points' room are used again rather than freed and made anew.
    auto node = last_.extract(pair);
    Entry& e = node ? node.mapped() : now_[pair];
    e.reach = reach;
    e.a = {a.pos, a.orient};
    e.b = {b.pos, b.orient};
    e.points = found;
    if (node) now_.insert(std::move(node));
}

}  // namespace mb
