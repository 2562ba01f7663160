// island.h — sleeping and waking bodies by islands of touching spheres.
//
// An island is a set of dynamic bodies joined by this step's contacts (union-find).
// It sleeps when every body in it has been slower than sleepSpeed for timeToSleep, and wakes as
// a whole when an awake body comes within contact reach of any of its bodies.
#pragma once

#include "contact_solver.h"
#include "marchbox/physics/physics.h"

#include <vector>

namespace mb {

// Advances each awake body's sleep timer by dt and puts settled islands to sleep. `parent` is
// scratch, kept by the caller so that a step allocates nothing.
void updateSleep(std::vector<PhysicsBody>& bodies, const std::vector<Contact>& contacts,
                 const PhysicsSettings& settings, std::vector<int>& parent);

// Wakes every body of the given sleeping islands (ids may repeat).
void wakeIslands(std::vector<PhysicsBody>& bodies, std::vector<int>& islands);

}  // namespace mb
