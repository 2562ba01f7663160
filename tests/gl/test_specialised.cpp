// test_specialised.cpp — the shader built for a scene draws what the uber shader draws, and
// holds only the code the scene needs.
#include "golden.h"

#include "marchbox/gl/shader.h"
#include "marchbox/gl/shader_source.h"

#include <gtest/gtest.h>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

using namespace mb;

namespace {

std::string sourceFor(const Scene& s, bool uber = false) {
    std::string src, error;
    EXPECT_TRUE(fragmentSource(shaderFeatures(s, RenderMode::Shaded, uber, 65536), &src, &error))
        << error;
    return src;
}

}  // namespace

// Same maths, different control flow: only silhouettes may differ. The specialised shader meets
// plain members exactly where uber marches them to within epsilon, which moves an edge pixel by
// a shade: dominoes' thin turned boxes, all edges, reach p99 11.
TEST(Specialised, EverySceneRendersLikeTheUberShader) {
    for (const std::string& name : test::sceneNames()) {
        Scene scene = test::loadSceneOrDie("scenes/" + name + ".txt");
        Image spec = test::renderOrDie(scene, test::options(RenderMode::Shaded), 160, 90);
        Image uber = test::renderOrDie(scene, test::options(RenderMode::Shaded, true), 160, 90);
        ImageDiff d = diffImages(spec, uber);
        EXPECT_LE(d.meanAbs, 0.5) << name;
        EXPECT_LE(d.p99, 12.0) << name;
    }
}

TEST(Specialised, LeavesOutWhatTheSceneDoesNotUse) {
    Scene s;
    s.materials.push_back({});
    s.objects.push_back({});  // one sphere, no lights, no mirrors
    s.render.shadows = 1;
    s.render.reflections = 3;
    std::string src = sourceFor(s);
    EXPECT_NE(src.find("float sdSphere("), std::string::npos);
    for (const char* absent : {"sdBox(", "sdTorus(", "sdCapsule(", "sdCylinder(", "opSubtract(",
                               "opIntersect(", "hardShadow(", "softShadow(", "calcAO(", "uShadows"})
        EXPECT_EQ(src.find(absent), std::string::npos) << absent << " should be left out";
    EXPECT_NE(src.find("#define REFLECTIONS 0"), std::string::npos) << "no material reflects";
    EXPECT_EQ(src.find("REFLECTIONS;"), std::string::npos) << "no reflection loop";
}

TEST(Specialised, KeepsOnlyTheShadowKindInUse) {
    Scene s;
    s.materials.push_back({});
    s.objects.push_back({});
    s.lights.push_back({});
    s.render.shadows = 1;
    std::string hard = sourceFor(s);
    EXPECT_NE(hard.find("hardShadow("), std::string::npos);
    EXPECT_EQ(hard.find("softShadow("), std::string::npos);
    s.render.shadows = 2;
    EXPECT_NE(sourceFor(s).find("softShadow("), std::string::npos);
    std::string uber = sourceFor(s, true);
    EXPECT_NE(uber.find("uShadows"), std::string::npos);
}

// llvmpipe runs every case of the uber shader's shape switch for every object, so the uber
// program of a scene with no cone, ellipsoid, rounding or shell leaves those out (default.txt's
// uber frame: 122 ms of CPU a frame with them, 92 without), and one that uses any has them all.
TEST(Specialised, TheUberShaderHasVersion3ShapesOnlyForScenesThatUseThem) {
    Scene s = test::loadSceneOrDie("scenes/default.txt");
    std::string classic = sourceFor(s, true);
    for (const char* absent : {"sdCone(", "sdEllipsoid(", "sdRoundedBox(", "opShell("})
        EXPECT_EQ(classic.find(absent), std::string::npos) << absent;
    for (auto change : {+[](Object& o) { o.type = ShapeType::Cone; },
                        +[](Object& o) { o.type = ShapeType::Ellipsoid; },
                        +[](Object& o) { o.round = 0.01f; }, +[](Object& o) { o.shell = 0.01f; }}) {
        Scene v3 = s;
        change(v3.objects[0]);
        std::string all = sourceFor(v3, true);
        for (const char* present :
             {"float sdCone(", "float sdEllipsoid(", "float sdRoundedBox(", "float opShell("})
            EXPECT_NE(all.find(present), std::string::npos) << present;
    }
}

