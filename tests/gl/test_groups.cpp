// test_groups.cpp — format version 3's groups in the GL renderer: a member's CSG carves its own
// group alone, groups that flatten draw alike through every path (compiled, uber, object grid),
// a scene whose groups do not flatten is compiled whatever is asked, and a body's group moves
// by its uniforms alone. tests/gl/test_agreement.cpp and test_reference.cpp hold the same scenes
// against the CPU mirror and the CPU reference.
#include "golden.h"

#include "marchbox/gl/scene_tree.h"
#include "marchbox/gl/shader_source.h"
#include "marchbox/scene/camera.h"
#include "marchbox/scene/sdf.h"
#include "marchbox/scene/scene_io.h"

#include <gtest/gtest.h>
#include <algorithm>
#include <chrono>
#include <thread>

using namespace mb;

namespace {

const char* const kHeader =
    "scene version:3\n"
    "camera pos:0,1.2,-3.2 target:0,0.5,0 fov:45\n"
    "render shadows:1 reflections:0\n"
    "material name:clay r:0.8 g:0.55 b:0.4\n"
    "material name:steel r:0.5 g:0.6 b:0.7\n"
    "light pos:-3,6,-5\n";

// On the left a ball (object 0, met exactly as a plain member) and an ellipsoid (1, marched);
// on the right a group whose box (2) loses its left edge to the group's own subtract, a box so
// large that it holds the ball and the ellipsoid too.
std::string localCsgScene(bool withGroup, bool withSubtract) {
    std::string s = std::string(kHeader) +
                    "object type:sphere material:0 pos:-0.75,0.5,0 radius:0.25 static:1\n"
                    "object type:ellipsoid material:0 pos:-0.2,0.5,0 size:0.2,0.3,0.2 static:1\n";
    if (withGroup)
        s += "group name:slab pos:0.6,0.5,0 static:1\n"
             "object in:slab type:box material:1 pos:0,0,0 size:0.3,0.3,0.3\n";
    if (withGroup && withSubtract)
        s += "object in:slab type:box material:1 pos:-0.85,0,0 size:0.8,0.8,0.8 op:subtract\n";
    return s;
}

int differingPixels(const Image& a, const Image& b) {
    int n = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) n += objectIdAt(a, x, y) != objectIdAt(b, x, y);
    return n;
}

// What the CPU mirror sees at each pixel's centre (as test_agreement.cpp), row 0 at the top.
std::vector<int> mirrorIds(const Scene& s, int w, int h) {
    SceneSdf sdf = makeSceneSdf(s);
    CameraBasis basis = cameraBasis(s.camera);
    std::vector<int> ids;
    for (int row = 0; row < h; ++row)
        for (int x = 0; x < w; ++x) {
            glm::vec3 dir =
                cameraRay(basis, glm::vec2(x + 0.5f, h - 1 - row + 0.5f), glm::vec2(w, h));
            ids.push_back(
                castRay(sdf, basis.pos, dir, s.render.steps, s.render.epsilon, maxRayDistance(s))
                    .object);
        }
    return ids;
}

// Object pixels whose id differs from the mirror's where the mirror sees one id over the whole
// 3x3 block: away from every silhouette, where no rounding can tip a grazing ray.
int differingInside(const Image& gpu, const std::vector<int>& cpu) {
    const int w = gpu.width;
    int n = 0;
    for (int y = 1; y + 1 < gpu.height; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            const int id = cpu[size_t(y * w + x)];
            bool inside = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) inside &= cpu[size_t((y + dy) * w + x + dx)] == id;
            const int seen = objectIdAt(gpu, x, y);
            // Floor or sky on both sides: the mirror marches the floor, which may run out of
            // steps near the horizon, where the shader meets it in closed form.
            n += inside && seen != id && (seen >= 0 || id >= 0);
        }
    return n;
}

int pixelsOf(const Image& ids, int object) {
    int n = 0;
    for (int y = 0; y < ids.height; ++y)
        for (int x = 0; x < ids.width; ++x) n += objectIdAt(ids, x, y) == object;
    return n;
}

