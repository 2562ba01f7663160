// test_scene_io.cpp — scene files: parsing, errors and limits, canonical saving, round trips.
#include "marchbox/scene/scene_io.h"
#include "marchbox/scene/sdf.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <unistd.h>

using namespace mb;
namespace fs = std::filesystem;

namespace {

// A version 1 file, the format's example before version 2: its box has no `static` and a mass,
// and stays still all the same (only version 1's spheres move).
const char* kExample = R"(scene version:1
camera pos:0,2.5,-7 target:0,0.8,0 fov:45
world gravity:9.81 restitution:0.7 friction:0.3
render steps:256 shadows:2 reflections:2
material name:red r:0.9 g:0.15 b:0.1 Ka:0.1 Kd:0.8 Ks:0.6 C:48 Kr:0.1
material name:mirror r:0.9 g:0.9 b:0.95 Kd:0.2 Ks:1 C:200 Kr:0.8
light pos:3,6,-4 color:1,0.95,0.9 intensity:1
light dir:-0.3,-1,0.2 color:0.4,0.45,0.6 intensity:0.5
object type:sphere material:0 pos:0,2,0 radius:0.5 mass:2 vel:1,0,0
object type:box material:1 pos:2,0.5,0 size:0.5,0.5,1.5 rot:0,30,0
object type:sphere material:1 pos:2,0.9,0 radius:0.6 static:1 op:subtract blend:0.05
- r:0.2 g:0.8 b:0.3 Ka:0.1 Kd:0.7 Ks:0.3 C:16
- type:0 material:2 pos:-1.5,3,0.5 radius:0.4 mass:1
)";

// The format's version 2 example: a body of every kind, exact turns, keyframes.
const char* kExample2 = R"(scene version:2
camera pos:0,2.5,-7 target:0,0.8,0 fov:45
keyframe t:0 pos:0,2.5,-7
keyframe t:4 pos:5,3,-4 target:0,0.5,0
world gravity:9.81 restitution:0.7 friction:0.3
render steps:256 shadows:2 reflections:2
material name:red r:0.9 g:0.15 b:0.1 Ka:0.1 Kd:0.8 Ks:0.6 C:48 Kr:0.1
material name:mirror r:0.9 g:0.9 b:0.95 Kd:0.2 Ks:1 C:200 Kr:0.8
light pos:3,6,-4 color:1,0.95,0.9 intensity:1
light dir:-0.3,-1,0.2 color:0.4,0.45,0.6 intensity:0.5
object type:sphere material:0 pos:0,2,0 radius:0.5 mass:2 vel:1,0,0
object type:box material:1 pos:2,0.5,0 size:0.5,0.5,1.5 rot:0,30,0 static:1
object type:box material:0 pos:-1,3,0 size:0.3,0.2,0.4 mass:1.5 spin:0,2,0
object type:sphere material:1 pos:2,0.9,0 radius:0.6 static:1 op:subtract blend:0.05
- r:0.2 g:0.8 b:0.3 Ka:0.1 Kd:0.7 Ks:0.3 C:16
- type:0 material:2 pos:-1.5,3,0.5 radius:0.4 mass:1
)";

const char* kMat = "material r:1 g:1 b:1";                           // one valid material, line 1
const char* kObj = "material r:1 g:1 b:1\nobject type:0 pos:0,0,0";  // an object on line 2

// A fatal failure where the text does not parse: callers that go on to index the scene wrap
// the call in ASSERT_NO_FATAL_FAILURE, so a wrong bound fails its own test and no other.
Scene parseOk(const std::string& text) {
    Scene s;
    std::vector<SceneError> errors;
    [&] {
        ASSERT_TRUE(parseScene(text, &s, &errors))
            << text << "\nfirst error: "
            << (errors.empty() ? "" : std::to_string(errors[0].line) + ": " + errors[0].message);
    }();
    return s;
}

std::vector<SceneError> parseErrors(const std::string& text) {
    Scene s;
    std::vector<SceneError> errors;
    EXPECT_FALSE(parseScene(text, &s, &errors)) << text;
    return errors;
}

// Expects `text` to fail with exactly one error, at `line`, saying `message`.
void expectError(const std::string& text, int line, const std::string& message) {
    std::vector<SceneError> errors = parseErrors(text);
    ASSERT_EQ(errors.size(), 1u) << text
                                 << "\nfirst: " << (errors.empty() ? "" : errors[0].message);
    EXPECT_EQ(errors[0].line, line) << text;
    EXPECT_EQ(errors[0].message, message) << text;
}

std::string repeatLines(const std::string& line, int n) {
    std::string text;
    for (int i = 0; i < n; ++i) text += line + "\n";
    return text;
}

std::string readBytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

//-----------------------------------------------------------------------------
// Reading
//-----------------------------------------------------------------------------
TEST(SceneParse, ExampleFromSpecLoadsWithItsValues) {
    Scene s;
    ASSERT_NO_FATAL_FAILURE(s = parseOk(kExample));
    EXPECT_EQ(s.camera.pos, glm::vec3(0, 2.5f, -7));
    EXPECT_EQ(s.camera.fov, 45.0f);
    EXPECT_EQ(s.world.restitution, 0.7f);
    EXPECT_TRUE(s.world.ground);
    EXPECT_EQ(s.render.shadows, 2);
    EXPECT_EQ(s.render.reflections, 2);
    EXPECT_EQ(s.render.epsilon, 0.001f);  // default
    ASSERT_EQ(s.materials.size(), 3u);
    EXPECT_EQ(s.materials[1].name, "mirror");
    EXPECT_EQ(s.materials[1].Ka, 0.1f);           // default
    EXPECT_EQ(s.materials[2].name, "material2");  // the legacy line, unnamed
    EXPECT_EQ(s.materials[2].color, glm::vec3(0.2f, 0.8f, 0.3f));
    EXPECT_EQ(s.materials[2].C, 16.0f);
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_FALSE(s.lights[0].directional);
    EXPECT_TRUE(s.lights[1].directional);
    EXPECT_EQ(s.lights[1].vec, glm::vec3(-0.3f, -1, 0.2f));
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_EQ(s.objects[1].type, ShapeType::Box);
    EXPECT_EQ(s.objects[1].size, glm::vec3(0.5f, 0.5f, 1.5f));
    EXPECT_EQ(s.objects[2].op, CsgOp::Subtract);
    EXPECT_EQ(s.objects[2].blend, 0.05f);
    EXPECT_TRUE(s.objects[2].isStatic);
    EXPECT_EQ(s.objects[3].material, 2);
    EXPECT_EQ(s.objects[3].pos, glm::vec3(-1.5f, 3, 0.5f));
    EXPECT_TRUE(s.objects[3].dynamic());
}

