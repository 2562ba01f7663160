// test_scene_groups.cpp — format version 3: groups, their tree order, frames and local CSG, the
// new shapes' keys, and every version 3 error at its line.
#include "marchbox/scene/scene_io.h"
#include "marchbox/scene/sdf.h"

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>
#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtx/string_cast.hpp>

using namespace mb;
using glm::vec3;

namespace {

// The contract's own example.
const char* kExample3 = R"(scene version:3
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
# a cup that falls, lands and catches the ball above it
group name:cup pos:-3,0.8,0 mass:0.5
object in:cup type:cylinder material:1 pos:0,0,0 radius:0.5 height:0.8
object in:cup type:cylinder material:1 pos:0,0.06,0 radius:0.44 height:0.8 op:subtract
object type:sphere material:0 pos:-3,2.5,0 radius:0.2 mass:0.3
# a row of five posts, each a capsule on a rounded base, as one static group
group name:posts pos:3,0,2 static:1 repeat:5,1,1 spacing:0.8,1,1
object in:posts type:box material:1 pos:0,0.1,0 size:0.25,0.1,0.25 round:0.04
object in:posts type:capsule material:0 pos:0,0.8,0 radius:0.12 height:1
)";

const std::string kHead = "scene version:3\nmaterial r:1 g:1 b:1\n";  // lines 1 and 2

Scene parseOk(const std::string& text) {
    Scene s;
    std::vector<SceneError> errors;
    EXPECT_TRUE(parseScene(text, &s, &errors)) << (errors.empty() ? "" : errors[0].message);
    return s;
}

void expectError(const std::string& text, int line, const std::string& message) {
    SCOPED_TRACE(text);
    std::vector<SceneError> errors;
    ASSERT_FALSE(parseScene(text, nullptr, &errors));
    ASSERT_FALSE(errors.empty());
    EXPECT_EQ(errors[0].line, line);
    EXPECT_EQ(errors[0].message, message);
}

}  // namespace

TEST(SceneGroups, ContractExampleLoadsAsATreeAndRoundTripsExactly) {
    Scene s = parseOk(kExample3);
    ASSERT_EQ(s.groups.size(), 2u);
    EXPECT_EQ(s.groups[0].name, "cup");
    EXPECT_TRUE(s.groups[0].dynamic());
    EXPECT_EQ(s.groups[0].first, 5);
    EXPECT_EQ(groupEnd(s, 0), 7);
    EXPECT_EQ(s.objects[5].group, 0);
    EXPECT_FALSE(s.objects[5].dynamic()) << "a member moves with its group";
    EXPECT_EQ(s.objects[7].group, -1);
    EXPECT_FALSE(s.groups[1].dynamic());
    EXPECT_EQ(s.groups[1].repeat, glm::ivec3(5, 1, 1));
    EXPECT_EQ(s.objects[8].round, 0.04f);
    const std::string text = formatScene(s);
    Scene again = parseOk(text);
    EXPECT_EQ(again, s);
    EXPECT_EQ(formatScene(again), text);
    EXPECT_NE(text.find("\ngroup name:cup pos:-3,0.8,0 orient:1,0,0,0 mass:0.5 "),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("\nobject in:cup type:cylinder material:1 pos:0,0.06,0 radius:0.44 "
                        "height:0.8 rot:0,0,0 op:subtract blend:0\n"),
              std::string::npos)
        << "a member writes no motion keys\n"
        << text;
}

