// shader_source.cpp — from a scene to its fragment shader: the feature set it needs, the
// #defines made from it, and shaders/march.frag assembled behind them; the render modes' names.
#include "marchbox/gl/shader_source.h"

#include "marchbox/gl/glsl_conditionals.h"
#include "marchbox/gl/gpu_scene.h"
#include "marchbox/gl/plain_members.h"
#include "marchbox/gl/scene_tree.h"
#include "marchbox/gl/shader.h"

#include "marchbox/scene/sdf.h"
#include "marchbox/scene/shapes.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <iterator>
#include <sstream>
#include <utility>
#include <vector>

namespace mb {

static const char* kModeNames[kRenderModeCount] = {"shaded", "normals", "depth", "steps",
                                                   "ao",     "shadow",  "id"};

const char* renderModeName(RenderMode m) { return kModeNames[int(m)]; }

bool parseRenderMode(const std::string& s, RenderMode* out) {
    for (int i = 0; i < kRenderModeCount; ++i)
        if (s == kModeNames[i]) {
            *out = RenderMode(i);
            return true;
        }
    return false;
}

int objectIdAt(const Image& ids, int x, int y) {
    const uint8_t* p = ids.pixel(x, y);
    return int(p[0]) + 256 * int(p[1]) + kHitNone;
}

static bool anyMirror(const Scene& s) {
    return std::any_of(s.materials.begin(), s.materials.end(),
                       [](const Material& m) { return m.Kr > 0; });
}

// The shapes of format version 2: every scene before cones, ellipsoids, round and shell.
constexpr unsigned classicShapes() {
    unsigned shapes = 0;
    for (const ShapeRow& row : kShapes)
        if (row.since < 3) shapes |= 1u << int(row.type);
    return shapes;
}
constexpr unsigned kClassicShapes = classicShapes();

// Whether the scene has a cone, an ellipsoid, or a rounded or hollow shape.
static bool usesVersion3Shapes(const Scene& s) {
    return std::any_of(s.objects.begin(), s.objects.end(), [](const Object& o) {
        return (1u << int(o.type) & ~kClassicShapes) || o.round > 0 || o.shell > 0;
    });
}

// llvmpipe runs every case of the uber shader's shape switch for every object (a SIMD group's
// objects differ), so the version 3 shapes cost a classic scene there whether or not it has any:
// default.txt's uber frame took 33% more CPU time with them (92 against 122 ms a frame, one
// llvmpipe thread, 320x180). The uber program comes in two kinds: the classic shapes, and every
// shape for a scene that uses the others.
static ShaderFeatures uberFeatures(RenderMode mode, int uniformObjects, bool version3Shapes) {
    ShaderFeatures f;
    f.uber = true;
    f.mode = mode;
    f.shapes = version3Shapes ? (1u << kShapeTypeCount) - 1 : kClassicShapes;
    f.subtract = f.intersect = f.blend = true;
    f.round = f.shell = version3Shapes;
    f.objects = std::min(kMaxObjects, uniformObjects);
    f.materials = kMaxMaterials;
    f.pointLights = f.dirLights = kMaxLights;
    f.steps = 4096;
    f.shadows = 2;
    f.reflections = 8;
    f.fog = f.ao = true;
    f.grid = true;
    return f;
}

static void applyQuality(ShaderFeatures* f, const RenderQuality& q) {
    f->relaxPercent = f->grid ? 100 : q.relaxPercent;
    f->coneEpsilon = q.coneEpsilon;
    f->shadowSteps = q.shadowSteps;
    f->checkerboard = q.checkerboard && f->mode != RenderMode::ObjectId;
}

int shadowKind(const Scene& s) { return s.lights.empty() ? 0 : s.render.shadows; }

unsigned shadowCasters(const Scene& s, float cutoff) {
    auto brightness = [](const Light& l) {
        return l.intensity * std::max({l.color.r, l.color.g, l.color.b});
    };
    float brightest = 0.0f;
    for (const Light& l : s.lights) brightest = std::max(brightest, brightness(l));
    unsigned mask = 0;
    int bit = 0;
    for (bool directional : {false, true})  // packScene's order
        for (const Light& l : s.lights)
            if (l.directional == directional)
                mask |= unsigned(brightness(l) >= cutoff * brightest) << bit++;
    return mask;
}

// The weighted count of the top-level objects that may be plain members (a group's members are
// marched with it). Where they stand is left out, so a running scene keeps its program.
static float straightHitCost(const Scene& s) {
    float cost = 0.0f;
    for (const Object& o : s.objects)
        if (o.group < 0 && mayBePlain(o)) cost += shapeRow(o.type).hitCost;
    return cost;
}

bool usesGrid(const Scene& s, const RenderQuality& q) {
    int n = int(s.objects.size());
    if (q.grid >= 0) return q.grid == 1 && n > 0;
    return n > kGridMinObjects || straightHitCost(s) > kStraightHitsMost;
}

// Plain members are met exactly where the chain is compiled (a line each) or walks the grid;
// the object loop, kept for measuring, marches everything.
static void choosePlain(ShaderFeatures* f, const Scene& s) {
    if (!f->compiled && !f->grid) return;
    std::vector<bool> plain = plainMembers(s);
    long members = std::count(plain.begin(), plain.end(), true);
    if (members == 0) return;
    f->plain = f->compiled ? 1 : 2;
    f->rest = members < long(plain.size());
}

ShaderFeatures shaderFeatures(const Scene& s, RenderMode mode, bool uber, int maxUniformBlockBytes,
                              const RenderQuality& quality) {
    int blockBytes = maxUniformBlockBytes > 0 ? maxUniformBlockBytes : 16384;
    int uniformObjects = blockBytes / int(sizeof(GpuObject));
    const bool flat = flatChain(s);
    if (uber && flat) {
        ShaderFeatures f = uberFeatures(mode, uniformObjects, usesVersion3Shapes(s));
        applyQuality(&f, quality);
        return f;
    }
    ShaderFeatures f;
    f.mode = mode;
    auto addOp = [&f](CsgOp op, float blend) {
        f.subtract |= op == CsgOp::Subtract;
        f.intersect |= op == CsgOp::Intersect;
        f.blend |= blend > 0;
    };
    for (const Object& o : s.objects) {
        f.shapes |= 1u << int(o.type);
        addOp(o.op, o.blend);
        f.round |= o.round > 0;
        f.shell |= o.shell > 0;
    }
    f.objects = int(s.objects.size());
    f.grid = flat && usesGrid(s, quality);
    f.compiled = !flat || (!f.grid && f.objects <= kGridMinObjects);
    if (f.compiled) {
        f.layout = sceneLayout(s);
        f.groups = int(s.groups.size());
        for (const Group& g : s.groups) {
            addOp(g.op, g.blend);
            f.repeat |= g.repeat != glm::ivec3(1);
        }
    }
    f.objectsInStorage =
        f.objects > uniformObjects || f.groups * int(sizeof(GpuGroup)) > blockBytes;
    choosePlain(&f, s);
    f.materials = int(s.materials.size());
    for (const Light& l : s.lights) (l.directional ? f.dirLights : f.pointLights)++;
    f.ground = s.world.ground;
    f.steps = s.render.steps;
    f.shadows = shadowKind(s);
    if (quality.shadowCutoff > 0.0f) f.shadowCasters = shadowCasters(s, quality.shadowCutoff);
    f.reflections = anyMirror(s) ? s.render.reflections : 0;
    f.fog = s.render.fog > 0;
    f.ao = s.render.ao;
    applyQuality(&f, quality);
    return f;
}

static std::string joined(const std::vector<std::string>& words) {
    std::string s;
    for (const std::string& w : words) s += (s.empty() ? "" : ", ") + w;
    return s;
}

static std::string counted(int n, const char* what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

// How the objects are visited, then one line per group of features.
std::vector<std::string> describeFeatures(const ShaderFeatures& f) {
    if (f.uber) return {"uber: every feature, switched by uniforms"};
    std::vector<std::string> lines = {
        f.compiled ? "compiled: " + counted(f.objects, "object") +
                         (f.groups ? " in " + counted(f.groups, "group") : "") + ", a line each"
        : f.grid ? "object grid: " + counted(f.objects, "object")
                 : "object loop: " + counted(f.objects, "object")};
    std::vector<std::string> shapes, ops = {"union"}, extras;
    for (int t = 0; t < kShapeTypeCount; ++t)
        if (f.shapes >> t & 1u) shapes.push_back(shapeTypeName(ShapeType(t)));
    if (f.subtract) ops.push_back("subtract");
    if (f.intersect) ops.push_back("intersect");
    if (f.blend) ops.push_back("blended");
    if (f.round) ops.push_back("rounded");
    if (f.shell) ops.push_back("hollow");
    if (f.repeat) ops.push_back("repeated");
    if (!shapes.empty()) lines.insert(lines.end(), {joined(shapes), joined(ops)});
    lines.push_back(counted(f.pointLights, "point light") + ", " +
                    counted(f.dirLights, "directional light"));
    static const char* const kShadows[] = {"no shadows", "hard shadows", "soft shadows"};
    lines.push_back(kShadows[f.shadows]);
    if (f.reflections > 0) lines.push_back(counted(f.reflections, "reflection"));
    if (f.fog) extras.push_back("fog");
    if (f.ao) extras.push_back("ambient occlusion");
    if (f.ground) extras.push_back("ground");
    if (f.checkerboard) extras.push_back("checkerboard");
    if (!extras.empty()) lines.push_back(joined(extras));
    return lines;
}

static std::string upperCase(std::string s) {
    for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

// MODE_SHADED, MODE_NORMALS, ... MODE_ID: the names the shaders compare MODE with, made from
// the command line's names so that RenderMode is the one list of modes.
static std::string modeMacro(int mode) {
    return upperCase(std::string("MODE_") + kModeNames[mode]);
}

// The macros in the order the prefix lists them.
static std::vector<std::pair<std::string, long>> featureDefines(const ShaderFeatures& f) {
    std::vector<std::pair<std::string, long>> d = {{"UBER", f.uber}, {"MODE", long(f.mode)}};
    for (int m = 0; m < kRenderModeCount; ++m) d.push_back({modeMacro(m), m});
    unsigned hits = 0;  // the types present that a plain member can be
    for (const ShapeRow& row : kShapes) {
        d.push_back({upperCase("HAS_" + std::string(row.name)), (f.shapes >> int(row.type)) & 1});
        if (row.hit) hits |= f.shapes & 1u << int(row.type);
    }
    d.push_back({"PLAIN_SPHERES_ONLY", hits == 1u << int(ShapeType::Sphere)});
    d.insert(d.end(), {{"HAS_SUBTRACT", f.subtract},
                       {"HAS_INTERSECT", f.intersect},
                       {"HAS_BLEND", f.blend},
                       {"HAS_ROUND", f.round},
                       {"HAS_SHELL", f.shell},
                       {"NUM_OBJECTS", f.objects},
                       {"NUM_GROUPS", f.groups},
                       {"HAS_REPEAT", f.repeat},
                       {"NUM_MATERIALS", f.materials},
                       {"NUM_POINT_LIGHTS", f.pointLights},
                       {"NUM_DIR_LIGHTS", f.dirLights},
                       {"OBJECTS_IN_STORAGE", f.objectsInStorage},
                       {"HAS_GROUND", f.ground},
                       {"MAX_STEPS", f.steps},
                       {"SHADOWS", f.shadows},
                       {"REFLECTIONS", f.reflections},
                       {"HAS_FOG", f.fog},
                       {"HAS_AO", f.ao},
                       {"USE_GRID", f.grid},
                       {"COMPILED", f.compiled},
                       {"PLAIN", f.plain},
                       {"HAS_REST", f.rest},
                       {"RELAX_PERCENT", f.relaxPercent},
                       {"CONE_EPSILON", f.coneEpsilon},
                       {"SHADOW_STEPS", f.shadowSteps},
                       {"SHADOW_CASTERS", long(f.shadowCasters)},
                       {"CHECKERBOARD", f.checkerboard},
                       {"OUTLINE", f.outline}});
    return d;
}

std::string shaderPrefix(const ShaderFeatures& f) {
    std::ostringstream o;
    o << (f.objectsInStorage ? "#version 430 core\n" : "#version 330 core\n");
    for (const auto& [name, value] : featureDefines(f))
        o << "#define " << name << ' ' << value << '\n';
    // A march's object id is a float: an object's index or one of these, sdf.h's own values.
    o << "const float HIT_GROUND = " << kHitGround << ".0;\n"
      << "const float HIT_NONE = " << kHitNone << ".0;\n";
    return o.str();
}

bool fragmentSource(const ShaderFeatures& f, std::string* out, std::string* error, LineMap* lines) {
    std::string body, resolved;
    LineMap map;
    if (!readShaderSource(shaderDir() + "/march.frag", &body, &map, error)) return false;
    auto list = featureDefines(f);
    Defines defines(list.begin(), list.end());
    if (!resolveConditionals(body, defines, &resolved, error, &map)) return false;
    const std::string marker = "#pragma marchbox scene\n";
    size_t at = resolved.find(marker);
    if (at == std::string::npos) {
        *error = "march.frag: no '#pragma marchbox scene' line for the compiled scene";
        return false;
    }
    std::string scene = (f.compiled ? compileSceneMap(f.layout, f.shadows == 2) + "\n" : "") +
                        compileShapeSwitch(f.shapes, f.round, f.shell);
    resolved.replace(at, marker.size(), scene);
    auto markerLine = map.begin() + std::count(resolved.begin(), resolved.begin() + long(at), '\n');
    LineMap sceneLines = linesOf("<scene code>", scene);
    map.insert(map.erase(markerLine), sceneLines.begin(), sceneLines.end());
    std::string prefix = shaderPrefix(f);
    *out = prefix + resolved;
    if (lines) *lines = withPrefix(prefix, map);
    return true;
}

}  // namespace mb
