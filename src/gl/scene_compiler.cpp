// scene_compiler.cpp — the tables that turn a scene's layout into GLSL (see scene_compiler.h).
#include "marchbox/gl/scene_compiler.h"

#include "marchbox/gl/plain_members.h"
#include "marchbox/gl/scene_tree.h"
#include "marchbox/scene/shapes.h"

#include <algorithm>
#include <functional>
#include <glm/gtc/quaternion.hpp>
#include <iterator>
#include <sstream>

namespace mb {

namespace {

// Each operator's join onto the chain (shaders/sdf.glsl).
const char* const kJoin[] = {"joinUnion", "joinSubtract", "joinIntersect"};
static_assert(std::size(kJoin) == kCsgOpCount, "a join for every CsgOp");

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
    for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
        s.replace(at, from.size(), to);
    return s;
}

// The object's distance: its type's call, rounded and hollowed where its layout says so.
std::string shapeCall(ShapeType type, bool rounded, bool shelled, const std::string& record,
                      const std::string& point) {
    std::string call = rounded ? shapeRow(type).rounded : shapeRow(type).sdf;
    if (shelled) call = "opShell(" + call + ", $o.detail.z)";
    return replaceAll(replaceAll(call, "$o", record), "$q", point);
}

std::string comment(const ObjectLayout& o, int i) {
    return "  // " + std::to_string(i) + ": " + shapeTypeName(o.type) +
           (o.op != CsgOp::Union ? std::string(", ") + csgOpName(o.op) : "") +
           (o.blended ? ", blended" : "") + (o.rotated ? ", turned" : "") +
           (o.rounded ? ", rounded" : "") + (o.shelled ? ", hollow" : "");
}

// A vector v of the world in object rec's frame, turned only where the object is.
std::string inFrame(const ObjectLayout& o, const std::string& rec, const std::string& v) {
    return o.rotated ? rec + ".toLocal * (" + v + ")" : v;
}

// Object i joined onto the chain `res` at the point `p` (a member of a mirrored or repeated
// group sees its group's image of the point).
std::string objectLine(const ObjectLayout& o, int i, const std::string& indent = "    ",
                       const std::string& res = "res", const std::string& p = "p") {
    std::string rec = "o" + std::to_string(i), id = std::to_string(i);
    std::string q = inFrame(o, rec, p + " - " + rec + ".posBound.xyz");
    std::string k = o.blended ? rec + ".shape.z" : "0.0";
    return indent + res + " = " + kJoin[int(o.op)] + "(" + res + ", " +
           shapeCall(o.type, o.rounded, o.shelled, rec, q) + ", " + k + ", " + id + ".0);" +
           comment(o, i) + "\n";
}

// A ray call with `$o` the object's record and `$r`, `$d` the ray in its frame.
std::string rayCall(const std::string& call, const std::string& record, const std::string& ray,
                    const std::string& direction) {
    return replaceAll(replaceAll(replaceAll(call, "$o", record), "$r", ray), "$d", direction);
}

// The same for object i of the compiled scene, from the world's ray.
std::string rayCall(const std::string& call, const ObjectLayout& o, int i) {
    const std::string rec = "o" + std::to_string(i);
    return rayCall(call, rec, inFrame(o, rec, "ro - " + rec + ".posBound.xyz"),
                   inFrame(o, rec, "rd"));
}

std::string hitLine(const ObjectLayout& o, int i) {
    return "    best = nearerHit(best, " + rayCall(shapeRow(o.type).hit, o, i) + ", " +
           std::to_string(i) + ".0);" + comment(o, i) + "\n";
}

// A plain ball's line of closed-form penumbra (shaders/penumbra.glsl).
std::string clearanceLine(const ObjectLayout& o, int i) {
    return "    least = min(least, " + rayCall("sphereClearance($r, $d, $o.shape.x, far)", o, i) +
           ");" + comment(o, i) + "\n";
}

bool plainBall(const ObjectLayout& o) { return o.plain && o.type == ShapeType::Sphere; }

using Keep = std::function<bool(const ObjectLayout&)>;

std::string groupComment(const GroupLayout& g, int n) {
    static const char* const kAxes[] = {"x", "y", "z"};
    std::string s = "// group " + std::to_string(n) + ": " + g.name;
    if (g.op != CsgOp::Union) s += std::string(", ") + csgOpName(g.op);
    if (g.blended) s += ", blended";
    std::string axes;
    for (int a = 0; a < 3; ++a)
        if (g.mirror[a]) axes += axes.empty() ? kAxes[a] : std::string(", ") + kAxes[a];
    if (!axes.empty()) s += ", mirrored in " + axes;
    if (g.repeat != glm::ivec3(1))
        s += ", " + std::to_string(g.repeat.x) + " x " + std::to_string(g.repeat.y) + " x " +
             std::to_string(g.repeat.z) + " copies";
    return s + "\n";
}

// The GLSL swizzle of the mirrored axes ("x", "xz"), empty for none.
std::string mirrorSwizzle(const GroupLayout& g) {
    std::string s;
    for (int a = 0; a < 3; ++a)
        if (g.mirror[a]) s += "xyz"[a];
    return s;
}

// Writes a chain: the members of one group (or of the top level), a line per object and a
// nested block per member group, over the objects `keep` selects. A group none of whose objects
// is kept is left out whole.
class ChainWriter {
public:
    ChainWriter(std::ostringstream& s, const SceneLayout& layout, Keep keep)
        : s_(s), layout_(layout), keep_(std::move(keep)) {}