// Members that come later in the file are put after their group: the save reads as the tree.
TEST(SceneGroups, MembersAreStoredAndSavedInTreeOrder) {
    Scene s = parseOk(kHead +
                      "group name:a\n"
                      "object type:sphere pos:9,0,0\n"
                      "group name:b in:a\n"
                      "object in:a type:box pos:1,0,0\n"
                      "object in:b type:sphere pos:2,0,0\n"
                      "object type:sphere pos:8,0,0\n");
    // The top level is a, 9, 8 in file order; a holds b then the box; b holds the sphere at 2.
    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_EQ(s.objects[0].pos.x, 2.0f);
    EXPECT_EQ(s.objects[1].pos.x, 1.0f);
    EXPECT_EQ(s.objects[2].pos.x, 9.0f);
    EXPECT_EQ(s.objects[3].pos.x, 8.0f);
    EXPECT_EQ(s.groups[0].first, 0);
    EXPECT_EQ(s.groups[1].first, 0);
    EXPECT_EQ(groupEnd(s, 0), 2);
    EXPECT_EQ(groupEnd(s, 1), 1);
    const std::string text = formatScene(s);
    EXPECT_NE(text.find("\ngroup name:a pos:0,0,0 orient:1,0,0,0 mass:1 vel:0,0,0 spin:0,0,0 "
                        "static:0\n"
                        "group in:a name:b pos:0,0,0\n"
                        "object in:b type:sphere material:0 pos:2,0,0 radius:0.5 rot:0,0,0 "
                        "op:union blend:0\n"
                        "object in:a type:box "),
              std::string::npos)
        << text;
    EXPECT_EQ(parseOk(text), s);
}

// A member's place is its group's place plus the group's turn applied to the member's; its turn
// the group's times its own.
TEST(SceneGroups, AMemberThreeGroupsDeepStandsWhereItsGroupsPutIt) {
    Scene s = parseOk(kHead +
                      "group name:a pos:1,0,0 rot:0,90,0 static:1\n"
                      "group name:b in:a pos:0,2,0 rot:90,0,0\n"
                      "group name:c in:b pos:0,0,3\n"
                      "object in:c type:box pos:0.5,0,0 size:0.1,0.2,0.3\n");
    const Placement at = worldPose(s, s.objects[0]);
    // a turns +90° about y: x → -z, z → x. b turns +90° about x: y → z, z → -y.
    // In b's frame the member is at (0.5, 0, 3); b turns it to (0.5, -3, 0), moves it to
    // (0.5, -1, 0); a turns that to (0, -1, -0.5) and moves it to (1, -1, -0.5).
    EXPECT_NEAR(at.pos.x, 1.0f, 1e-5f);
    EXPECT_NEAR(at.pos.y, -1.0f, 1e-5f);
    EXPECT_NEAR(at.pos.z, -0.5f, 1e-5f);
    // The box's local x axis runs along world -z, its y along world x... checked by the SDF:
    // its half-extents along its own axes are 0.1, 0.2, 0.3.
    SceneSdf sdf = makeSceneSdf(s);
    const glm::mat3 turn = glm::mat3_cast(at.turn);
    for (int axis = 0; axis < 3; ++axis) {
        const float half = s.objects[0].size[axis];
        EXPECT_NEAR(mapObjects(sdf, at.pos + turn[axis] * (half + 0.05f)).d, 0.05f, 1e-4f);
    }
    EXPECT_NEAR(mapObjects(sdf, vec3(1.0f, -1.0f, -0.5f)).d, -0.1f, 1e-4f);
}

// A member's subtract carves its group only: the sphere before the group stays whole.
TEST(SceneGroups, AMembersSubtractLeavesWhatIsOutsideItsGroupWhole) {
    const std::string ball = "object type:sphere pos:0,0,0 radius:0.5 static:1\n";
    Scene grouped = parseOk(kHead + ball +
                            "group name:g static:1\n"
                            "object in:g type:box pos:3,0,0\n"
                            "object in:g type:sphere pos:0,0,0 radius:1 op:subtract\n");
    Scene flat = parseOk(kHead + ball +
                         "object type:box pos:3,0,0 static:1\n"
                         "object type:sphere pos:0,0,0 radius:1 op:subtract static:1\n");
    EXPECT_NEAR(mapObjects(makeSceneSdf(grouped), vec3(0)).d, -0.5f, 1e-6f);
    EXPECT_GT(mapObjects(makeSceneSdf(flat), vec3(0)).d, 0.0f) << "the flat chain carves it";
    EXPECT_EQ(mapObjects(makeSceneSdf(grouped), vec3(0)).object, 0);
}

