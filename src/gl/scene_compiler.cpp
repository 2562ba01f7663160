// scene_compiler.cpp — the tables that turn a scene's layout into GLSL (see scene_compiler.h).
#include "marchbox/gl/scene_compiler.h"

#include "marchbox/gl/plain_members.h"

#include <algorithm>
#include <cstdint>
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

// Each type's exact hit (shaders/intersect.glsl): `$r` and `$d` are the ray in the object's frame.
const char* const kHitCall[kShapeTypeCount] = {
    "hitSphere($r, $d, $o.shape.x)",
    "hitBox($r, $d, $o.sizeMinor.xyz)",
    "hitTorus($r, $d, $o.shape.x, $o.sizeMinor.w)",
    "hitCapsule($r, $d, $o.shape.y, $o.shape.x)",
    "hitCylinder($r, $d, $o.shape.y, $o.shape.x)",
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

std::string comment(const ObjectLayout& o, int i) {
    return "  // " + std::to_string(i) + ": " + shapeTypeName(o.type) +
           (o.op != CsgOp::Union ? std::string(", ") + csgOpName(o.op) : "") +
           (o.blended ? ", blended" : "") + (o.rotated ? ", turned" : "");
}

// A vector v of the world in object rec's frame, turned only where the object is.
std::string inFrame(const ObjectLayout& o, const std::string& rec, const std::string& v) {
    return o.rotated ? rec + ".toLocal * (" + v + ")" : v;
}

std::string objectLine(const ObjectLayout& o, int i) {
    std::string rec = "o" + std::to_string(i), id = std::to_string(i);
    std::string q = inFrame(o, rec, "p - " + rec + ".posBound.xyz");
    std::string k = o.blended ? rec + ".shape.z" : "0.0";
    return "    res = " + std::string(kJoin[int(o.op)]) + "(res, " + shapeCall(o.type, rec, q) +
           ", " + k + ", " + id + ".0);" + comment(o, i) + "\n";
}

// A ray call of object i: `$r` and `$d` become the ray in its frame, `$o` its record.
std::string rayCall(const std::string& call, const ObjectLayout& o, int i) {
    std::string rec = "o" + std::to_string(i);
    std::string s = replaceAll(call, "$o", rec);
    s = replaceAll(s, "$r", inFrame(o, rec, "ro - " + rec + ".posBound.xyz"));
    return replaceAll(s, "$d", inFrame(o, rec, "rd"));
}

std::string hitLine(const ObjectLayout& o, int i) {
    return "    best = nearerHit(best, " + rayCall(kHitCall[int(o.type)], o, i) + ", " +
           std::to_string(i) + ".0);" + comment(o, i) + "\n";
}

// A plain ball's line of closed-form penumbra (shaders/penumbra.glsl).
std::string clearanceLine(const ObjectLayout& o, int i) {
    return "    least = min(least, " + rayCall("sphereClearance($r, $d, $o.shape.x, far)", o, i) +
           ");" + comment(o, i) + "\n";
}

bool plainBall(const ObjectLayout& o) { return o.plain && o.type == ShapeType::Sphere; }

// One function of the chain over the objects `keep` selects.
template <typename Keep>
void writeChain(std::ostringstream& s, const char* name, const std::vector<ObjectLayout>& layout,
                Keep keep) {
    s << "vec2 " << name << "(vec3 p) {\n    vec2 res = vec2(1e10, HIT_NONE);\n";
    for (size_t i = 0; i < layout.size(); ++i)
        if (keep(layout[i])) s << objectLine(layout[i], int(i));
    s << "    return res;\n}\n";
}

// The plain members' exact hits; anyHit (shadows) changes nothing here: the lines run straight
// through, a loop would not end sooner on llvmpipe.
void writePlainHits(std::ostringstream& s, const std::vector<ObjectLayout>& layout) {
    uint64_t members = 0;
    for (size_t i = 0; i < layout.size(); ++i) members |= uint64_t(layout[i].plain) << i;
    s << "\n// Whether object id is a plain member.\nbool plainMember(int id) {\n"
      << "    uint bits = id < 32 ? " << uint32_t(members) << "u : " << uint32_t(members >> 32)
      << "u;\n    return id >= 0 && ((bits >> uint(id & 31)) & 1u) != 0u;\n}\n";
    s << "\n// The plain members, met exactly: x the nearest hit before far, y its object. A loop, "
         "not\n"
         "// an if: llvmpipe leaves it at once when no ray of a SIMD group meets their box.\n"
         "vec2 hitPlainMembers(vec3 ro, vec3 rd, float far, bool anyHit) {\n"
         "    vec2 best = vec2(far, HIT_NONE);\n"
         "    for (bool near = plainBoxMet(ro, rd, far); near; near = false) {\n";
    for (size_t i = 0; i < layout.size(); ++i)
        if (layout[i].plain) s << "    " << hitLine(layout[i], int(i));
    s << "    }\n    return best;\n}\n\n// The marched objects: all but the plain members.\n";
    writeChain(s, "mapRest", layout, [](const ObjectLayout& o) { return !o.plain; });
}

// Soft shadows: the plain balls' least clearance in closed form where the ray passes within
// 1/k of the plain members' box (past that, k times any clearance is over 1 and changes
// nothing), and the chain of everything else, which is marched. Searching another shape's
// penumbra, as the grid does, cost more here than marching it with the rest: in default.txt,
// a torus and a capsule made the frame 1.5-2x slower.
void writeSoftShadowParts(std::ostringstream& s, const std::vector<ObjectLayout>& layout) {
    s << "\n// The plain balls' soft shadow: the least of their clearances along the ray.\n"
         "float plainClearance(vec3 ro, vec3 rd, float far, float k) {\n"
         "    float least = 1e10;\n";
    if (std::any_of(layout.begin(), layout.end(), plainBall)) {
        s << "    for (bool near = plainBoxNear(ro, rd, far, k); near; near = false) {\n";
        for (size_t i = 0; i < layout.size(); ++i)
            if (plainBall(layout[i])) s << "    " << clearanceLine(layout[i], int(i));
        s << "    }\n";
    }
    s << "    return least;\n}\n\n// What soft shadows march: all but the plain balls.\n";
    writeChain(s, "mapSoftRest", layout, [](const ObjectLayout& o) { return !plainBall(o); });
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
    std::vector<bool> plain = plainMembers(scene);
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        layout.push_back({o.type, o.op, turns(o), o.blend > 0.0f, plain[i]});
    }
    return layout;
}