// A table: a top and four legs, a turned group of union members only, nested one deep, then a
// ball. Every group flattens (scene_tree.h).
const char* const kTable =
    "group name:table pos:0,0,0.3 rot:0,20,0 static:1\n"
    "object in:table type:box material:0 pos:0,0.7,0 size:0.6,0.05,0.4\n"
    "group name:legs in:table pos:0,0.35,0\n"
    "object in:legs type:cylinder material:1 pos:0.5,0,0.3 radius:0.05 height:0.7\n"
    "object in:legs type:cylinder material:1 pos:-0.5,0,0.3 radius:0.05 height:0.7\n"
    "object in:legs type:cylinder material:1 pos:0.5,0,-0.3 radius:0.05 height:0.7\n"
    "object in:legs type:cylinder material:1 pos:-0.5,0,-0.3 radius:0.05 height:0.7\n"
    "object type:sphere material:1 pos:0.1,0.95,0.2 radius:0.2 static:1\n";

}  // namespace

// The bug it catches: a group's members joined onto the whole chain (the group nesting dropped),
// so that the slab's subtract carves the ball, which stands outside the group, away.
TEST(Groups, AMembersSubtractLeavesObjectsOutsideItsGroupWhole) {
    const int w = 160, h = 90;
    RenderOptions ids = test::options(RenderMode::ObjectId);
    Scene alone = test::parseSceneOrDie(localCsgScene(false, false));
    Scene carved = test::parseSceneOrDie(localCsgScene(true, true));
    Scene whole = test::parseSceneOrDie(localCsgScene(true, false));
    Image aloneIds = test::renderOrDie(alone, ids, w, h);
    const int ball = pixelsOf(aloneIds, 0), ellipsoid = pixelsOf(aloneIds, 1);
    ASSERT_GT(ball, 150) << "the ball fills part of the frame";
    ASSERT_GT(ellipsoid, 150) << "so does the ellipsoid";
    for (bool uber : {false, true}) {
        ids.uber = uber;  // a tree: compiled either way
        Image carvedIds = test::renderOrDie(carved, ids, w, h);
        // Both are whole: the same pixels as with no group at all. Measured: equal.
        EXPECT_EQ(pixelsOf(carvedIds, 0), ball) << (uber ? "uber" : "compiled");
        EXPECT_EQ(pixelsOf(carvedIds, 1), ellipsoid) << (uber ? "uber" : "compiled");
        // The subtract does carve its own group's box.
        const int box = pixelsOf(test::renderOrDie(whole, ids, w, h), 2);
        EXPECT_LT(pixelsOf(carvedIds, 2), box - 100) << "the slab loses its left part";
    }
}

// Groups of sharp unions only flatten into one chain: the compiled blocks, the uber shader's
// loop and the object grid's cells each draw what the CPU mirror's tree sees. The bug it
// catches: members packed with their own pos and turn (makeSdfObject(o)) rather than their
// group's placed in the world, or a path that leaves a group's members out of its bounds.
TEST(Groups, GroupsThatFlattenDrawAlikeThroughEveryPath) {
    const int w = 160, h = 90;
    Scene s = test::parseSceneOrDie(std::string(kHeader) + kTable);
    ASSERT_TRUE(flatChain(s));
    std::vector<int> cpu = mirrorIds(s, w, h);
    ASSERT_GT(std::count(cpu.begin(), cpu.end(), 0), 150) << "the table top shows";
    RenderOptions compiled = test::options(RenderMode::ObjectId);
    RenderOptions uber = test::options(RenderMode::ObjectId, true), grid = compiled;
    grid.quality.grid = 1;
    ASSERT_TRUE(shaderFeatures(s, RenderMode::ObjectId, false, 65536).compiled);
    ASSERT_TRUE(shaderFeatures(s, RenderMode::ObjectId, true, 65536).uber);
    ASSERT_TRUE(shaderFeatures(s, RenderMode::ObjectId, false, 65536, grid.quality).grid);
    for (const auto& [name, options] :
         {std::pair{"compiled", compiled}, std::pair{"uber", uber}, std::pair{"grid", grid}}) {
        // Measured: 0 for each.
        EXPECT_EQ(differingInside(test::renderOrDie(s, options, w, h), cpu), 0) << name;
    }
}