    // parent's members among objects [first, end), joined onto `res` at point `p`.
    void members(int parent, int first, int end, const std::string& indent, const std::string& res,
                 const std::string& p) {
        for (int i = first; i < end;) {
            const ObjectLayout& o = layout_.objects[size_t(i)];
            if (o.group == parent) {
                if (keep_(o)) s_ << objectLine(o, i, indent, res, p);
                ++i;
                continue;
            }
            int g = o.group;  // the member group that holds object i
            while (layout_.groups[size_t(g)].parent != parent) g = layout_.groups[size_t(g)].parent;
            if (keeps(g)) group(g, indent, res, p);
            i = layout_.groups[size_t(g)].end;
        }
    }

private:
    bool keeps(int g) const {
        const GroupLayout& group = layout_.groups[size_t(g)];
        for (int i = group.first; i < group.end; ++i)
            if (keep_(layout_.objects[size_t(i)])) return true;
        return false;
    }

    // Where the group's members lie beyond its bounding sphere they leave res as it is (sdf.cpp's
    // leavesAlone). An if: as a loop run once, which llvmpipe leaves at once when no ray of a
    // SIMD group comes near, the example scenes drew no faster (the chair 11.1 ms a frame against
    // 10.1) and llvmpipe's compile grew with the square of the groups: 32 carved groups took
    // 20 s to compile and draw at 320x180, 64 took 87 s, against 5 and 16 s as ifs. An
    // intersection always needs its value.
    void open(const GroupLayout& g, const std::string& rec, const std::string& indent,
              const std::string& res, const std::string& p) {
        const std::string lower =
            "length(" + p + " - " + rec + ".posBound.xyz) - " + rec + ".posBound.w";
        const std::string k = rec + ".blend.x";
        if (g.op == CsgOp::Union)
            s_ << indent << "if (" << lower << " < " << res << ".x" << (g.blended ? " + " + k : "")
               << ") {\n";
        else if (g.op == CsgOp::Subtract)
            s_ << indent << "if (" << lower << " < " << (g.blended ? k + " - " : "-") << res
               << ".x) {\n";
        else s_ << indent << "{\n";
    }

    // The point in the group's frame, turned only where the group is.
    std::string frame(const GroupLayout& g, const std::string& rec, const std::string& p) {
        std::string v = p + " - " + rec + ".posBound.xyz";
        return g.turned ? rec + ".toLocal * (" + v + ")" : v;
    }
    // A point q of the group's frame back in the world.
    std::string world(const GroupLayout& g, const std::string& rec, const std::string& q) {
        return rec + ".posBound.xyz + " + q + (g.turned ? " * " + rec + ".toLocal" : "");
    }

