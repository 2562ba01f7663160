// test_glsl_conditionals.cpp — the #if resolver that trims shaders to their scene.
#include "marchbox/gl/glsl_conditionals.h"

#include <gtest/gtest.h>

using namespace mb;

static std::string resolve(const std::string& src, const Defines& d) {
    std::string out, error;
    EXPECT_TRUE(resolveConditionals(src, d, &out, &error)) << error;
    return out;
}

TEST(GlslConditionals, KeepsTheTakenBranchOfAChain) {
    const std::string src =
        "a\n#if SHADOWS == 1\nhard\n#elif SHADOWS == 2\nsoft\n#else\nnone\n#endif\nb\n";
    EXPECT_EQ(resolve(src, {{"SHADOWS", 1}}), "a\nhard\nb\n");
    EXPECT_EQ(resolve(src, {{"SHADOWS", 2}}), "a\nsoft\nb\n");
    EXPECT_EQ(resolve(src, {}), "a\nnone\nb\n");
}

TEST(GlslConditionals, NestsAndEvaluatesOperators) {
    const std::string src =
        "#if A || (B && !C)\n  #if MODE >= 4 && MODE != 5\nx\n  #endif\ny\n#endif\n";
    EXPECT_EQ(resolve(src, {{"A", 1}, {"MODE", 4}}), "x\ny\n");
    EXPECT_EQ(resolve(src, {{"B", 1}, {"C", 0}, {"MODE", 5}}), "y\n");
    EXPECT_EQ(resolve(src, {{"B", 1}, {"C", 1}}), "");
    EXPECT_EQ(resolve("#if 2 * 3 - 1 == 5 // comment\nz\n#endif\n", {}), "z\n");
}

TEST(GlslConditionals, ReportsUnbalancedAndMalformed) {
    std::string out, error;
    EXPECT_FALSE(resolveConditionals("#endif\n", {}, &out, &error));
    EXPECT_NE(error.find("without #if"), std::string::npos);
    EXPECT_FALSE(resolveConditionals("#if A\n", {}, &out, &error));
    EXPECT_FALSE(resolveConditionals("#if (A\n#endif\n", {}, &out, &error));
    EXPECT_FALSE(resolveConditionals("#if A ==\n#endif\n", {}, &out, &error));
}
