// surface.h — friction and restitution: a body's or a static surface's own, and a touching
// pair's, combined as the scene format says.
#pragma once

#include "marchbox/scene/scene.h"

#include <algorithm>
#include <cmath>

namespace mb {

struct Surface {
    double friction = 0.0, restitution = 0.0;
};

// The object's own values, or the world's where it has none.
inline Surface surfaceOf(const Object& o, const World& world) {
    return {double(o.friction.value_or(world.friction)),
            double(o.restitution.value_or(world.restitution))};
}

// √(f₁·f₂) and max(e₁, e₂) (Box2D's rule). Equal values give that value exactly, where √(f·f)
// may round: a scene that sets no values of its own keeps every bit it had before there were any.
inline Surface combine(const Surface& a, const Surface& b) {
    const double friction =
        a.friction == b.friction ? a.friction : std::sqrt(a.friction * b.friction);
    return {friction, std::max(a.restitution, b.restitution)};
}

}  // namespace mb