// Which groups flatten (scene_tree.h): sharp unions all the way down, no mirror, one copy; a
// group with no members adds nothing, whatever it would do. The bug it catches: a group judged
// by its own members alone, its member groups' carving, blends or copies let into the flat chain.
TEST(Groups, OnlySharpUnionsAllTheWayDownFlatten) {
    const std::string table = std::string(kHeader) + kTable;
    EXPECT_TRUE(flatChain(test::parseSceneOrDie(table)));
    for (const char* leg : {" op:subtract\n", " op:intersect\n", " blend:0.1\n"}) {
        std::string text = table;
        const std::string first = "height:0.7\n";
        text.replace(text.find(first), first.size(), std::string("height:0.7") + leg);
        Scene s = test::parseSceneOrDie(text);
        EXPECT_FALSE(flatChain(s)) << "a leg of the nested group with" << leg;
        EXPECT_EQ(flatGroups(s), (std::vector<bool>{false, false})) << leg;
    }
    for (const char* key : {" mirror:x", " repeat:2,1,1", " op:subtract", " blend:0.1"}) {
        std::string text = table;
        const std::string legs = "group name:legs in:table pos:0,0.35,0";
        text.replace(text.find(legs), legs.size(), legs + key);
        EXPECT_FALSE(flatChain(test::parseSceneOrDie(text))) << key;
        // The same group with no members adds nothing: it flattens.
        Scene s =
            test::parseSceneOrDie(std::string(kHeader) + "group name:empty static:1" + key + "\n");
        EXPECT_TRUE(flatChain(s)) << key;
    }
}

// The uber shader and the grid walk one flat chain: a scene whose groups carve, blend, mirror or
// repeat is compiled, for the uber shader too (`marchbox shader --uber`, `render --uber`), and
// its shader says why. The grid is never used for it, however many objects it has.
TEST(Groups, ATreeIsCompiledWhateverIsAsked) {
    Scene s = test::loadSceneOrDie("tests/scenes/groups_v3.txt");
    ASSERT_FALSE(flatChain(s));
    RenderQuality gridAlways;
    gridAlways.grid = 1;
    for (bool uber : {false, true}) {
        ShaderFeatures f = shaderFeatures(s, RenderMode::Shaded, uber, 65536, gridAlways);
        EXPECT_TRUE(f.compiled && !f.uber && !f.grid) << (uber ? "uber" : "own");
        EXPECT_EQ(f.groups, int(s.groups.size()));
        std::string src, error;
        ASSERT_TRUE(fragmentSource(f, &src, &error)) << error;
        EXPECT_NE(src.find("so this scene is always compiled"), std::string::npos);
    }
    EXPECT_EQ(shaderFeatures(s, RenderMode::Shaded, true, 65536),
              shaderFeatures(s, RenderMode::Shaded, false, 65536))
        << "one program: the editor does not build the same one twice";
}

// `marchbox shader` on groups: a block per group, named in a comment, members a line each, the
// bound test, the mirror and the copies, no table lookup in the map.
TEST(Groups, TheShaderReadsAsTheTree) {
    Scene s = test::loadSceneOrDie("tests/scenes/groups_v3.txt");
    std::string src, error;
    ASSERT_TRUE(fragmentSource(shaderFeatures(s, RenderMode::Shaded, false, 65536), &src, &error))
        << error;
    size_t begin = src.find("vec2 mapObjects(vec3 p) {"), end = src.find("\n}\n", begin);
    ASSERT_NE(begin, std::string::npos);
    std::string map = src.substr(begin, end - begin);
    EXPECT_EQ(map.find("uObjects["), std::string::npos);
    EXPECT_EQ(map.find("sdObjectLocal("), std::string::npos);
    for (const char* line : {
             "    // group 0: cup\n"
             "    if (length(p - g0.posBound.xyz) - g0.posBound.w < res.x) {\n"
             "        vec2 r0 = vec2(1e10, HIT_NONE);\n",
             "        r0 = joinSubtract(r0, sdCylinder(o1.toLocal * (p - o1.posBound.xyz), "
             "o1.shape.y, o1.shape.x), 0.0, 1.0);  // 1: cylinder, subtract, turned\n"
             "        res = joinUnion(res, r0.x, 0.0, r0.y);  // cup\n",
             "            // group 3: cap\n",  // three deep
             "    // group 4: rings, mirrored in x\n",
             "q4.x = abs(q4.x);",
             "    // group 5: cones, 3 x 1 x 1 copies\n",
             "Copies copies5 = nearestCopy(q5, g5.spacing.xyz, ivec3(3, 1, 1));",
             "sdRoundedCone(",
             "opShell(sdSphere(p - o9.posBound.xyz, o9.shape.x), o9.detail.z)",
             "sdEllipsoid(o8.toLocal * (p - o8.posBound.xyz), o8.sizeMinor.xyz)",
         })
        EXPECT_NE(map.find(line), std::string::npos) << line << "\nin\n" << map;
}