// The conditionals read an unknown name as 0, so a misspelt mode would quietly be the shaded
// view: every MODE_ name march.frag tests must be one the prefix defines from RenderMode.
TEST(Specialised, EveryModeNameTheShaderTestsIsDefined) {
    std::ifstream in(shaderDir() + "/march.frag");
    std::string text((std::istreambuf_iterator<char>(in)), {}), prefix = shaderPrefix({});
    const std::regex name("MODE_[A-Z]+");
    const std::sregex_iterator end;
    int tested = 0;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), name); it != end; ++it) {
        EXPECT_NE(prefix.find("#define " + it->str() + " "), std::string::npos) << it->str();
        ++tested;
    }
    EXPECT_GE(tested, kRenderModeCount - 1) << "march.frag names the views it draws";
}

// Past the uniform-block limit objects move to a storage buffer; nothing is capped silently.
TEST(Specialised, FourThousandNinetySixSpheresRender) {
    Scene s;
    s.materials.push_back({});
    s.render.shadows = 0;
    s.camera.pos = {0, 80, -1};  // from above, every sphere is in view
    s.camera.target = {0, 0, 0};
    for (int i = 0; i < kMaxObjects; ++i) {
        Object o;
        o.pos = {float(i % 64) - 32.0f, 0.4f, float(i / 64) - 32.0f};
        o.radius = 0.4f;
        s.objects.push_back(o);
    }
    ShaderFeatures f = shaderFeatures(s, RenderMode::ObjectId, false, 65536);
    EXPECT_TRUE(f.objectsInStorage);
    Image ids = test::renderOrDie(s, test::options(RenderMode::ObjectId), 320, 180);
    std::set<int> seen;
    for (int y = 0; y < ids.height; ++y)
        for (int x = 0; x < ids.width; ++x) seen.insert(objectIdAt(ids, x, y));
    std::string error;
    if (seen.size() < 4050) savePng(test::outputPath("spheres4096.ids.png"), ids, &error);
    // About 2 pixels a sphere: a few at the edges may fall between pixel centres.
    EXPECT_GE(seen.size(), 4050u) << "nearly all 4096 spheres must show, the last ones too";
}

// Exact hits tested one after another on every ray cost more than the plain members' grid walk
// past 16 spheres' worth, each type weighted by its hitCost (shader_source.h's measurements):
// 16 spheres stay compiled a line each, 17 walk the grid; 10 boxes stay, 11 walk (16.5); 4 tori
// stay, 5 walk (20); 20 boxes carved by a subtraction are marched, not met, and stay compiled.
// Planted: the fixed 64 alone (dominoes.txt's 20 boxes compiled, 2.6 times the grid's time).
TEST(Specialised, ManyObjectsMetExactlyWalkTheirGrid) {
    auto walks = [](ShapeType type, int n, CsgOp op = CsgOp::Union) {
        Scene s;
        s.materials.push_back({});
        for (int i = 0; i < n; ++i) {
            Object o;
            o.type = type;
            o.pos = {float(i % 8), 0.5f, float(i / 8)};
            o.op = i > 0 ? op : CsgOp::Union;
            s.objects.push_back(o);
        }
        const ShaderFeatures f = shaderFeatures(s, RenderMode::Shaded, false, 65536);
        EXPECT_NE(f.grid, f.compiled);
        return f.grid;
    };
    EXPECT_FALSE(walks(ShapeType::Sphere, 16));
    EXPECT_TRUE(walks(ShapeType::Sphere, 17));
    EXPECT_FALSE(walks(ShapeType::Box, 10));
    EXPECT_TRUE(walks(ShapeType::Box, 11));
    EXPECT_FALSE(walks(ShapeType::Torus, 4));
    EXPECT_TRUE(walks(ShapeType::Torus, 5));
    EXPECT_FALSE(walks(ShapeType::Box, 20, CsgOp::Subtract));
    EXPECT_TRUE(walks(ShapeType::Box, 65, CsgOp::Subtract));  // past kGridMinObjects, whatever
}