TEST(SceneParse, EmptyTextIsTheDefaultScene) {
    EXPECT_EQ(parseOk(""), Scene{});
    Scene commented;
    commented.comments.end = "\n\n# only a comment\n\n";  // kept, for the next save
    EXPECT_EQ(parseOk("\n\n# only a comment\n   \n"), commented);
}

TEST(SceneParse, CrlfCommentsBlanksTabsAndIndentAreIgnored) {
    std::string crlf = std::regex_replace(std::string(kExample), std::regex("\n"), "\r\n");
    EXPECT_EQ(parseOk(crlf), parseOk(kExample));
    Scene s = parseOk(
        "# comment\n\n  \t\n   # indented comment\r\n"
        "\tcamera\tfov:30  pos:1,2,3\t\n");
    EXPECT_EQ(s.camera.fov, 30.0f);
    EXPECT_EQ(s.camera.pos, glm::vec3(1, 2, 3));
}

TEST(SceneParse, LegacyLinesAndDashPrefix) {
    Scene s = parseOk(
        "- r:0.2 g:0.8 b:0.3 Ka:0.1 Kd:0.7 Ks:0.3 C:16\n"
        "r:1 g:1 b:1\n"
        "- type:0 material:1 pos:-1.5,3,0.5 radius:0.4 mass:1\n"
        "type:4 pos:0,0,0\n"
        "- camera fov:30\n");
    ASSERT_EQ(s.materials.size(), 2u);
    EXPECT_EQ(s.materials[0].color, glm::vec3(0.2f, 0.8f, 0.3f));
    EXPECT_EQ(s.materials[0].Kd, 0.7f);
    EXPECT_EQ(s.materials[1].name, "material1");
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(s.objects[0].type, ShapeType::Sphere);
    EXPECT_EQ(s.objects[0].material, 1);
    EXPECT_EQ(s.objects[0].radius, 0.4f);
    EXPECT_EQ(s.objects[1].type, ShapeType::Cylinder);
    EXPECT_EQ(s.camera.fov, 30.0f);
}

