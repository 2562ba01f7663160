// scene.cpp — names of the scene model's enumerations, as the file format spells them.
#include "marchbox/scene/scene.h"

namespace mb {

const char* shapeTypeName(ShapeType t) {
    static const char* names[kShapeTypeCount] = {"sphere", "box", "torus", "capsule", "cylinder"};
    return names[int(t)];
}

const char* csgOpName(CsgOp op) {
    static const char* names[kCsgOpCount] = {"union", "subtract", "intersect"};
    return names[int(op)];
}

}  // namespace mb