    void group(int n, const std::string& indent, const std::string& res, const std::string& p) {
        const GroupLayout& g = layout_.groups[size_t(n)];
        const std::string id = std::to_string(n), rec = "g" + id, chain = "r" + id;
        const std::string in = indent + "    ", axes = mirrorSwizzle(g);
        const std::string k = g.blended ? rec + ".blend.x" : "0.0";
        s_ << indent << groupComment(g, n);
        open(g, rec, indent, res, p);
        std::string result = chain;
        if (g.repeat == glm::ivec3(1)) {
            std::string point = p;
            if (!axes.empty()) {
                const std::string q = "q" + id;
                point = "p" + id;
                s_ << in << "vec3 " << q << " = " << frame(g, rec, p) << ";\n"
                   << in << q << "." << axes << " = abs(" << q << "." << axes << ");\n"
                   << in << "vec3 " << point << " = " << world(g, rec, q)
                   << ";  // the point its members see\n";
            }
            s_ << in << "vec2 " << chain << " = vec2(1e10, HIT_NONE);\n";
            members(n, g.first, g.end, in, chain, point);
        } else {
            // The union of the copies that can come nearest (groups.glsl), sharp.
            const std::string q = "q" + id, copies = "copies" + id, c = "c" + id, i = "n" + id,
                              point = "p" + id, inner = in + "    ";
            result = "best" + id;
            s_ << in << "vec3 " << q << " = " << frame(g, rec, p) << ";\n"
               << in << "vec2 " << result << " = vec2(1e10, HIT_NONE);\n"
               << in << "Copies " << copies << " = nearestCopy(" << q << ", " << rec
               << ".spacing.xyz, ivec3(" << g.repeat.x << ", " << g.repeat.y << ", " << g.repeat.z
               << "));\n"
               << in << "for (int " << i << " = 0; " << i << " < " << copies << ".count; ++" << i
               << ") {\n"
               << inner << "vec3 " << c << ";\n"
               << inner << "if (!copyAt(" << copies << ", " << i << ", " << q << ", " << rec
               << ".spacing, " << result << ".x, " << c << ")) continue;\n";
            if (!axes.empty())
                s_ << inner << c << "." << axes << " = abs(" << c << "." << axes << ");\n";
            s_ << inner << "vec3 " << point << " = " << world(g, rec, c)
               << ";  // the point this copy's members see\n"
               << inner << "vec2 " << chain << " = vec2(1e10, HIT_NONE);\n";
            members(n, g.first, g.end, inner, chain, point);
            s_ << inner << "if (" << chain << ".x < " << result << ".x) " << result << " = "
               << chain << ";\n"
               << inner << "if (" << i << " == 0) widenCopies(" << copies << ", " << q << ", "
               << rec << ".spacing, " << result << ".x);\n"
               << in << "}\n";
        }
        s_ << in << res << " = " << kJoin[int(g.op)] << "(" << res << ", " << result << ".x, " << k
           << ", " << result << ".y);  // " << g.name << "\n"
           << indent << "}\n";
    }