TEST(SceneParse, KeysInAnyOrder) {
    Scene s;
    ASSERT_NO_FATAL_FAILURE(s = parseOk("material b:0.3 name:x Kr:1 r:0.1 g:0.2\n"));
    EXPECT_EQ(s.materials[0].color, glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(s.materials[0].name, "x");
    EXPECT_EQ(s.materials[0].Kr, 1.0f);
}

TEST(SceneParse, TypeByNameOrNumberAndOpByName) {
    const char* names[] = {"sphere", "box", "torus", "capsule", "cylinder", "cone", "ellipsoid"};
    static_assert(std::size(names) == kShapeTypeCount);
    for (int i = 0; i < kShapeTypeCount; ++i) {
        std::string text = std::string("scene version:3\n") + kMat + "\nobject type:" + names[i] +
                           " pos:0,0,0\n" +
                           "object type:" + std::to_string(i) + " pos:0,0,0\n";
        Scene s;
        ASSERT_NO_FATAL_FAILURE(s = parseOk(text));
        EXPECT_EQ(s.objects[0].type, ShapeType(i));
        EXPECT_EQ(s.objects[1].type, ShapeType(i));
    }
    Scene s;
    ASSERT_NO_FATAL_FAILURE(
        s = parseOk(std::string(kObj) + " op:union\n" + "object type:0 pos:0,0,0 op:intersect\n"));
    EXPECT_EQ(s.objects[0].op, CsgOp::Union);
    EXPECT_EQ(s.objects[1].op, CsgOp::Intersect);
}

TEST(SceneParse, NumberForms) {
    Scene s;
    ASSERT_NO_FATAL_FAILURE(s = parseOk("camera pos:1,-0.25,.5 target:3e-4,+2,1E3 fov:+45\n"));
    EXPECT_EQ(s.camera.pos, glm::vec3(1, -0.25f, 0.5f));
    EXPECT_EQ(s.camera.target, glm::vec3(3e-4f, 2, 1000));
    EXPECT_EQ(s.camera.fov, 45.0f);
    // A number below the smallest float is finite: it reads as the nearest float, zero.
    EXPECT_EQ(parseOk("camera pos:1e-50,-1e-99999,0\n").camera.pos, glm::vec3(0));
}

TEST(SceneParse, WholeNumberKeysAcceptIntegerValuedNumbers) {
    Scene s;
    ASSERT_NO_FATAL_FAILURE(
        s = parseOk("scene version:1.0\nrender steps:256.0 aa:2e0 shadows:0\n"));
    EXPECT_EQ(s.render.steps, 256);
    EXPECT_EQ(s.render.aa, 2);
    EXPECT_EQ(s.render.shadows, 0);
    expectError("render steps:2.5", 1, "'steps' must be a whole number, got '2.5'");
    expectError("render steps:4096.0001", 1, "'steps' must be a whole number, got '4096.0001'");
}

TEST(SceneParse, ObjectMayComeBeforeItsMaterial) {
    Scene s;
    ASSERT_NO_FATAL_FAILURE(
        s = parseOk("object type:box pos:0,0,0 material:1\n" + repeatLines(kMat, 2)));
    EXPECT_EQ(s.objects[0].material, 1);
}

TEST(SceneParse, FailureLeavesTheSceneUntouched) {
    Scene s;
    ASSERT_NO_FATAL_FAILURE(s = parseOk(kExample));
    Scene before = s;
    std::vector<SceneError> errors;
    EXPECT_FALSE(parseScene("camera fov:10\nworld gravity:-1\n", &s, &errors));
    EXPECT_EQ(s, before);
    EXPECT_FALSE(parseScene("camera fov:10\nworld gravity:-1\n", &s, nullptr));  // errors optional
}

//-----------------------------------------------------------------------------
// Errors
//-----------------------------------------------------------------------------
TEST(SceneErrors, EachKindWithItsLine) {
    struct Case {
        std::string text;
        int line;
        const char* message;
    };
    const std::string obj = kObj;
    const Case cases[] = {
        {"camera fov:45\nsphere pos:0,0,0", 2, "unknown record kind 'sphere'"},
        {"pos:0,0,0", 1, "unknown record kind 'pos:0,0,0'"},
        {obj + " foo:1", 2, "unknown key 'foo' in object"},
        {"\nworld Gravity:1", 2, "unknown key 'Gravity' in world"},
        {"world floor2:1", 1, "unknown key 'floor2' in world"},
        {obj + " pos:1,1,1", 2, "repeated key 'pos'"},
        {kMat + std::string("\nobject pos:0,0,0"), 2, "missing required key 'type'"},
        {"material r:1 b:1", 1, "missing required key 'g'"},
        {"light color:1,1,1", 1, "light needs exactly one of 'pos' or 'dir'"},
        {"light pos:0,1,0 dir:0,-1,0", 1, "light needs exactly one of 'pos' or 'dir'"},
        {"camera fov", 1, "expected key:value, got 'fov'"},
        {"camera fov:abc", 1, "'fov' must be a number, got 'abc'"},
        {"camera fov:nan", 1, "'fov' must be a number, got 'nan'"},
        {"camera fov:inf", 1, "'fov' must be a number, got 'inf'"},
        {"camera fov:1,5", 1, "'fov' must be a number, got '1,5'"},
        {"camera fov:0x10", 1, "'fov' must be a number, got '0x10'"},
        {"camera fov:5.", 1, "'fov' must be a number, got '5.'"},
        {"camera fov:1e39", 1, "'fov' must be a number within float range, got '1e39'"},
        {"camera pos:1,2", 1, "'pos' must be a vector x,y,z, got '1,2'"},
        {"camera pos:1, 2,3", 1, "expected key:value, got '2,3'"},
        {"camera pos:1,2,-1e40", 1,
         "'pos' must be a vector of numbers within float range, got '1,2,-1e40'"},
        {"material name:a/b r:1 g:1 b:1", 1,
         "'name' must be a name of letters, digits, '_', '.' or '-', got 'a/b'"},
        {"world ground:yes", 1, "'ground' must be 0 or 1, got 'yes'"},
        {"world ground:1.0", 1, "'ground' must be 0 or 1, got '1.0'"},
        {kMat + std::string("\nobject type:prism pos:0,0,0"), 2,
         "'type' must be sphere, box, torus, capsule, cylinder, cone, ellipsoid or 0 to 6, got "
         "'prism'"},
        {kMat + std::string("\nobject type:7 pos:0,0,0"), 2,
         "'type' must be sphere, box, torus, capsule, cylinder, cone, ellipsoid or 0 to 6, got "
         "'7'"},
        {obj + " op:xor", 2, "'op' must be union, subtract or intersect, got 'xor'"},
        {obj + " material:1e12", 2,
         "'material' must be a whole number within ±2147483647, got '1e12'"},
        {obj + " material:2.5", 2, "'material' must be a whole number, got '2.5'"},
        {obj + " radius:1e-50", 2,
         "'radius' must be > 0, and '1e-50' is too small for a float: it reads as 0"},
        {"object type:0 pos:0,0,0\n" + std::string(kMat) + "\nobject type:0 pos:0,0,0 material:3",
         3, "material 3 does not exist"},
        {"object type:0 pos:0,0,0", 1, "material 0 does not exist"},
        {"camera\ncamera", 2, "second camera record"},
        {"world\n\nworld", 3, "second world record"},
        {"render\n# c\nrender", 3, "second render record"},
        {"camera\nscene version:1", 2, "'scene' must be the first record"},
        {"scene\nscene", 2, "'scene' must be the first record"},
        {"scene version:4", 1, "'version' must be 1 to 3"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.text);
        expectError(c.text, c.line, c.message);
    }
}

// `check` prints messages on a terminal: a quoted CR, ESC or NUL from the file would rewrite it,
// and a cut through a UTF-8 character would print half of one.
TEST(SceneErrors, QuotedTextHasNoControlBytesAndWholeCharacters) {
    expectError("camera fov:\x1b[2J40", 1, "'fov' must be a number, got '?[2J40'");
    expectError("camera fov:40\r fov:30", 1, "expected key:value, got 'fov:40?'");
    expectError(std::string("camera fov:4\0", 13), 1, "'fov' must be a number, got '4?'");
    const std::string e39 = std::string(39, 'e') + "\xC3\xA9";  // 'é' straddles byte 40
    expectError("camera " + e39 + ":1", 1,
                "expected key:value, got '" + std::string(39, 'e') + "...'");
}

// Every range in the spec's table: the value just outside fails, the bound itself loads.
TEST(SceneErrors, EveryRangeRejectsOutsideAndAcceptsTheBound) {
    struct Case {
        std::string base;  // a valid record, or lines ending in one, to add the key to
        const char *key, *bad, *good, *must;
    };
    const std::string obj = kObj, mat = kMat;
    const Case cases[] = {
        {"camera", "fov", "0.99", "1", "1 to 179"},
        {"camera", "fov", "179.5", "179", "1 to 179"},
        {"world", "gravity", "-0.1", "0", ">= 0"},
        {"world", "restitution", "-0.1", "0", "0 to 1"},
        {"world", "restitution", "1.01", "1", "0 to 1"},
        {"world", "friction", "-1", "0", ">= 0"},
        {"world", "rolling", "-0.001", "0", ">= 0"},
        {"render", "steps", "0", "1", "1 to 4096"},
        {"render", "steps", "4097", "4096", "1 to 4096"},
        {"render", "epsilon", "0", "1e-9", "> 0"},
        {"render", "shadows", "-1", "0", "0 to 2"},
        {"render", "shadows", "3", "2", "0 to 2"},
        {"render", "reflections", "9", "8", "0 to 8"},
        {"render", "reflections", "-1", "0", "0 to 8"},
        {"render", "fog", "-0.001", "0", ">= 0"},
        {"render", "aa", "0", "1", "1 to 4"},
        {"render", "aa", "5", "4", "1 to 4"},
        {"material g:1 b:1", "r", "-0.1", "0", ">= 0"},
        {"material r:1 b:1", "g", "-0.1", "0", ">= 0"},
        {"material r:1 g:1", "b", "-0.1", "0", ">= 0"},
        {mat, "Ka", "-0.1", "0", ">= 0"},
        {mat, "Kd", "-0.1", "0", ">= 0"},
        {mat, "Ks", "-0.1", "0", ">= 0"},
        {mat, "C", "0", "0.001", "> 0"},
        {mat, "Kr", "1.5", "1", "0 to 1"},
        {mat, "Kr", "-0.5", "0", "0 to 1"},
        {"light pos:0,0,0", "color", "1,-1,1", "0,0,0", ">= 0"},
        {"light pos:0,0,0", "intensity", "-1", "0", ">= 0"},
        {"light", "dir", "0,0,0", "0,-0.001,0", "non-zero"},
        {obj, "material", "-1", "0", ">= 0"},
        {obj, "radius", "0", "0.01", "> 0"},
        {obj, "size", "1,0,1", "1,0.1,1", "> 0"},
        {obj, "minor", "-0.1", "0.1", "> 0"},
        {obj, "height", "0", "2", "> 0"},
        {obj, "mass", "-1", "0", ">= 0"},
        {obj, "blend", "-0.1", "0", ">= 0"},
    };
    for (const Case& c : cases) {
        std::string prefix = c.base + " " + c.key + ":";
        SCOPED_TRACE(prefix + c.bad);
        int line = int(std::count(c.base.begin(), c.base.end(), '\n')) + 1;
        expectError(prefix + c.bad, line, "'" + std::string(c.key) + "' must be " + c.must);
        parseOk(prefix + c.good);
    }
}

TEST(SceneErrors, ManyErrorsComeInLineOrderAndStop) {
    std::vector<SceneError> errors = parseErrors(
        "object type:0 pos:0,0,0 material:4\ncamera fov:0 bogus:1\n" + std::string(kMat));
    ASSERT_EQ(errors.size(), 3u);
    EXPECT_EQ(errors[0].line, 1);
    EXPECT_EQ(errors[0].message, "material 4 does not exist");  // found at the end, sorted in
    EXPECT_EQ(errors[1].line, 2);
    EXPECT_EQ(errors[2].line, 2);

    errors = parseErrors("camera fov\nscene version:1\n");  // a malformed record still counts
    ASSERT_EQ(errors.size(), 2u);
    EXPECT_EQ(errors[1].message, "'scene' must be the first record");

    errors = parseErrors(repeatLines("bogus", 10000));
    ASSERT_LE(errors.size(), 101u);
    EXPECT_EQ(errors.front().line, 1);
    EXPECT_TRUE(std::is_sorted(errors.begin(), errors.end(),
                               [](auto& a, auto& b) { return a.line < b.line; }));
}

//-----------------------------------------------------------------------------
// Limits
//-----------------------------------------------------------------------------
TEST(SceneLimits, LineOf4096BytesLoadsAndOneMoreIsAnError) {
    std::string line = "camera" + std::string(4096 - 6, ' ');
    parseOk(line + "\r\n");  // the line end is not part of the line
    expectError("\n" + line + " \n", 2, "line longer than 4096 bytes");
}

TEST(SceneLimits, MegabyteLineIsAnErrorAtItsLineAndReadingGoesOn) {
    std::string huge = "object type:0 pos:" + std::string(1 << 20, '1') + ",0,0";
    std::vector<SceneError> errors =
        parseErrors(std::string(kMat) + "\n" + huge + "\nworld gravity:-1\n");
    ASSERT_EQ(errors.size(), 2u);
    EXPECT_EQ(errors[0].line, 2);
    EXPECT_EQ(errors[0].message, "line longer than 4096 bytes");
    EXPECT_EQ(errors[1].line, 3);
}

TEST(SceneLimits, LongestNumberAllowedOnALine) {
    std::string digits(4000, '1');  // regexes run on tokens this long without trouble
    expectError("camera fov:" + digits, 1,
                "'fov' must be a number within float range, got '" + digits.substr(0, 40) + "...'");
    EXPECT_NEAR(parseOk("camera fov:1." + digits).camera.fov, 1.1111111f, 1e-6f);
}

TEST(SceneLimits, Objects4096LoadAnd4097Fail) {
    std::string text = std::string(kMat) + "\n" + repeatLines("object type:0 pos:0,0,0", 4096);
    EXPECT_EQ(parseOk(text).objects.size(), 4096u);
    expectError(text + "object type:0 pos:0,0,0\n", 4098, "more than 4096 objects");
}

TEST(SceneLimits, Materials256LoadAnd257Fail) {
    std::string text = repeatLines(kMat, 256);
    Scene s;
    ASSERT_NO_FATAL_FAILURE(s = parseOk(text));
    ASSERT_EQ(s.materials.size(), 256u);
    EXPECT_EQ(s.materials[255].name, "material255");
    expectError(text + kMat, 257, "more than 256 materials");
}

TEST(SceneLimits, Lights16LoadAnd17Fail) {
    std::string text = repeatLines("light dir:0,-1,0", 16);
    EXPECT_EQ(parseOk(text).lights.size(), 16u);
    expectError(text + "light pos:1,1,1", 17, "more than 16 lights");
}

// `rolling` (SCENE_FORMAT.md, world): rolling resistance, >= 0, 0.02 when absent.
TEST(SceneParse, WorldRollingReadsAndDefaults) {
    EXPECT_EQ(parseOk("world gravity:9.81").world.rolling, 0.02f);
    EXPECT_EQ(parseOk("").world.rolling, 0.02f);
    EXPECT_EQ(World{}.rolling, 0.02f);
    EXPECT_EQ(parseOk("world rolling:0.15 friction:0.5").world.rolling, 0.15f);
    EXPECT_EQ(parseOk("world rolling:0").world.rolling, 0.0f);
    EXPECT_EQ(parseOk("world rolling:3e2").world.rolling, 300.0f);  // no upper bound
    expectError("# c\n\nworld gravity:1 rolling:-0.5", 3, "'rolling' must be >= 0");
    expectError("world rolling:fast", 1, "'rolling' must be a number, got 'fast'");
    expectError("world rolling:0.1 rolling:0.2", 1, "repeated key 'rolling'");
}

//-----------------------------------------------------------------------------
// Writing and round trips
//-----------------------------------------------------------------------------
TEST(SceneFormat, DefaultSceneCanonicalText) {
    EXPECT_EQ(formatScene(Scene{}),
              "scene version:3\n"
              "camera pos:0,2,-6 target:0,1,0 fov:50\n"
              "world gravity:9.81 restitution:0.8 friction:0.3 rolling:0.02 floor:0 ground:1\n"
              "render steps:256 epsilon:0.001 shadows:1 reflections:3 fog:0 ao:0 aa:1\n");
}

TEST(SceneFormat, EveryKeyWrittenAndUnnamedMaterialsGetTheirIndexName) {
    Scene s;
    s.materials.resize(2);
    s.materials[0].name = "red";
    s.lights.resize(1);
    s.lights[0].directional = true;
    s.lights[0].vec = glm::vec3(0, -1, 0);
    s.objects.resize(1);
    s.objects[0].op = CsgOp::Subtract;
    std::string text = formatScene(s);
    EXPECT_NE(text.find("\nmaterial name:red r:1 g:1 b:1 Ka:0.1 Kd:0.8 Ks:0.5 C:32 Kr:0\n"
                        "material name:material1 "),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("\nlight dir:0,-1,0 color:1,1,1 intensity:1\n"), std::string::npos);
    EXPECT_NE(text.find("\nobject type:sphere material:0 pos:0,0,0 radius:0.5 orient:1,0,0,0 "
                        "mass:1 vel:0,0,0 spin:0,0,0 static:0 op:subtract blend:0\n"),
              std::string::npos)
        << "a body writes orient, and a sphere only its radius" << text;
}

void expectRoundTrip(const Scene& s) {
    std::string text = formatScene(s);
    Scene again;
    ASSERT_NO_FATAL_FAILURE(again = parseOk(text));
    EXPECT_EQ(again, s);
    EXPECT_EQ(formatScene(again), text);
}

TEST(SceneFormat, SpecExampleRoundTripsExactly) {
    Scene s;
    ASSERT_NO_FATAL_FAILURE(s = parseOk(kExample));
    expectRoundTrip(s);
    EXPECT_EQ(formatScene(s).rfind("scene version:3\n", 0), 0u) << "saves write version 3";
}

TEST(SceneFormat, EveryFileInScenesRoundTripsThroughSaveAndLoad) {
    fs::path dir = fs::path(MARCHBOX_SOURCE_DIR) / "scenes";
    fs::path out = fs::temp_directory_path() / ("marchbox_roundtrip_" + std::to_string(getpid()));
    fs::create_directories(out);
    int files = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() != ".txt") continue;
        SCOPED_TRACE(entry.path().string());
        ++files;
        Scene s, again;
        std::vector<std::string> errors;
        ASSERT_TRUE(loadScene(entry.path().string(), &s, &errors)) << errors[0];
        std::string saved = (out / entry.path().filename()).string(), error;
        ASSERT_TRUE(saveScene(saved, s, &error)) << error;
        std::string first = readBytes(saved);
        ASSERT_TRUE(loadScene(saved, &again, &errors)) << errors[0];
        EXPECT_EQ(again, s);
        ASSERT_TRUE(saveScene(saved, again, &error)) << error;
        EXPECT_EQ(readBytes(saved), first);
    }
    fs::remove_all(out);
    if (files == 0) GTEST_SKIP() << "no scenes/*.txt yet; the spec example covers the round trip";
}

