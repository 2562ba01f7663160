// test_shader_lines.cpp — a compile error names the line a person edits: the map from the
// assembled fragment shader back to shaders/, and the driver's log rewritten through it.
#include "golden.h"

#include "marchbox/gl/glsl_conditionals.h"
#include "marchbox/gl/shader_lines.h"
#include "marchbox/gl/shader_source.h"

#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

using namespace mb;

namespace {

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::vector<std::string> fileLines(const std::string& path) {
    std::ifstream in(path);
    return splitLines(std::string((std::istreambuf_iterator<char>(in)), {}));
}

// Each line of the assembled source is the line its origin names: the file's own line, the
// prefix's, or the scene code's. An independent reading of the pieces, not of the map.
void expectEveryLineFound(const ShaderFeatures& f) {
    std::string source, error;
    LineMap map;
    ASSERT_TRUE(fragmentSource(f, &source, &error, &map)) << error;
    std::vector<std::string> lines = splitLines(source);
    ASSERT_EQ(map.size(), lines.size());
    std::map<std::string, std::vector<std::string>> origins = {
        {"<defines>", splitLines(shaderPrefix(f))},
        {"<scene code>",
         splitLines((f.compiled ? compileSceneMap(f.layout, f.shadows == 2) + "\n" : "") +
                    compileShapeSwitch(f.shapes, f.round, f.shell))}};
    for (size_t i = 0; i < lines.size(); ++i) {
        const LineOrigin& o = map[i];
        if (!origins.count(o.file)) origins[o.file] = fileLines(o.file);
        const std::vector<std::string>& file = origins[o.file];
        ASSERT_TRUE(o.line >= 1 && o.line <= int(file.size())) << o.file << ':' << o.line;
        EXPECT_EQ(lines[i], file[size_t(o.line - 1)])
            << "line " << i + 1 << " mapped to " << o.file << ':' << o.line;
    }
}

}  // namespace

TEST(ShaderLines, RewritesEachDriversLocationForm) {
    LineMap map = {{"a.glsl", 7}, {"b.glsl", 42}, {"<scene code>", 3}};
    EXPECT_EQ(rewriteShaderLog("0:2(14): error: syntax error\n0:3(1): warning: unused\n", map),
              "b.glsl:42(14): error: syntax error\n<scene code>:3(1): warning: unused\n");  // Mesa
    EXPECT_EQ(rewriteShaderLog("ERROR: 0:1: 'x' : undeclared identifier", map),  // AMD, Intel
              "ERROR: a.glsl:7: 'x' : undeclared identifier");
    EXPECT_EQ(rewriteShaderLog("0(2) : error C0000: syntax error", map),
              "b.glsl:42 : error C0000: syntax error");
}

TEST(ShaderLines, LeavesOtherLinesAndLocationsPastTheMapAlone) {
    LineMap map = {{"a.glsl", 7}};
    for (const char* log :
         {"0:2(1): error: past the end", "0:0(1): error: before the start",
          "1:1(1): error: another source string", "link error: 0:1 not at the start",
          "0:99999999999999999999(1): error: absurd", "", "\n\n"})
        EXPECT_EQ(rewriteShaderLog(log, map), log);
}

TEST(ShaderLines, RemovedConditionalLinesDoNotShiftTheMap) {
    const std::string src = "a\n#if X\nb\n#else\nc\n#endif\nd\n";
    LineMap map = linesOf("f.glsl", src);
    std::string out, error;
    ASSERT_TRUE(resolveConditionals(src, {{"X", 0}}, &out, &error, &map)) << error;
    EXPECT_EQ(out, "a\nc\nd\n");
    EXPECT_EQ(map, (LineMap{{"f.glsl", 1}, {"f.glsl", 5}, {"f.glsl", 7}}));
}

TEST(ShaderLines, ConditionalErrorsNameTheFileLine) {
    LineMap map = {{"x.glsl", 10}, {"y.glsl", 20}, {"y.glsl", 21}};
    std::string out, error;
    EXPECT_FALSE(resolveConditionals("a\n#if (A\n#endif\n", {}, &out, &error, &map));
    EXPECT_EQ(error.rfind("y.glsl:20: cannot evaluate", 0), 0u) << error;
    map = {{"x.glsl", 10}, {"y.glsl", 20}};
    EXPECT_FALSE(resolveConditionals("a\n#if A\n", {}, &out, &error, &map));
    EXPECT_EQ(error, "y.glsl:20: #if without #endif");
}

TEST(ShaderLines, EveryAssembledLineIsTheLineItsOriginNames) {
    Scene s = test::loadSceneOrDie("scenes/primitives.txt");
    ShaderFeatures compiled = shaderFeatures(s, RenderMode::Shaded, false, 65536);
    ASSERT_TRUE(compiled.compiled);
    expectEveryLineFound(compiled);
    expectEveryLineFound(shaderFeatures(s, RenderMode::Shaded, true, 65536));  // uber: shape switch
    RenderQuality grid;
    grid.grid = 1;
    expectEveryLineFound(shaderFeatures(s, RenderMode::Normals, false, 65536, grid));
}
