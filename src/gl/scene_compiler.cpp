// scene_compiler.cpp — the tables that turn a scene's layout into GLSL (see scene_compiler.h).
#include "marchbox/gl/scene_compiler.h"

#include <sstream>

namespace mb {

namespace {

// Each type's SDF call, once: `$o` is the object's record, `$q` the point in its frame.
const char* const kShapeCall[kShapeTypeCount] = {
    "sdSphere($q, $o.shape.x)",                 // radius
    "sdBox($q, $o.sizeMinor.xyz)",              // half-extents
    "sdTorus($q, $o.shape.x, $o.sizeMinor.w)",  // major radius, tube radius
    "sdCapsule($q, $o.shape.y, $o.shape.x)",    // height, radius
    "sdCylinder($q, $o.shape.y, $o.shape.x)",   // height, radius
};

// Each operator's join onto the chain (shaders/sdf.glsl).
const char* const kJoin[] = {"joinUnion", "joinSubtract", "joinIntersect"};

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
    for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
        s.replace(at, from.size(), to);
    return s;
}

std::string shapeCall(ShapeType type, const std::string& record, const std::string& point) {
    return replaceAll(replaceAll(kShapeCall[int(type)], "$o", record), "$q", point);
}

std::string objectLine(const ObjectLayout& o, int i) {
    std::string rec = "o" + std::to_string(i), id = std::to_string(i);
    std::string rel = "p - " + rec + ".posBound.xyz";
    std::string q = o.rotated ? rec + ".toLocal * (" + rel + ")" : rel;
    std::string k = o.blended ? rec + ".shape.z" : "0.0";
    std::string comment = "  // " + id + ": " + shapeTypeName(o.type) +
                          (o.op != CsgOp::Union ? std::string(", ") + csgOpName(o.op) : "") +
                          (o.blended ? ", blended" : "") + (o.rotated ? ", turned" : "");
    return "    res = " + std::string(kJoin[int(o.op)]) + "(res, " + shapeCall(o.type, rec, q) +
           ", " + k + ", " + id + ".0);" + comment + "\n";
}

// Whether the shader turns the point into the object's frame. A body of any shape but the
// sphere turns as it moves, so its shader has the turn from the start and play compiles nothing.
bool turns(const Object& o) {
    if (o.dynamic() && o.type != ShapeType::Sphere) return true;
    return o.orient ? *o.orient != glm::quat(1.0f, 0.0f, 0.0f, 0.0f) : o.rot != glm::vec3(0.0f);
}

}  // namespace

std::vector<ObjectLayout> objectLayout(const Scene& scene) {
    std::vector<ObjectLayout> layout;
    layout.reserve(scene.objects.size());
    for (const Object& o : scene.objects)
        layout.push_back({o.type, o.op, turns(o), o.blend > 0.0f});
    return layout;
}

std::string compileSceneMap(const std::vector<ObjectLayout>& layout) {
    std::ostringstream s;
    s << "// The scene, compiled: " << layout.size() << " objects in file order.\n";
    if (!layout.empty()) {
        s << "// Read from the Objects block once per pixel: the march reads registers.\nObject";
        for (size_t i = 0; i < layout.size(); ++i) s << (i ? ", o" : " o") << i;
        s << ";\n";
    }
    s << "\nvoid loadObjects() {\n";
    for (size_t i = 0; i < layout.size(); ++i) s << "    o" << i << " = uObjects[" << i << "];\n";
    s << "}\n\n// x: distance; y: index of the surface's object, HIT_NONE for nothing.\n"
         "vec2 mapObjects(vec3 p) {\n    vec2 res = vec2(1e10, HIT_NONE);\n";
    for (size_t i = 0; i < layout.size(); ++i) s << objectLine(layout[i], int(i));
    s << "    return res;\n}\n";
    return s.str();
}

std::string compileShapeSwitch(unsigned shapes) {
    std::ostringstream s;
    s << "// Object i's own distance at q, a point in its frame.\n"
         "float sdObjectLocal(int i, vec3 q) {\n    int type = uObjects[i].info.x;\n";
    for (int t = 0; t < kShapeTypeCount; ++t)
        if (shapes >> t & 1u)
            s << "    if (type == " << t << ") return "
              << shapeCall(ShapeType(t), "uObjects[i]", "q") << ";\n";
    s << "    return 1e10;\n}\n";
    return s.str();
}

}  // namespace mb