TEST(SceneFormat, FormatFloatShortestAndReadable) {
    EXPECT_EQ(formatFloat(0.1f), "0.1");
    EXPECT_EQ(formatFloat(1e-5f), "1e-05");
    EXPECT_EQ(formatFloat(-2.0f), "-2");
    EXPECT_EQ(formatFloat(9.81f), "9.81");
    EXPECT_EQ(formatFloat(FLT_MAX), "3.4028235e+38");
}

// Random bit patterns cover denormals, huge exponents and every mantissa shape.
TEST(SceneFormat, FormatFloatRoundTripsRandomFloats) {
    const std::regex number(R"([-+]?([0-9]+(\.[0-9]+)?|\.[0-9]+)([eE][-+]?[0-9]+)?)");
    std::mt19937 rng(12345);
    for (int i = 0; i < 200000; ++i) {
        uint32_t bits = rng();
        float v;
        std::memcpy(&v, &bits, sizeof v);
        if (!std::isfinite(v)) continue;
        std::string s = formatFloat(v);
        ASSERT_TRUE(std::regex_match(s, number)) << s;
        float back = 0;
        std::from_chars(s.data(), s.data() + s.size(), back);
        uint32_t backBits;
        std::memcpy(&backBits, &back, sizeof back);
        ASSERT_EQ(backBits, bits) << s;
    }
}

