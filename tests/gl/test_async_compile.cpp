// test_async_compile.cpp — a feature change does not wait for the compiler: the uber program
// stands in until the scene's own program links, then takes over.
#include "golden.h"
#include "../scoped_env.h"

#include "marchbox/gl/offscreen_context.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <thread>

using namespace mb;

namespace {

// A context and a renderer already drawing `scene` with its own program.
struct Drawing {
    OffscreenContext context;
    Renderer r;
    Scene s;
    std::string error;

    void start(const char* scene) {
        ASSERT_TRUE(context.create(1, 1, &error)) << error;
        ASSERT_TRUE(r.init(&error)) << error;
        s = test::loadSceneOrDie(scene);
        ASSERT_TRUE(r.setScene(s, {}, &error)) << error;
    }
};

}  // namespace

TEST(AsyncCompile, UberStandsInUntilTheNewProgramLinks) {
    Drawing d;
    ASSERT_NO_FATAL_FAILURE(d.start("scenes/primitives.txt"));
    Renderer& r = d.r;
    Scene& s = d.s;
    std::string& error = d.error;
    r.prepareUber(r.requestFor(s, {}));
    for (int i = 0; i < 6000 && r.compiling(); ++i) {  // up to a minute on a loaded llvmpipe
        ASSERT_TRUE(r.poll(&error)) << error;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    const Program* first = r.program();

    s.render.shadows = 2;  // a new feature set: soft shadows
    ASSERT_TRUE(r.requestScene(r.requestFor(s, {}), &error)) << error;
    const Program* standIn = r.program();
    EXPECT_NE(standIn, first) << "the old program cannot draw soft shadows";
    bool linked = false;
    for (int i = 0; i < 6000 && !linked; ++i) {
        ASSERT_TRUE(r.poll(&error)) << error;
        linked = !r.compiling();
        if (!linked) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ASSERT_TRUE(linked);
    EXPECT_NE(r.program(), standIn) << "the scene's own program takes over once linked";
    EXPECT_NE(r.program(), first);
}

// Soft shadows are only compiled once a scene asks for them: break that code in a copy of
// shaders/ after the first program is built.
TEST(AsyncCompile, ABrokenShaderKeepsTheLastGoodProgramAndSaysWhy) {
    namespace fs = std::filesystem;
    fs::path dir = fs::path(test::outputPath("broken-shaders"));
    fs::remove_all(dir);
    fs::copy(test::sourcePath("shaders"), dir);
    test::ScopedEnv shaders("MARCHBOX_SHADERS", dir.c_str());
    test::ScopedCwd cwd(dir.parent_path());  // the error then names broken-shaders/raymarch.glsl
    Drawing d;
    ASSERT_NO_FATAL_FAILURE(d.start("scenes/shadows_hard.txt"));
    Renderer& r = d.r;
    Scene& s = d.s;
    std::string& error = d.error;
    const Program* good = r.program();
    std::ifstream in(dir / "raymarch.glsl");
    std::string text((std::istreambuf_iterator<char>(in)), {});
    size_t at = text.find("float softShadow(");
    text.replace(at, 17, "float softShadow(not glsl ");
    std::ofstream(dir / "raymarch.glsl") << text;
    int line = 1 + int(std::count(text.begin(), text.begin() + long(at), '\n'));

    s.render.shadows = 2;
    bool started = r.requestScene(r.requestFor(s, {}), &error), failed = false;
    for (int i = 0; started && i < 6000 && r.compiling(); ++i) failed = !r.poll(&error);
    EXPECT_TRUE(failed || !started) << "the broken shader must be reported";
    EXPECT_NE(error.find("error"), std::string::npos) << error;
    std::string where = "broken-shaders/raymarch.glsl:" + std::to_string(line) + '(';
    EXPECT_NE(error.find(where), std::string::npos) << "names " << where << ": " << error;
    EXPECT_EQ(r.program(), good) << "the last good program keeps drawing";
    std::string again;
    EXPECT_FALSE(r.requestScene(r.requestFor(s, {}), &again))
        << "the same broken features are not rebuilt";
    EXPECT_EQ(again, error);
}
