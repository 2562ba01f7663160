// test_carved.cpp — objects a later subtraction swallows whole, and those it does not.
#include "marchbox/editor/carved.h"
#include "marchbox/scene/scene_io.h"

#include <gtest/gtest.h>

using namespace mb;

static Scene load(const char* text) {
    Scene s;
    std::vector<SceneError> errors;
    EXPECT_TRUE(parseScene(text, &s, &errors)) << (errors.empty() ? "" : errors[0].message);
    return s;
}

// A sphere of radius 0.3 at the centre of a box cut 1 m across: inside by 0.5 - 0.3 = 0.2 m.
TEST(Carved, ASphereListedBeforeASubtractionThatHoldsItIsHidden) {
    const Scene s = load("scene version:3\nmaterial r:1 g:0 b:0\n"
                         "object type:box pos:0,1,0 size:2,1,2 static:1\n"
                         "object type:sphere pos:0,1,0 radius:0.3 static:1\n"
                         "object type:box pos:0,1,0 size:0.5,0.5,0.5 op:subtract static:1\n"
                         "object type:sphere pos:3,1,0 radius:0.3 static:1\n");
    EXPECT_EQ(carvedAway(s), (std::vector<int>{-1, 2, -1, -1}));
}

TEST(Carved, OnlyWhollyInsideBeforeItInItsChainOrAChainHoldingIt) {
    const Scene s = load("scene version:3\nmaterial r:1 g:0 b:0\n"
                         // pokes out: 0.45 + 0.3 > 0.5 from the centre
                         "object type:sphere pos:0.45,1,0 radius:0.3 static:1\n"
                         "group name:g static:1\n"
                         "object in:g type:sphere pos:0,1,0 radius:0.3\n"  // the cut carves g
                         "group name:h static:1\n"
                         "object in:h type:box pos:0,1,0 size:0.5,0.5,0.5 op:subtract\n"
                         "object type:sphere pos:0,1,0 radius:0.2 static:1\n"  // not in h's chain
                         "object type:box pos:0,1,0 size:0.5,0.5,0.5 op:subtract static:1\n"
                         // after the cut: drawn over it
                         "object type:sphere pos:0,1,0 radius:0.3 static:1\n");
    EXPECT_EQ(carvedAway(s), (std::vector<int>{-1, 4, -1, 4, -1, -1}));
}