    std::ostringstream& s_;
    const SceneLayout& layout_;
    Keep keep_;
};

// One function of the chain over the objects `keep` selects.
void writeChain(std::ostringstream& s, const char* name, const SceneLayout& layout, Keep keep) {
    s << "vec2 " << name << "(vec3 p) {\n    vec2 res = vec2(1e10, HIT_NONE);\n";
    ChainWriter(s, layout, std::move(keep))
        .members(-1, 0, int(layout.objects.size()), "    ", "res", "p");
    s << "    return res;\n}\n";
}

// The plain members' exact hits; anyHit (shadows) changes nothing here: the lines run straight
// through, a loop would not end sooner on llvmpipe.
void writePlainHits(std::ostringstream& s, const SceneLayout& layout) {
    const std::vector<ObjectLayout>& objects = layout.objects;
    s << "\n// The plain members, met exactly: x the nearest hit before far, y its object. A loop, "
         "not\n"
         "// an if: llvmpipe leaves it at once when no ray of a SIMD group meets their box.\n"
         "vec2 hitPlainMembers(vec3 ro, vec3 rd, float far, bool anyHit) {\n"
         "    vec2 best = vec2(far, HIT_NONE);\n"
         "    for (bool near = plainBoxMet(ro, rd, far); near; near = false) {\n";
    for (size_t i = 0; i < objects.size(); ++i)
        if (objects[i].plain) s << "    " << hitLine(objects[i], int(i));
    s << "    }\n    return best;\n}\n\n// The marched objects: all but the plain members.\n";
    writeChain(s, "mapRest", layout, [](const ObjectLayout& o) { return !o.plain; });
}

// Soft shadows: the plain balls' least clearance in closed form where the ray passes within
// 1/k of the plain members' box (past that, k times any clearance is over 1 and changes
// nothing), and the chain of everything else, which is marched. Searching another shape's
// penumbra, as the grid does, cost more here than marching it with the rest: in default.txt,
// a torus and a capsule made the frame 1.5-2x slower.
void writeSoftShadowParts(std::ostringstream& s, const SceneLayout& layout) {
    const std::vector<ObjectLayout>& objects = layout.objects;
    s << "\n// The plain balls' soft shadow: the least of their clearances along the ray.\n"
         "float plainClearance(vec3 ro, vec3 rd, float far, float k) {\n"
         "    float least = 1e10;\n";
    if (std::any_of(objects.begin(), objects.end(), plainBall)) {
        s << "    for (bool near = plainBoxNear(ro, rd, far, k); near; near = false) {\n";
        for (size_t i = 0; i < objects.size(); ++i)
            if (plainBall(objects[i])) s << "    " << clearanceLine(objects[i], int(i));
        s << "    }\n";
    }
    s << "    return least;\n}\n\n// What soft shadows march: all but the plain balls.\n";
    writeChain(s, "mapSoftRest", layout, [](const ObjectLayout& o) { return !plainBall(o); });
}

bool ownTurn(const std::optional<glm::quat>& orient, glm::vec3 rot) {
    return orient ? *orient != glm::quat(1.0f, 0.0f, 0.0f, 0.0f) : rot != glm::vec3(0.0f);
}

// Whether the shader turns the point into the object's frame. A body of any shape but the
// sphere turns as it moves, so its shader has the turn from the start and play compiles nothing;
// so does a member of a turned group, or of a body (scene_tree.h's frameTurned). A ball is the
// same turned or not: only its own turn, as a top-level ball's, turns it.
bool turns(const Scene& scene, const Object& o) {
    if (o.type != ShapeType::Sphere && (o.dynamic() || frameTurned(scene, o.group))) return true;
    return ownTurn(o.orient, o.rot);
}

// scene_tree.h's !flatChain, from the layout: a group with members that carves, blends,
// mirrors or repeats, or a member that does.
bool anyGroupNotFlat(const SceneLayout& layout) {
    for (const GroupLayout& g : layout.groups)
        if (g.end > g.first &&
            (g.op != CsgOp::Union || g.blended || glm::any(g.mirror) || g.repeat != glm::ivec3(1)))
            return true;
    for (const ObjectLayout& o : layout.objects)
        if (o.group >= 0 && (o.op != CsgOp::Union || o.blended)) return true;
    return false;
}

}  // namespace

SceneLayout sceneLayout(const Scene& scene) {
    SceneLayout layout;
    layout.objects.reserve(scene.objects.size());
    std::vector<bool> plain = plainMembers(scene);
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        layout.objects.push_back({o.type, o.op, turns(scene, o), o.blend > 0.0f, plain[i],
                                  o.round > 0.0f && shapeRow(o.type).rounded != nullptr,
                                  o.shell > 0.0f, o.group});
    }
    const std::vector<int> end = groupEnds(scene);
    for (size_t g = 0; g < scene.groups.size(); ++g) {
        const Group& group = scene.groups[g];
        layout.groups.push_back({group.name, group.parent, group.first, end[g], group.op,
                                 group.blend > 0.0f, frameTurned(scene, int(g)), group.mirror,
                                 group.repeat});
    }
    return layout;
}