// Play moves a body's group through its uniforms alone: the same program, new pixels. Its
// members are compiled turned from the start, as a body of its own is.
TEST(Groups, MovingABodysGroupCompilesNothing) {
    Scene s = test::parseSceneOrDie(
        std::string(kHeader) +
        "group name:cup pos:0,0.45,0 mass:0.5\n"
        "object in:cup type:cylinder material:0 pos:0,0,0 radius:0.4 height:0.9\n"
        "object in:cup type:cylinder material:1 pos:0,0.08,0 radius:0.32 "
        "height:0.9 op:subtract\n");
    ASSERT_TRUE(s.groups[0].dynamic());
    ShaderFeatures before = shaderFeatures(s, RenderMode::ObjectId, false, 65536);
    for (const ObjectLayout& o : before.layout.objects) EXPECT_TRUE(o.rotated);
    EXPECT_TRUE(before.layout.groups[0].turned);
    Scene moved = s;
    moved.groups[0].pos += glm::vec3(0.3f, 0.2f, 0.1f);
    moved.groups[0].orient = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1, 0, 1)));
    EXPECT_EQ(shaderFeatures(moved, RenderMode::ObjectId, false, 65536), before);

    OffscreenContext context;
    Renderer r;
    std::string error;
    ASSERT_TRUE(context.create(1, 1, &error)) << error;
    ASSERT_TRUE(r.init(&error)) << error;
    RenderOptions ids = test::options(RenderMode::ObjectId);
    Image a, b;
    ASSERT_TRUE(renderFrame(r, s, ids, 96, 54, &a, &error)) << error;
    const Program* program = r.program();
    ASSERT_TRUE(renderFrame(r, moved, ids, 96, 54, &b, &error)) << error;
    EXPECT_EQ(r.program(), program) << "moving the body compiled a new program";
    EXPECT_GT(differingPixels(a, b), 200) << "the cup moved in the picture";
    // The moved cup as a scene of its own draws the same: the uniforms carry the whole move.
    EXPECT_EQ(differingPixels(b, test::renderOrDie(moved, ids, 96, 54)), 0);
}

// The editor draws with the uber shader while a scene's own program compiles; a tree has no
// uber program to stand in, so none is built for it and the last program keeps drawing until
// the scene's own links.
TEST(Groups, ATreeHasNoUberStandIn) {
    OffscreenContext context;
    Renderer r;
    std::string error;
    ASSERT_TRUE(context.create(1, 1, &error)) << error;
    ASSERT_TRUE(r.init(&error)) << error;
    ASSERT_TRUE(r.setScene(test::loadSceneOrDie("scenes/primitives.txt"), {}, &error)) << error;
    const Program* first = r.program();
    SceneRequest tree = r.requestFor(test::loadSceneOrDie("tests/scenes/groups_v3.txt"), {});
    EXPECT_FALSE(tree.standIn.uber);
    r.prepareUber(tree);
    EXPECT_FALSE(r.compiling()) << "no stand-in to build";
    ASSERT_TRUE(r.requestScene(tree, &error)) << error;
    EXPECT_EQ(r.program(), first) << "the last program draws on meanwhile";
    for (int i = 0; i < 6000 && r.compiling(); ++i) {  // up to a minute on a loaded llvmpipe
        ASSERT_TRUE(r.poll(&error)) << error;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    EXPECT_NE(r.program(), first) << "the scene's own program takes over once linked";
    ASSERT_NE(r.features(), nullptr);
    EXPECT_TRUE(r.features()->compiled);
}