TEST(SceneFormat, RandomScenesRoundTripThroughText) {
    std::mt19937 rng(7);
    auto anyFloat = [&] {
        for (;;) {
            uint32_t bits = rng();
            float v;
            std::memcpy(&v, &bits, sizeof v);
            if (std::isfinite(v)) return v;
        }
    };
    Scene s;
    for (int i = 0; i < 500; ++i) {
        Object o;
        o.pos = glm::vec3(anyFloat(), anyFloat(), anyFloat());
        o.rot = glm::vec3(anyFloat(), anyFloat(), anyFloat());
        o.type = ShapeType(i % kShapeTypeCount);
        // A type writes only the size keys it uses: a box's radius would not come back.
        if (o.type != ShapeType::Box && o.type != ShapeType::Ellipsoid)
            o.radius = std::fabs(anyFloat()) + FLT_MIN;
        o.isStatic = true;  // a static object keeps its Euler angles, to the bit
        s.objects.push_back(o);
    }
    s.materials.resize(1);
    s.materials[0].name = "m";
    expectRoundTrip(s);
}

//-----------------------------------------------------------------------------
// Comments
//-----------------------------------------------------------------------------
// The record lines of a scene's canonical text, in order: what a commented save must hold
// between its comments.
std::vector<std::string> recordLines(Scene s) {
    s.comments = {};
    for (Material& m : s.materials) m.comment.clear();
    for (Light& l : s.lights) l.comment.clear();
    for (Object& o : s.objects) o.comment.clear();
    std::vector<std::string> lines;
    std::string text = formatScene(s);
    for (size_t start = 0, end; (end = text.find('\n', start)) != std::string::npos;
         start = end + 1)
        lines.push_back(text.substr(start, end - start + 1));
    return lines;
}