std::string compileSceneMap(const SceneLayout& layout, bool softShadows) {
    const std::vector<ObjectLayout>& objects = layout.objects;
    std::ostringstream s;
    s << "// The scene, compiled: " << objects.size() << " objects in "
      << (layout.groups.empty() ? "file order"
                                : std::to_string(layout.groups.size()) + " groups, in tree order")
      << ".\n";
    if (anyGroupNotFlat(layout))
        s << "// Its groups carve, blend, mirror or repeat their members alone: the uber shader "
             "and the\n// object grid walk one flat chain, so this scene is always compiled.\n";
    if (!objects.empty() || !layout.groups.empty()) {
        s << (layout.groups.empty() ? "// Read from the Objects block"
                                    : "// Read from the Objects and Groups blocks")
          << " once per pixel: the march reads registers.\n";
        if (!objects.empty()) {
            s << "Object";
            for (size_t i = 0; i < objects.size(); ++i) s << (i ? ", o" : " o") << i;
            s << ";\n";
        }
        if (!layout.groups.empty()) {
            s << "Group";
            for (size_t g = 0; g < layout.groups.size(); ++g) s << (g ? ", g" : " g") << g;
            s << ";\n";
        }
    }
    s << "\nvoid loadObjects() {\n";
    for (size_t i = 0; i < objects.size(); ++i) s << "    o" << i << " = uObjects[" << i << "];\n";
    for (size_t g = 0; g < layout.groups.size(); ++g)
        s << "    g" << g << " = uGroups[" << g << "];\n";
    s << "}\n\n// x: distance; y: index of the surface's object, HIT_NONE for nothing.\n";
    writeChain(s, "mapObjects", layout, [](const ObjectLayout&) { return true; });
    if (std::none_of(objects.begin(), objects.end(), [](const ObjectLayout& o) { return o.plain; }))
        return s.str();
    writePlainHits(s, layout);
    if (softShadows) writeSoftShadowParts(s, layout);
    return s.str();
}

std::string compileShapeSwitch(unsigned shapes, bool round, bool shell) {
    std::ostringstream s;
    // With hollow shapes the switch is the solid's, and sdShape hollows it (sdf.cpp's order).
    s << "// Object o's own distance at q, a point in its frame.\n"
      << (shell ? "float sdSolid(Object o, vec3 q) {\n" : "float sdShape(Object o, vec3 q) {\n")
      << "    int type = o.info.x;\n";
    for (int t = 0; t < kShapeTypeCount; ++t) {
        if (!(shapes >> t & 1u)) continue;
        const ShapeType type = ShapeType(t);
        // A rounded form with no rounding (round 0) is its shape to the bit: one call, where
        // a choice of two would run both for a SIMD group whose objects differ.
        s << "    if (type == " << t << ") return "
          << shapeCall(type, round && kShapes[t].rounded != nullptr, false, "o", "q") << ";\n";
    }
    s << "    return 1e10;\n}\n";
    if (shell)
        s << "\nfloat sdShape(Object o, vec3 q) {\n    float d = sdSolid(o, q);\n"
             "    return o.detail.z > 0.0 ? opShell(d, o.detail.z) : d;\n}\n";
    s << "\nfloat sdObjectLocal(int i, vec3 q) { return sdShape(uObjects[i], q); }\n";
    // The grid of plain members meets them through their records (intersect.glsl).
    s << "\n#if PLAIN == 2\nfloat hitShape(Object o, vec3 r, vec3 d) {\n    int type = o.info.x;\n";
    for (int t = 0; t < kShapeTypeCount; ++t)
        if ((shapes >> t & 1u) && kShapes[t].hit)
            s << "    if (type == " << t << ") return " << rayCall(kShapes[t].hit, "o", "r", "d")
              << ";\n";
    s << "    return -1.0;\n}\n#endif\n";
    return s.str();
}

}  // namespace mb
