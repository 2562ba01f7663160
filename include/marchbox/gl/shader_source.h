// marchbox/gl/shader_source.h — the fragment shader a scene needs, as GLSL text.
//
// The shader is shaders/march.frag behind a block of #defines made from the scene's feature
// set: the object types and operators in use, the exact light counts, the shadow kind, the
// reflection depth. Code a scene does not use is not in its shader. The uber shader sets
// every feature and reads the counts and switches from uniforms instead.
#pragma once

#include "marchbox/gl/image.h"
#include "marchbox/gl/scene_compiler.h"
#include "marchbox/gl/shader_lines.h"
#include "marchbox/scene/scene.h"

#include <string>
#include <vector>

namespace mb {

enum class RenderMode : int { Shaded = 0, Normals, Depth, Steps, Ao, Shadow, ObjectId };
constexpr int kRenderModeCount = 7;
const char* renderModeName(RenderMode m);  // "shaded", "normals", ... "id"
bool parseRenderMode(const std::string& s, RenderMode* out);
// The id view (RenderMode::ObjectId) writes a pixel's object id minus kHitNone (0 nothing, 1 the
// ground, 2 the first object) as red + 256·green; this reads it back: the object's index,
// kHitGround or kHitNone.
int objectIdAt(const Image& ids, int x, int y);

// Renderer knobs beyond the scene's `render` record; defaults from docs/render-report.md.
struct RenderQuality {
    int relaxPercent = 100;    // over-relaxation ω × 100 (Keinert et al. 2014); 100 is plain
    bool coneEpsilon = false;  // the hit distance grows to half a pixel's footprint far away
    int shadowSteps = 128;     // march steps of each shadow ray
    int grid = -1;             // object grid: -1 when it pays (kGridMinObjects), 0 never, 1 always
    float softness = 8.0f;     // soft-shadow k (Quilez): penumbra width ~ distance / k; a uniform
    // Lights less bright than this fraction of the brightest cast no shadow (0: every light
    // does). Each skipped light saves a shadow ray per shaded point (draft, quality_preset.cpp).
    float shadowCutoff = 0.0f;
    // Shade half the pixels, in a checkerboard, and fill in the rest from their neighbours
    // (gl/checkerboard.h): half the fragments (draft). Never for object ids, which do not average.
    bool checkerboard = false;

    bool operator==(const RenderQuality&) const = default;
};

struct ShaderFeatures {
    bool uber = false;
    RenderMode mode = RenderMode::Shaded;
    unsigned shapes = 0;  // bit i set: ShapeType i is present
    bool subtract = false, intersect = false, blend = false;
    bool round = false, shell = false;  // some object has rounded edges, some is hollow
    int objects = 0, materials = 0, pointLights = 0, dirLights = 0;
    int groups = 0;       // groups the compiled tree reads (the Groups block); 0 unless compiled
    bool repeat = false;  // some group has copies (shaders/groups.glsl)
    bool ground = true;
    int steps = 256;      // march steps, a compile-time loop bound
    int shadows = 0;      // 0 none, 1 hard, 2 soft
    int reflections = 0;  // bounces actually possible: 0 when nothing reflects
    bool fog = false, ao = false;
    bool objectsInStorage = false;  // past the uniform-block limit objects (and groups) go in SSBOs
    bool grid = false;              // steps visit one cell of the object grid, not every object
    int relaxPercent = 100;         // applies without the grid only: cell caps are not radii
    bool coneEpsilon = false;
    int shadowSteps = 128;
    unsigned shadowCasters = (1u << kMaxLights) - 1;  // bit i: light i of the Lights block casts
    bool checkerboard = false;
    bool outline = false;   // the editor's selection ring, shaded views only
    bool compiled = false;  // the chain is straight-line code, per `layout`
    SceneLayout layout;     // empty unless compiled
    // Plain members (gl/plain_members.h) met exactly: 0 none, everything marched; 1 a line each
    // (compiled); 2 through their own grid. `rest`: some objects are still marched.
    int plain = 0;
    bool rest = true;

    bool operator==(const ShaderFeatures&) const = default;  // every field: no stale program
};

// Up to this many objects the chain is compiled straight-line; above it a step looks only at
// its grid cell. A scene whose groups do not flatten (gl/scene_tree.h) is compiled whatever its
// size, and for the uber shader too: the grid and the uber shader's loop walk one flat chain.
// Measured on llvmpipe at 480x270 (docs/render-report.md): compiled against the grid, 8 objects 14
// against 54 ms, 32: 52 against 83, 64: 122 against 150, 96: 215 against 198; and compiling costs
// about 30 ms more per object (64 objects: 2 s).
constexpr int kGridMinObjects = 64;
// Objects a ray may meet exactly (plain_members.h) are tested one after another on every
// primary, shadow and mirror ray where the scene is compiled, and walked in their own grid
// otherwise. Past about 16 spheres' worth, each weighted by its type's hitCost (shapes.h), the
// walk costs less. Measured on llvmpipe at 480x270, straight-line against the grid (ms): 12
// spheres 7.3 against 9.1, 16: 10.7 against 9.2, 8 turned boxes 10.2 against 13.3, 12: 17.3
// against 8.9; dominoes.txt (20 boxes) 141 against 54, mixed_pile.txt (36 bodies) 57 against 21.
constexpr float kStraightHitsMost = 16.0f;

// The rules both the specialised and the uber shader follow, each written once.
int shadowKind(const Scene& scene);  // 0 without lights
// Bit i set: light i, in the Lights block's order (point lights, then directional), is at least
// `cutoff` times as bright as the brightest light, brightness being its colour's largest
// channel times its intensity.
unsigned shadowCasters(const Scene& scene, float cutoff);
bool usesGrid(const Scene& scene, const RenderQuality& quality);  // see RenderQuality::grid

// maxUniformBlockBytes is GL_MAX_UNIFORM_BLOCK_SIZE; 0 means "assume the GL minimum, 16 KiB".
// `uber` asks for the general shader; a scene it cannot draw (groups that do not flatten) gets
// its compiled features instead, whose shader says why in a comment.
ShaderFeatures shaderFeatures(const Scene& scene, RenderMode mode, bool uber,
                              int maxUniformBlockBytes, const RenderQuality& quality = {});

// What a shader was built for, a line each, for people: "compiled: 3 objects, a line each",
// "sphere, box", "union, subtract, blended", "1 point light", "soft shadows", "2 reflections",
// "fog, ambient occlusion, ground".
std::vector<std::string> describeFeatures(const ShaderFeatures& f);

// The #version line, the #define block for a feature set (with MODE_SHADED ... MODE_ID, the names
// of RenderMode's values) and the constants HIT_GROUND and HIT_NONE (sdf.h's kHitGround, kHitNone).
std::string shaderPrefix(const ShaderFeatures& f);

// The complete fragment source: prefix plus shaders/march.frag with its includes expanded.
// `lines`, when given, gets each line's origin: a file of shaders/, `<defines>` for the prefix,
// `<scene code>` for the code compiled for the scene (line n of that part).
bool fragmentSource(const ShaderFeatures& f, std::string* out, std::string* error,
                    LineMap* lines = nullptr);

}  // namespace mb