// Records out of the canonical order, a missing `world` and `render`, CRLF, trailing blanks.
const char* kCommented =
    "# Notes on the whole file\r\n"
    "scene version:1\n"
    "# the objects come first here\n"
    "object type:sphere pos:0,1,0 material:1\n"
    "  # indented, with trailing blanks \t \n"
    "object type:box pos:2,0.5,0\n"
    "\n"
    "# the camera, last in this file\n"
    "camera fov:40\n"
    "material r:1 g:0 b:0\n"
    "\t\n"
    "# blue\n"
    "- r:0 g:0 b:1\n"
    "light pos:0,5,0\n"
    "\n"
    "# the end\r\n";

TEST(SceneComments, EachRunStaysAboveItsRecordInTheCanonicalOrder) {
    Scene s;
    ASSERT_NO_FATAL_FAILURE(s = parseOk(kCommented));
    std::vector<std::string> r =
        recordLines(s);  // scene camera world render 2×material light 2×object
    ASSERT_EQ(r.size(), 9u);
    // A save starts with `scene version:1` (SCENE_FORMAT.md): the lines above it go with the
    // record that followed it, here the first object.
    EXPECT_EQ(formatScene(s), r[0] + "\n# the camera, last in this file\n" + r[1] + r[2] + r[3] +
                                  r[4] + "\n# blue\n" + r[5] + r[6] +
                                  "# Notes on the whole file\n# the objects come first here\n" +
                                  r[7] + "  # indented, with trailing blanks\n" + r[8] +
                                  "\n# the end\n");
    EXPECT_EQ(s.objects[1].comment, "  # indented, with trailing blanks\n");
    EXPECT_EQ(s.comments.end, "\n# the end\n");
}

TEST(SceneComments, RoundTripKeepsEveryCommentAndSavingTwiceGivesTheSameBytes) {
    Scene s;
    ASSERT_NO_FATAL_FAILURE(s = parseOk(kCommented));
    const std::string saved = formatScene(s);
    for (const char* note : {"# Notes on the whole file", "# the objects come first here",
                             "  # indented, with trailing blanks",
                             "# the camera, last in this file", "# blue", "# the end"})
        EXPECT_NE(saved.find(std::string(note) + "\n"), std::string::npos) << note;
    Scene again;
    ASSERT_NO_FATAL_FAILURE(again = parseOk(saved));
    EXPECT_EQ(again, s);
    EXPECT_EQ(formatScene(again), saved);
    // The example scenes carry comments of their own: each one survives a save.
    fs::path dir = fs::path(MARCHBOX_SOURCE_DIR) / "scenes";
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() != ".txt") continue;
        const std::string text = readBytes(entry.path());
        const std::string out = formatScene(parseOk(text));
        std::istringstream lines(text);
        for (std::string line; std::getline(lines, line);) {
            line.erase(line.find_last_not_of(" \t\r") + 1);
            size_t first = line.find_first_not_of(" \t");
            if (first != std::string::npos && line[first] == '#') {
                EXPECT_NE(out.find(line + "\n"), std::string::npos) << entry.path() << ": " << line;
            }
        }
    }
}

TEST(SceneComments, ADeletedRecordTakesItsCommentsAndTheEndStays) {
    Scene s;
    ASSERT_NO_FATAL_FAILURE(s = parseOk(kCommented));
    s.objects.erase(s.objects.begin());
    s.materials.pop_back();
    s.objects[0].material = 0;
    const std::string saved = formatScene(s);
    EXPECT_EQ(saved.find("# the objects come first here"), std::string::npos) << saved;
    EXPECT_EQ(saved.find("# blue"), std::string::npos) << saved;
    EXPECT_NE(saved.find("  # indented, with trailing blanks\nobject type:box"), std::string::npos);
    s.objects.clear();
    s.lights.clear();
    EXPECT_EQ(formatScene(s).substr(formatScene(s).size() - 11), "\n# the end\n");
}

TEST(SceneComments, AnythingAProgramPutsThereSavesAsCommentsThatReadBack) {
    Scene s;
    s.comments.camera = "not a comment\n  # spaced   \r\n\t \n\r# carriage\nno newline";
    s.objects.resize(1);
    s.materials.resize(1);
    s.objects[0].comment = "#" + std::string(5000, 'x') + "\n";
    const std::string saved = formatScene(s);
    EXPECT_NE(saved.find("\n# not a comment\n  # spaced\n\n# \r# carriage\n# no newline\ncamera "),
              std::string::npos)
        << saved;
    EXPECT_NE(saved.find("\n#" + std::string(kMaxLineBytes - 1, 'x') + "\nobject "),
              std::string::npos);
    Scene back;
    ASSERT_NO_FATAL_FAILURE(back = parseOk(saved));
    EXPECT_EQ(formatScene(back), saved);
    EXPECT_EQ(back.comments.camera,
              "# not a comment\n  # spaced\n\n# \r# carriage\n# no newline\n");
}

