// physics_test_util.h — small helpers shared by the physics tests.
#pragma once

#include "marchbox/physics/physics.h"
#include "marchbox/scene/scene_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

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

// A scene from its text (version 3 where it says so), with a material for its objects to name.
inline Scene sceneFromText(const std::string& text) {
    Scene s;
    std::vector<SceneError> errors;
    const bool ok = parseScene(text + "material r:0.8 g:0.8 b:0.8\n", &s, &errors);
    EXPECT_TRUE(ok) << (errors.empty() ? "" : errors[0].message) << " at line "
                    << (errors.empty() ? 0 : errors[0].line);
    return s;
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