// Mirror keeps the positive half, reflected; repeat unions copies centred on the group.
TEST(SceneGroups, MirrorAndRepeatPlaceTheirCopies) {
    Scene s = parseOk(kHead +
                      "group name:m mirror:x static:1\n"
                      "object in:m type:sphere pos:2,0,0 radius:0.5\n"
                      "object in:m type:sphere pos:-5,0,0 radius:0.5\n"
                      "group name:r pos:0,0,10 repeat:3,1,2 spacing:2,1,4 static:1\n"
                      "object in:r type:sphere pos:0,0,0 radius:0.25\n");
    SceneSdf sdf = makeSceneSdf(s);
    EXPECT_NEAR(mapObjects(sdf, vec3(-2, 0, 0)).d, -0.5f, 1e-6f) << "the reflected copy";
    EXPECT_GT(mapObjects(sdf, vec3(-5, 0, 0)).d, 2.0f) << "the negative half is dropped";
    for (float x : {-2.0f, 0.0f, 2.0f})
        for (float z : {8.0f, 12.0f}) EXPECT_NEAR(mapObjects(sdf, vec3(x, 0, z)).d, -0.25f, 1e-6f);
    EXPECT_NEAR(mapObjects(sdf, vec3(4, 0, 8)).d, 1.75f, 1e-5f) << "no copy past the last";
}

// A repeated group is the union of every copy, overlapping or not, though mapGroup visits only
// the copies whose bounding spheres come near (the cell holding the point, then a box about
// it). Here 7 x 5 x 3 copies, turned and mirrored, each overlapping its neighbours, against
// the minimum over all 105 at points in, around and beyond them. Planted: the box one copy
// short at its upper end, or reaching only the nearest copy's distance and not the copies'
// bound beyond it: both miss copies.
TEST(SceneGroups, ARepeatedGroupIsTheUnionOfEveryCopy) {
    Scene s = parseOk(kHead +
                      "group name:r pos:1,2,3 rot:10,20,30 mirror:x repeat:7,5,3 "
                      "spacing:0.3,0.4,0.5 static:1\n"
                      "object in:r type:box pos:0.1,0,0 size:0.25,0.1,0.3\n"
                      "object in:r type:sphere pos:0,0.2,0.1 radius:0.15\n");
    const SceneSdf sdf = makeSceneSdf(s);
    const SdfGroup& g = sdf.groups[0];
    auto everyCopy = [&](vec3 p) {
        float d = 1e10f;
        for (int k = 0; k < 3; ++k)
            for (int j = 0; j < 5; ++j)
                for (int i = 0; i < 7; ++i) {
                    vec3 q = g.toLocal * (p - g.pos) - (vec3(i, j, k) - vec3(3, 2, 1)) * g.spacing;
                    q.x = std::abs(q.x);
                    const vec3 image = g.pos + glm::transpose(g.toLocal) * q;
                    for (const SdfObject& o : sdf.objects) d = std::min(d, sdObject(o, image));
                }
        return d;
    };
    std::uint32_t seed = 12345;
    auto next = [&] { return float((seed = seed * 1664525u + 1013904223u) >> 8) / 16777216.0f; };
    for (int n = 0; n < 3000; ++n) {
        const vec3 p = g.pos + (vec3(next(), next(), next()) - 0.5f) * vec3(4.0f, 3.5f, 3.0f);
        ASSERT_NEAR(mapGroup(sdf, 0, p).d, everyCopy(p), 1e-6f)
            << "at " << p.x << "," << p.y << "," << p.z;
    }
}