// rolling is written after friction, in the order of the spec's table, and reads back exactly.
TEST(SceneFormat, RollingIsWrittenAndRoundTrips) {
    Scene s;
    s.world.rolling = 0.0375f;
    const std::string text = formatScene(s);
    EXPECT_NE(
        text.find(
            "\nworld gravity:9.81 restitution:0.8 friction:0.3 rolling:0.0375 floor:0 ground:1\n"),
        std::string::npos)
        << text;
    expectRoundTrip(s);
    s.world.rolling = 0.0f;
    EXPECT_NE(formatScene(s).find(" rolling:0 "), std::string::npos);
    expectRoundTrip(s);
    s.world.rolling = std::nextafter(0.02f, 1.0f);
    expectRoundTrip(s);
    EXPECT_EQ(parseOk(formatScene(s)).world.rolling, s.world.rolling);
}

TEST(SceneEquality, ComparesEveryFieldExactly) {
    Scene a = parseOk(kExample), b = a;
    EXPECT_EQ(a, b);
    b.objects[3].spin.z = std::nextafter(0.0f, 1.0f);
    EXPECT_NE(a, b);
    b = a;
    b.lights[0].directional = true;
    EXPECT_NE(a, b);
    b = a;
    b.materials[2].name = "green";
    EXPECT_NE(a, b);
    b = a;
    b.objects.pop_back();
    EXPECT_NE(a, b);
    b = a;
    b.objects[0].comment = "# a note\n";
    EXPECT_NE(a, b);
    b = a;
    b.comments.end = "# a note\n";
    EXPECT_NE(a, b);
    b = a;
    b.world.rolling = 0.03f;
    EXPECT_NE(a, b);
}

//-----------------------------------------------------------------------------
// Files
//-----------------------------------------------------------------------------
class SceneFile : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("marchbox_io_" + std::to_string(getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override {
        fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add);
        fs::remove_all(dir_);
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    void write(const std::string& name, const std::string& text) const {
        std::ofstream(dir_ / name, std::ios::binary) << text;
    }
    size_t fileCount() const {
        return size_t(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
    }
    fs::path dir_;
};

TEST_F(SceneFile, LoadErrorsNameFileAndLine) {
    write("bad.txt", "camera fov:45\nworld gravity:-1\n");
    Scene s;
    std::vector<std::string> errors;
    EXPECT_FALSE(loadScene(path("bad.txt"), &s, &errors));
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0], path("bad.txt") + ":2: 'gravity' must be >= 0");
    EXPECT_EQ(s, Scene{});
}

TEST_F(SceneFile, UnreadablePathsGiveOneErrorWithoutLine) {
    std::vector<std::string> errors;
    Scene s;
    EXPECT_FALSE(loadScene(path("missing.txt"), &s, &errors));
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0], path("missing.txt") + ": cannot open: No such file or directory");
    EXPECT_FALSE(loadScene(dir_.string(), &s, &errors));
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0], dir_.string() + ": is a directory");
}

// `check` promises one line per error: a newline or ESC in the file's name shows as '?'.
TEST_F(SceneFile, ControlBytesInTheFileNameKeepEachErrorOneLine) {
    write("two\nlines\x1b.txt", "camera fov:45\nworld gravity:-1\n");
    Scene s;
    std::vector<std::string> errors;
    EXPECT_FALSE(loadScene(path("two\nlines\x1b.txt"), &s, &errors));
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0], path("two?lines?.txt") + ":2: 'gravity' must be >= 0");
    EXPECT_FALSE(loadScene(path("gone\r.txt"), &s, &errors));
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0], path("gone?.txt") + ": cannot open: No such file or directory");
    std::string error;
    EXPECT_FALSE(saveScene(path("no\ndir/scene.txt"), Scene{}, &error));
    EXPECT_EQ(error, "cannot save '" + path("no?dir/scene.txt") + "': No such file or directory");
}

TEST_F(SceneFile, HugeFileIsRefusedWithoutReadingIt) {
    std::string big = path("big.txt");
    write("big.txt", "");
    fs::resize_file(big, (size_t(64) << 20) + 1);  // sparse: costs no disk
    std::vector<std::string> errors;
    Scene s;
    EXPECT_FALSE(loadScene(big, &s, &errors));
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0], big + ": larger than 64 MiB");
}

TEST_F(SceneFile, SaveReplacesTheTargetAndLeavesNoTemporary) {
    write("scene.txt", "old contents\n");
    Scene s;
    ASSERT_NO_FATAL_FAILURE(s = parseOk(kExample));
    std::string error;
    ASSERT_TRUE(saveScene(path("scene.txt"), s, &error)) << error;
    EXPECT_EQ(readBytes(path("scene.txt")), formatScene(s));
    EXPECT_EQ(fileCount(), 1u);
}

TEST_F(SceneFile, SaveToMissingFolderFailsClearly) {
    std::string target = path("no_such_dir/scene.txt");
    std::string error;
    EXPECT_FALSE(saveScene(target, Scene{}, &error));
    EXPECT_EQ(error, "cannot save '" + target + "': No such file or directory");
    EXPECT_EQ(fileCount(), 0u);
}

// A target name so long that no temporary fits beside it: the save fails even as root.
TEST_F(SceneFile, FailedSaveLeavesTheOldFileWholeAndNoTemporary) {
    std::string name(250, 'a');
    write(name, "old contents\n");
    std::string error;
    EXPECT_FALSE(saveScene(path(name), parseOk(kExample), &error));
    EXPECT_EQ(error, "cannot save '" + path(name) + "': File name too long");
    EXPECT_EQ(readBytes(path(name)), "old contents\n");
    EXPECT_EQ(fileCount(), 1u);
}

TEST_F(SceneFile, SaveToReadOnlyFolderFailsClearly) {
    if (geteuid() == 0) GTEST_SKIP() << "root ignores folder permissions";
    write("scene.txt", "old contents\n");
    fs::permissions(dir_, fs::perms::owner_read | fs::perms::owner_exec);
    std::string error;
    EXPECT_FALSE(saveScene(path("scene.txt"), Scene{}, &error));
    EXPECT_EQ(error, "cannot save '" + path("scene.txt") + "': Permission denied");
    EXPECT_EQ(readBytes(path("scene.txt")), "old contents\n");
}

