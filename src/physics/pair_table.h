// pair_table.h — which pairs of rigid shapes meet in closed form, and by which routine: one
// table indexed by the two shape types, as Box2D's s_registers and Jolt's CollisionDispatch
// are. A pair without a routine is probed both ways (RigidBodies::probeShape). Adding a closed
// form is one routine and its entry, and for two types the flipped entry, which wraps it.
#pragma once

#include "pair_contact.h"
#include "rigid_bodies.h"

#include <vector>

namespace mb {

// The contacts of a and b within `reach` of touching, each normal pointing from a to b.
using PairRoutine = std::vector<PairContact> (*)(const RigidBody& a, const RigidBody& b,
                                                 double reach);

// The routine for a pair of plain objects of these types (no group, no rounding), or null.
PairRoutine pairRoutine(ShapeType a, ShapeType b);

}  // namespace mb