// The solids' box (objectBounds: the shader's bounds, the export's default voxel) holds every
// copy of every member and no more than they reach. A sphere 10 m off its group's origin: its
// own box, not one about the origin 21 m wide. Then a turned, mirrored, repeated group holding
// a group off its origin: every point inside a solid lies in the box, and the box reaches no
// further than a member's reach past the points found inside. Planted: the box of the sphere
// about each group's origin (the old one; 21 m wide), and the copies' spread left out (a copy
// outside the box).
TEST(SceneGroups, TheSolidsBoxHoldsEveryCopyAndNoMore) {
    const Box one = objectBounds(makeSceneSdf(parseOk(kHead + "group name:g pos:0,2,0 static:1\n"
                                                              "object in:g type:sphere pos:10,0,0 "
                                                              "radius:0.5\n")));
    EXPECT_LT(glm::length(one.lo - vec3(9.5f, 1.5f, -0.5f)), 1e-5f);
    EXPECT_LT(glm::length(one.hi - vec3(10.5f, 2.5f, 0.5f)), 1e-5f);

    const SceneSdf sdf =
        makeSceneSdf(parseOk(kHead + "group name:r pos:1,2,3 rot:10,20,30 mirror:x "
                                     "repeat:4,3,2 spacing:0.6,0.5,0.7 static:1\n"
                                     "object in:r type:box pos:0.4,0,0 "
                                     "size:0.25,0.1,0.3\n"
                                     "group name:n in:r pos:2,0.5,0 rot:0,45,0\n"
                                     "object in:n type:sphere pos:0,0.3,0 "
                                     "radius:0.15\n"));
    const Box box = objectBounds(sdf);
    Box inside;
    std::uint32_t seed = 777;
    auto next = [&] { return float((seed = seed * 1664525u + 1013904223u) >> 8) / 16777216.0f; };
    for (int n = 0; n < 200000; ++n) {
        const vec3 p = vec3(1, 2, 3) + (vec3(next(), next(), next()) - 0.5f) * 12.0f;
        if (mapObjects(sdf, p).d >= 0.0f) continue;
        inside.lo = glm::min(inside.lo, p);
        inside.hi = glm::max(inside.hi, p);
    }
    ASSERT_FALSE(inside.empty());
    EXPECT_TRUE(glm::all(glm::lessThanEqual(box.lo, inside.lo)) &&
                glm::all(glm::greaterThanEqual(box.hi, inside.hi)))
        << "a solid outside the box";
    const float reach = glm::length(vec3(0.25f, 0.1f, 0.3f));  // the widest member's
    EXPECT_TRUE(glm::all(glm::greaterThan(box.lo, inside.lo - 2.0f * reach)) &&
                glm::all(glm::lessThan(box.hi, inside.hi + 2.0f * reach)))
        << "the box " << glm::to_string(box.lo) << ".." << glm::to_string(box.hi)
        << " against the solids' " << glm::to_string(inside.lo) << ".."
        << glm::to_string(inside.hi);
}

TEST(SceneGroups, RoundAndShellKeepTheirFacesInPlace) {
    Scene s = parseOk(kHead +
                      "object type:box pos:0,0,0 size:1,1,1 round:0.2 static:1\n"
                      "object type:sphere pos:5,0,0 radius:1 shell:0.1 static:1\n"
                      "object type:cone pos:0,0,5 radius:1 top:0.5 height:2 static:1\n"
                      "object type:cone pos:5,0,5 radius:0.5 height:1 round:0.1 static:1\n");
    SceneSdf sdf = makeSceneSdf(s);
    EXPECT_NEAR(mapObjects(sdf, vec3(1.5f, 0, 0)).d, 0.5f, 1e-6f) << "a face stays at x = 1";
    const float corner = glm::length(vec3(0.8f)) + 0.2f;  // the rounded corner's reach
    EXPECT_NEAR(mapObjects(sdf, glm::normalize(vec3(1)) * (corner + 0.1f)).d, 0.1f, 1e-5f);
    EXPECT_NEAR(mapObjects(sdf, vec3(5, 0, 0)).d, 0.9f, 1e-6f) << "hollow inside";
    EXPECT_NEAR(mapObjects(sdf, vec3(5.95f, 0, 0)).d, -0.05f, 1e-6f) << "mid-wall";
    EXPECT_NEAR(mapObjects(sdf, vec3(0, 2, 5)).d, 1.0f, 1e-6f) << "above the top";
    EXPECT_NEAR(mapObjects(sdf, vec3(0.75f, 0, 5)).d, 0.0f, 1e-6f) << "the slant at mid-height";
    // A pointed cone rounded by 0.1: its faces moved in by 0.1 give radii r₁ at the bottom and
    // r₂ < 0 at the top, so the inset cone ends at its apex, 0.8·r₁/(r₁ − r₂) above its base at
    // −0.4, and the rounded tip lies 0.1 above that. The base stays at −0.5.
    const float slope = 0.5f, side = 0.1f * std::sqrt(1.0f + slope * slope);
    const float r1 = 0.5f - slope * 0.1f - side, r2 = slope * 0.1f - side;
    const float tip = -0.4f + 0.8f * r1 / (r1 - r2) + 0.1f;
    EXPECT_NEAR(mapObjects(sdf, vec3(5, -0.6f, 5)).d, 0.1f, 1e-6f) << "the rounded cone's base";
    EXPECT_NEAR(mapObjects(sdf, vec3(5, 0.5f, 5)).d, 0.5f - tip, 1e-6f) << "its rounded tip";
}

