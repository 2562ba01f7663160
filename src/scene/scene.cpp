// scene.cpp — names of the scene model's enumerations, as the file format spells them.
#include "marchbox/scene/scene.h"

#include "marchbox/scene/sdf.h"

#include <glm/gtc/quaternion.hpp>

namespace mb {

const char* shapeTypeName(ShapeType t) {
    static const char* names[kShapeTypeCount] = {"sphere", "box", "torus", "capsule", "cylinder"};
    return names[int(t)];
}

const char* csgOpName(CsgOp op) {
    static const char* names[kCsgOpCount] = {"union", "subtract", "intersect"};
    return names[int(op)];
}

glm::quat Object::orientation() const {
    return orient ? *orient : glm::quat_cast(rotationFromEuler(rot));
}

}  // namespace mb
