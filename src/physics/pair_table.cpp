// pair_table.cpp — the closed-form pairs: boxes (box_box.cpp) and capsules
// (capsule_contacts.cpp), each against the other and itself.
#include "pair_table.h"

#include "box_box.h"
#include "capsule_contacts.h"

#include <array>

namespace mb {

namespace {

using glm::dvec3;

BoxPose boxOf(const RigidBody& b) { return {b.pos, b.orient, dvec3(b.shape.size)}; }

CapsulePose capsuleOf(const RigidBody& b) {
    return {b.pos, b.orient, 0.5 * double(b.shape.height), double(b.shape.radius)};
}

std::vector<PairContact> boxBox(const RigidBody& a, const RigidBody& b, double reach) {
    return collideBoxes(boxOf(a), boxOf(b), reach);
}

std::vector<PairContact> capsuleCapsule(const RigidBody& a, const RigidBody& b, double reach) {
    return collideCapsules(capsuleOf(a), capsuleOf(b), reach);
}

std::vector<PairContact> capsuleBox(const RigidBody& a, const RigidBody& b, double reach) {
    return collideCapsuleBox(capsuleOf(a), boxOf(b), reach);
}

// A routine for (b, a) used for (a, b): its normals turned to point from a to b.
template <PairRoutine routine>
std::vector<PairContact> flipped(const RigidBody& a, const RigidBody& b, double reach) {
    std::vector<PairContact> found = routine(b, a, reach);
    for (PairContact& c : found) c.normal = -c.normal;
    return found;
}

using Table = std::array<std::array<PairRoutine, kShapeTypeCount>, kShapeTypeCount>;

constexpr Table makeTable() {
    Table t{};
    auto set = [&t](ShapeType a, ShapeType b, PairRoutine r) { t[size_t(a)][size_t(b)] = r; };
    set(ShapeType::Box, ShapeType::Box, boxBox);
    set(ShapeType::Capsule, ShapeType::Capsule, capsuleCapsule);
    set(ShapeType::Capsule, ShapeType::Box, capsuleBox);
    set(ShapeType::Box, ShapeType::Capsule, flipped<capsuleBox>);
    return t;
}

constexpr Table kTable = makeTable();

}  // namespace

PairRoutine pairRoutine(ShapeType a, ShapeType b) { return kTable[size_t(a)][size_t(b)]; }

}  // namespace mb
