// physics_test_util.h — small helpers shared by the physics tests.
#pragma once

#include "marchbox/physics/physics.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace mb {

// A static object of the type at pos, turned by rot (Euler degrees): the shapes bodies land on.
inline Object staticShape(ShapeType type, glm::vec3 pos, glm::vec3 rot = glm::vec3(0.0f)) {
    Object o;
    o.type = type;
    o.pos = pos;
    o.rot = rot;
    o.isStatic = true;
    return o;
}

inline int stepsFor(double seconds, const PhysicsSettings& s) {
    return int(std::llround(seconds / s.dt));
}

inline bool finiteBody(const PhysicsBody& b) {
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(b.pos[k]) || !std::isfinite(b.vel[k]) || !std::isfinite(b.spin[k]))
            return false;
    return true;
}

inline bool allFinite(const PhysicsWorld& w) {
    for (int i = 0; i < w.bodyCount(); ++i)
        if (!finiteBody(w.body(i))) return false;
    return true;
}

inline glm::dvec3 momentum(const PhysicsWorld& w) {
    glm::dvec3 p(0.0);
    for (int i = 0; i < w.bodyCount(); ++i) p += w.body(i).vel / w.body(i).invMass;
    return p;
}

}  // namespace mb
