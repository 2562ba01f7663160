// marchbox/editor/carved.h — objects that a later subtraction hides whole: drawn nowhere but in
// their shadows' absence, and named so in the Objects list.
#pragma once

#include "marchbox/scene/scene.h"

#include <vector>

namespace mb {

// For each object, the index of a later object whose subtraction holds it whole, so that
// nothing of it shows: one of its own chain (its group's), or of a chain holding its group,
// which carves the group; -1 for one that is not. Whole means its bounding sphere inside the subtractor's solid, which a distance bound
// proves as well as an exact distance does.
std::vector<int> carvedAway(const Scene& s);

}  // namespace mb