std::string compileSceneMap(const std::vector<ObjectLayout>& layout, bool softShadows) {
    std::ostringstream s;
    s << "// The scene, compiled: " << layout.size() << " objects in file order.\n";
    if (!layout.empty()) {
        s << "// Read from the Objects block once per pixel: the march reads registers.\nObject";
        for (size_t i = 0; i < layout.size(); ++i) s << (i ? ", o" : " o") << i;
        s << ";\n";
    }
    s << "\nvoid loadObjects() {\n";
    for (size_t i = 0; i < layout.size(); ++i) s << "    o" << i << " = uObjects[" << i << "];\n";
    s << "}\n\n// x: distance; y: index of the surface's object, HIT_NONE for nothing.\n";
    writeChain(s, "mapObjects", layout, [](const ObjectLayout&) { return true; });
    if (std::none_of(layout.begin(), layout.end(), [](const ObjectLayout& o) { return o.plain; }))
        return s.str();
    writePlainHits(s, layout);
    if (softShadows) writeSoftShadowParts(s, layout);
    return s.str();
}

std::string compileShapeSwitch(unsigned shapes) {
    std::ostringstream s;
    s << "// Object o's own distance at q, a point in its frame.\n"
         "float sdShape(Object o, vec3 q) {\n    int type = o.info.x;\n";
    for (int t = 0; t < kShapeTypeCount; ++t)
        if (shapes >> t & 1u)
            s << "    if (type == " << t << ") return " << shapeCall(ShapeType(t), "o", "q")
              << ";\n";
    s << "    return 1e10;\n}\n\n"
         "float sdObjectLocal(int i, vec3 q) { return sdShape(uObjects[i], q); }\n";
    return s.str();
}

}  // namespace mb