//-----------------------------------------------------------------------------
// Version 2
//-----------------------------------------------------------------------------
TEST(SceneVersion2, ExampleLoadsWithEveryShapeABodyAndKeyframesFromTheCamera) {
    Scene s;
    ASSERT_NO_FATAL_FAILURE(s = parseOk(kExample2));
    ASSERT_EQ(s.objects.size(), 5u);
    EXPECT_TRUE(s.objects[2].dynamic()) << "a version 2 box with mass moves";
    EXPECT_FALSE(s.objects[1].dynamic());
    ASSERT_EQ(s.keyframes.size(), 2u);
    EXPECT_EQ(s.keyframes[0].target, glm::vec3(0, 0.8f, 0)) << "left out: the camera's";
    EXPECT_EQ(s.keyframes[0].fov, 45.0f);
    EXPECT_EQ(s.keyframes[1].pos, glm::vec3(5, 3, -4));
    expectRoundTrip(s);
}

TEST(SceneVersion2, AVersion1BoxStaysStillAndSavesAsStatic) {
    Scene s;
    ASSERT_NO_FATAL_FAILURE(s = parseOk(kExample));
    ASSERT_GE(s.objects.size(), 2u);
    EXPECT_FALSE(s.objects[1].dynamic()) << "version 1 moved spheres only";
    EXPECT_TRUE(s.objects[0].dynamic());
    const std::string text = formatScene(s);
    EXPECT_NE(text.find("object type:box material:1 pos:2,0.5,0 size:0.5,1.5,0.5"), 0u);
    EXPECT_NE(text.find("rot:0,30,0 mass:1 vel:0,0,0 spin:0,0,0 static:1"), std::string::npos)
        << text;
}

TEST(SceneVersion2, OwnFrictionRestitutionNameAndOrientRoundTrip) {
    Scene s;
    ASSERT_NO_FATAL_FAILURE(
        s = parseOk("scene version:2\n" + std::string(kMat) +
                    "\nobject type:capsule name:peg.1 pos:0,1,0 orient:0.7071068,0,0.7071068,0 "
                    "mass:2 friction:0.9"
                    " restitution:0.1\nobject type:box pos:0,3,0 static:1 orient:1,0,0,0\n"));
    ASSERT_EQ(s.objects.size(), 2u);
    const Object& o = s.objects[0];
    EXPECT_EQ(o.name, "peg.1");
    ASSERT_TRUE(o.friction && o.restitution && o.orient);
    EXPECT_EQ(*o.friction, 0.9f);
    EXPECT_EQ(*o.restitution, 0.1f);
    EXPECT_NEAR(glm::length(*o.orient), 1.0f, 1e-7f);
    EXPECT_NEAR(o.rot.y, 90.0f, 1e-3f) << "rot shows the exact turn in degrees";
    EXPECT_FALSE(s.objects[1].friction) << "absent: the world's";
    const std::string saved = formatScene(s);
    EXPECT_NE(saved.find("name:peg.1"), std::string::npos);
    EXPECT_NE(saved.find("friction:0.9 restitution:0.1"), std::string::npos) << saved;
    EXPECT_EQ(saved.find("rot:"), std::string::npos) << "both objects hold an exact turn";
    expectRoundTrip(s);
}

TEST(SceneVersion2, EachNewErrorWithItsLine) {
    struct Case {
        std::string text;
        int line;
        const char* message;
    };
    const std::string v2 = "scene version:2\n", obj = "object type:box pos:0,0,0 ";
    const Case cases[] = {
        {v2 + obj + "rot:0,1,0 orient:1,0,0,0", 2, "an object holds 'rot' or 'orient', not both"},
        {v2 + obj + "orient:1,0,0,0.1", 2,
         "'orient' must be a unit quaternion (length within 1e-3 of 1), got '1,0,0,0.1'"},
        {v2 + obj + "orient:1,0,0", 2, "'orient' must be a quaternion w,x,y,z, got '1,0,0'"},
        {obj + "orient:1,0,0,0", 1, "'orient' needs scene version:2"},
        {obj + "name:a", 1, "'name' needs scene version:2"},
        {obj + "friction:0.5", 1, "'friction' needs scene version:2"},
        {"scene version:1\n" + obj + "restitution:0.5", 2, "'restitution' needs scene version:2"},
        {"keyframe t:1", 1, "a 'keyframe' record needs scene version:2"},
        {v2 + "keyframe t:1\nkeyframe t:0\nkeyframe t:1 fov:30", 4, "a second keyframe at t 1"},
        {v2 + "keyframe pos:0,0,0", 2, "missing required key 't'"},
        {v2 + "keyframe t:-1", 2, "'t' must be >= 0"},
        {v2 + obj + "friction:-1", 2, "'friction' must be >= 0"},
        {v2 + obj + "restitution:2", 2, "'restitution' must be 0 to 1"},
        {v2 + obj + "name:a,b", 2,
         "'name' must be a name of letters, digits, '_', '.' or '-', got 'a,b'"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.text);
        std::vector<SceneError> errors = parseErrors(c.text + "\n" + kMat);  // for material 0
        ASSERT_EQ(errors.size(), 1u) << (errors.empty() ? "" : errors[0].message);
        EXPECT_EQ(errors[0].line, c.line);
        EXPECT_EQ(errors[0].message, c.message);
    }
}

// Bodies' exact turns read back to the same floats: a load normalises only what is off by more
// than rounding (normalising twice moves the last bit).
TEST(SceneVersion2, RandomTurnsOfBodiesRoundTrip) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    Scene s;
    s.materials.resize(1);
    s.materials[0].name = "m";
    for (int i = 0; i < 300; ++i) {
        Object o;
        o.type = ShapeType::Box;
        o.orient = glm::normalize(glm::quat(u(rng), u(rng), u(rng), u(rng)));
        o.rot = eulerFromRotation(glm::mat3_cast(*o.orient));
        s.objects.push_back(o);
    }
    Scene once;
    ASSERT_NO_FATAL_FAILURE(once = parseOk(formatScene(s)));
    expectRoundTrip(once);
}