TEST(SceneGroups, EachVersion3ErrorWithItsLine) {
    const std::string v2 = "scene version:2\nmaterial r:1 g:1 b:1\n";
    expectError(v2 + "group name:g", 3, "a 'group' record needs scene version:3");
    expectError(v2 + "object type:cone pos:0,0,0", 3, "'cone' needs scene version:3");
    expectError(v2 + "object type:box pos:0,0,0 round:0.1", 3, "'round' needs scene version:3");
    expectError(v2 + "object in:g type:box pos:0,0,0", 3, "'in' needs scene version:3");
    expectError(kHead + "object in:g type:box pos:0,0,0", 3,
                "'in' names no group defined above: 'g'");
    expectError(kHead + "group name:g\ngroup name:g", 4, "a second group named 'g'");
    expectError(kHead + "group pos:0,0,0", 3, "missing required key 'name'");
    expectError(kHead + "group name:g\nobject in:g type:box pos:0,0,0 mass:2", 4,
                "'mass' on a member: it moves with its group, whose top level has it");
    expectError(kHead + "group name:g\ngroup name:h in:g static:1", 4,
                "'static' on a member: it moves with its group, whose top level has it");
    std::string deep = kHead + "group name:g0\n";
    for (int i = 1; i <= 8; ++i)
        deep += "group name:g" + std::to_string(i) + " in:g" + std::to_string(i - 1) + "\n";
    expectError(deep, 11, "groups nested more than 8 deep");
    expectError(kHead + "object type:sphere pos:0,0,0 round:0.1", 3,
                "'round' is for a box, cylinder or cone, not a sphere");
    expectError(kHead + "object type:ellipsoid pos:0,0,0 round:0.1", 3,
                "'round' is for a box, cylinder or cone, not an ellipsoid");
    expectError(kHead + "object type:box pos:0,0,0 size:1,0.2,1 round:0.2", 3,
                "'round' must be less than 0.2, half the shape's smallest extent");
    expectError(kHead + "object type:cylinder pos:0,0,0 radius:1 height:1 shell:0.5", 3,
                "'shell' must be less than 0.5, half the shape's smallest extent");
    expectError(kHead + "object type:cone pos:0,0,0 radius:0.5 top:0.5", 3,
                "'top' must be less than 'radius' (0.5)");
    expectError(kHead + "group name:g repeat:65,1,1", 3, "'repeat' must be 1 to 64");
    expectError(kHead + "group name:g repeat:64,64,2", 3,
                "'repeat' makes 8192 copies, more than 4096");
    expectError(kHead + "group name:g mirror:xx", 3,
                "'mirror' must be letters x, y, z, each at most once, got 'xx'");
    expectError(kHead + "group name:g spacing:1,0,1", 3, "'spacing' must be > 0");
    expectError(kHead + "group name:g rot:0,1,0 orient:1,0,0,0", 3,
                "a group holds 'rot' or 'orient', not both");
}

// Version 2 files mean what they meant: a member-less scene has no groups and the same chain.
TEST(SceneGroups, AVersion2FileHasNoGroupsAndItsObjectsKeepTheirMeaning) {
    Scene s = parseOk(
        "scene version:2\nmaterial r:1 g:1 b:1\n"
        "object type:box pos:0,1,0 mass:1\n"
        "object type:sphere pos:0,1,0 op:subtract static:1\n");
    EXPECT_TRUE(s.groups.empty());
    EXPECT_TRUE(s.objects[0].dynamic());
    EXPECT_EQ(s.objects[1].group, -1);
}
