// test_scene_tree.cpp — edits of the object tree keep the scene in tree order, every item where
// it stands in the world, and the file loading.
#include "marchbox/editor/clipboard.h"
#include "marchbox/editor/scene_tree.h"
#include "marchbox/scene/scene_io.h"

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>
#include <random>

using namespace mb;

namespace {

// a, then a turned, dynamic cup holding a handle group, then an empty group and a box:
//   objects a(0) outer(1) ring(2) inner(3) b(4); groups cup(0) handle(1) empty(2).
const char* kCupScene =
    "scene version:3\n"
    "material r:1 g:0 b:0\n"
    "object type:sphere pos:0,3,0 radius:0.5 mass:3 name:a\n"
    "group name:cup pos:2,1,0 rot:0,90,0 mass:2 friction:0.5\n"
    "object in:cup type:cylinder pos:0,0,0 radius:0.5 height:0.8 name:outer\n"
    "group name:handle in:cup pos:0.6,0,0 rot:0,0,30\n"
    "object in:handle type:torus pos:0,0.1,0 radius:0.2 minor:0.05 rot:90,0,0 name:ring\n"
    "object in:cup type:cylinder pos:0,0.06,0 radius:0.44 height:0.8 op:subtract name:inner\n"
    "group name:empty static:1\n"
    "object type:box pos:-3,0.5,0 static:1 name:b\n";

Scene load(const char* text) {
    Scene s;
    std::vector<SceneError> errors;
    EXPECT_TRUE(parseScene(text, &s, &errors)) << (errors.empty() ? "" : errors[0].message);
    return s;
}

// What saving and loading would say: empty when the file loads and reads back the same.
std::string problems(const Scene& s) {
    std::string why;
    if (!treeInOrder(s, &why)) return why;
    Scene back;
    std::vector<SceneError> errors;
    if (!parseScene(formatScene(s), &back, &errors)) return errors.front().message;
    return formatScene(back) == formatScene(s) ? "" : "reads back otherwise";
}

// The tree from the raw records, apart from scene_tree's reading of it: each object's name and
// group, then each group's name, parent and first.
std::string layout(const Scene& s) {
    std::string out;
    for (const Object& o : s.objects)
        out += o.name + (o.group >= 0 ? "/" + s.groups[size_t(o.group)].name : "") + " ";
    out += "|";
    for (const Group& g : s.groups)
        out += " " + g.name + (g.parent >= 0 ? "<" + s.groups[size_t(g.parent)].name : "") + "@" +
               std::to_string(g.first);
    return out;
}

int named(const Scene& s, const std::string& name) {
    for (size_t i = 0; i < s.objects.size(); ++i)
        if (s.objects[i].name == name) return int(i);
    return -1;
}

Item object(int i) { return {ItemKind::Object, i}; }
Item group(int g) { return {ItemKind::Group, g}; }

// Every object's place in the world, by name.
std::vector<Placement> worldPlaces(const Scene& s, const std::vector<std::string>& names) {
    std::vector<Placement> out;
    for (const std::string& n : names) out.push_back(worldPose(s, s.objects[size_t(named(s, n))]));
    return out;
}

// Float noise of composing and undoing a few turns of unit size: a few ulps of 1.
void expectSamePlaces(const std::vector<Placement>& a, const std::vector<Placement>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[i].pos[k], b[i].pos[k], 1e-5f) << i;
        EXPECT_NEAR(std::abs(glm::dot(a[i].turn, b[i].turn)), 1.0f, 1e-6f)
            << i << " " << a[i].turn.w << "," << a[i].turn.x << "," << a[i].turn.y << ","
            << a[i].turn.z << " vs " << b[i].turn.w << "," << b[i].turn.x << "," << b[i].turn.y
            << "," << b[i].turn.z;
    }
}

const std::vector<std::string> kAll = {"a", "outer", "ring", "inner", "b"};

}  // namespace

TEST(SceneTree, ReadsTheTreeAsTheFileHasIt) {
    const Scene s = load(kCupScene);
    EXPECT_EQ(layout(s), "a outer/cup ring/handle inner/cup b | cup@1 handle<cup@2 empty@4");
    EXPECT_EQ(children(s, -1), (std::vector<Item>{object(0), group(0), group(2), object(4)}));
    EXPECT_EQ(children(s, 0), (std::vector<Item>{object(1), group(1), object(3)}));
    EXPECT_EQ(children(s, 2), std::vector<Item>{});
    EXPECT_EQ(spotOf(s, object(3)), (TreeSpot{0, 2}));
    EXPECT_TRUE(within(s, object(2), 0));
    EXPECT_FALSE(within(s, object(4), 0));
    EXPECT_EQ(roots(s, {object(2), object(4), group(0), object(2)}),
              (std::vector<Item>{group(0), object(4)}));  // the ring goes with its cup
    EXPECT_EQ(groupHeight(s, 0), 2);
    EXPECT_EQ(problems(s), "");
}

TEST(SceneTree, TreeInOrderNamesWhatIsOutOfStep) {
    std::string why;
    Scene s = load(kCupScene);
    s.objects[1].group = -1;  // outer says the top level, but stands inside the cup's run
    EXPECT_FALSE(treeInOrder(s, &why));
    EXPECT_EQ(why, "object 1 is out of tree order");
    s = load(kCupScene);
    s.groups[1].parent = 2;  // after its parent in the list: not preorder
    EXPECT_FALSE(treeInOrder(s, &why));
    EXPECT_EQ(why, "group 1 does not follow its parent");
    s = load(kCupScene);
    s.groups[2].first = 1;  // the empty group claims a place inside the cup
    EXPECT_FALSE(treeInOrder(s, &why));
}

TEST(SceneTree, InsertPutsAnObjectInItsGroupsRun) {
    Scene s = load(kCupScene);
    Object o;
    o.name = "new";
    o.mass = 5.0f;
    Renumbering r;
    std::string why;
    const int i = insertObject(s, o, {1, -1}, &r, &why);
    EXPECT_EQ(i, 3);
    EXPECT_EQ(layout(s),
              "a outer/cup ring/handle new/handle inner/cup b | cup@1 handle<cup@2 empty@5");
    EXPECT_EQ(s.objects[3].mass, 1.0f);  // a member has no mass of its own
    EXPECT_EQ(r(object(3)), object(4));  // inner moved down one
    EXPECT_EQ(problems(s), "");
}

TEST(SceneTree, EraseTakesAGroupWithEverythingInIt) {
    Scene s = load(kCupScene);
    Renumbering r = eraseItems(s, {group(0), object(2)});  // the ring goes with the cup anyway
    EXPECT_EQ(layout(s), "a b | empty@1");
    EXPECT_EQ(r.objects, (std::vector<int>{0, -1, -1, -1, 1}));
    EXPECT_EQ(r.groups, (std::vector<int>{-1, -1, 0}));
    EXPECT_EQ(problems(s), "");
    s = load(kCupScene);
    eraseItems(s, {object(0), object(2)});
    EXPECT_EQ(layout(s), "outer/cup inner/cup b | cup@0 handle<cup@1 empty@2");
    EXPECT_EQ(problems(s), "");
}

// The cup is turned 90 degrees about y and its handle 30 about z: the frames differ in turn.
TEST(SceneTree, MovingIntoAndOutOfAGroupKeepsTheWorldPlace) {
    Scene s = load(kCupScene);
    const std::vector<Placement> before = worldPlaces(s, kAll);
    Renumbering r;
    std::string why;
    ASSERT_TRUE(moveItem(s, object(4), {1, 0}, &r, &why)) << why;  // b into the handle, first
    EXPECT_EQ(layout(s), "a outer/cup b/handle ring/handle inner/cup | cup@1 handle<cup@2 empty@5");
    expectSamePlaces(worldPlaces(s, kAll), before);
    EXPECT_FALSE(s.objects[2].isStatic);  // a member's motion keys are the defaults
    EXPECT_EQ(problems(s), "");
    ASSERT_TRUE(moveItem(s, object(2), {-1, -1}, &r, &why)) << why;  // out, to the end
    expectSamePlaces(worldPlaces(s, kAll), before);
    const Object& b = s.objects[size_t(named(s, "b"))];
    EXPECT_TRUE(b.dynamic());  // as the cup it left
    EXPECT_EQ(b.mass, 2.0f);
    EXPECT_EQ(b.friction, 0.5f);
    EXPECT_EQ(problems(s), "");
}

TEST(SceneTree, AGroupCannotGoInsideItself) {
    Scene s = load(kCupScene);
    const std::string was = layout(s);
    Renumbering r;
    std::string why;
    EXPECT_FALSE(moveItem(s, group(0), {1, 0}, &r, &why));
    EXPECT_EQ(why, "a group cannot go inside itself");
    EXPECT_FALSE(moveItem(s, group(0), {0, 0}, &r, &why));
    EXPECT_EQ(layout(s), was);
}

TEST(SceneTree, GroupsNestNoDeeperThanTheFileAllows) {
    Scene s = load("scene version:3\nmaterial r:1 g:1 b:1\nobject type:sphere pos:1,2,3\n");
    Renumbering r;
    std::string why;
    Item top = object(0);
    for (int depth = 1; depth <= kMaxGroupDepth; ++depth) {
        const int g = groupItems(s, {top}, &r, &why);
        ASSERT_EQ(g, 0) << why;  // the new group is the outermost: first in preorder
        top = group(g);
    }
    EXPECT_EQ(groupDepth(s, kMaxGroupDepth - 1), kMaxGroupDepth);
    EXPECT_EQ(worldPose(s, s.objects[0]).pos, glm::vec3(1, 2, 3));
    EXPECT_EQ(groupItems(s, {top}, &r, &why), -1);
    EXPECT_EQ(why, "groups nest at most 8 deep");
    EXPECT_EQ(problems(s), "");
}

TEST(SceneTree, ShiftMovesAmongSiblingsAGroupAsAWhole) {
    Scene s = load(kCupScene);
    Renumbering r;
    std::string why;
    ASSERT_TRUE(shiftItem(s, group(1), -1, &r, &why)) << why;
    EXPECT_EQ(layout(s), "a ring/handle outer/cup inner/cup b | cup@1 handle<cup@1 empty@4");
    EXPECT_FALSE(shiftItem(s, object(3), 1, &r, &why));
    EXPECT_EQ(why, "object 3 is already last");
    ASSERT_TRUE(shiftItem(s, group(0), 2, &r, &why)) << why;  // past the empty group and b
    EXPECT_EQ(layout(s), "a b ring/handle outer/cup inner/cup | empty@1 cup@2 handle<cup@2");
    EXPECT_EQ(problems(s), "");
}

TEST(SceneTree, DuplicateCopiesAGroupWithEverythingInIt) {
    Scene s = load(kCupScene);
    std::vector<Item> copies;
    Renumbering r;
    std::string why;
    ASSERT_TRUE(duplicateItems(s, {group(0), object(1)}, {1, 0, 0}, &copies, &r, &why)) << why;
    EXPECT_EQ(copies, std::vector<Item>{group(3)});  // outer is in the cup: copied with it
    EXPECT_EQ(layout(s),
              "a outer/cup ring/handle inner/cup b outer.001/cup.001 ring.001/handle.001 inner.001/cup.001"
              " | cup@1 handle<cup@2 empty@4 cup.001@5 handle.001<cup.001@6");
    EXPECT_EQ(groupPose(s, 3).pos, groupPose(s, 0).pos + glm::vec3(1, 0, 0));
    EXPECT_EQ(s.objects[6].pos, s.objects[2].pos);  // members keep their place in the group
    EXPECT_EQ(problems(s), "");

    ASSERT_TRUE(duplicateItems(s, {object(2)}, {1, 0, 0}, &copies, &r, &why)) << why;
    EXPECT_EQ(copies, std::vector<Item>{object(3)});  // last in the handle
    const glm::vec3 moved = worldPose(s, s.objects[3]).pos - worldPose(s, s.objects[2]).pos;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(moved[k], k == 0 ? 1.0f : 0.0f, 1e-6f);
    EXPECT_EQ(problems(s), "");
}

TEST(SceneTree, GroupingKeepsEveryObjectWhereItStands) {
    Scene s = load(kCupScene);
    const std::vector<Placement> before = worldPlaces(s, kAll);
    Renumbering r;
    std::string why;
    const int g = groupItems(s, {object(4), object(0)}, &r, &why);  // in tree order: a, b
    ASSERT_EQ(g, 0) << why;
    EXPECT_EQ(layout(s),
              "a/group b/group outer/cup ring/handle inner/cup"
              " | group@0 cup@2 handle<cup@3 empty@5");
    EXPECT_EQ(s.groups[0].pos, glm::vec3(-1.5f, 1.75f, 0));  // at their centre
    EXPECT_TRUE(s.groups[0].isStatic);                       // until ticked dynamic
    EXPECT_EQ(s.groups[0].mass, 3.0f);                       // a's: b was static
    EXPECT_FALSE(s.objects[1].isStatic);                     // members have no motion
    expectSamePlaces(worldPlaces(s, kAll), before);
    EXPECT_EQ(r(object(4)), object(1));
    EXPECT_EQ(problems(s), "");

    // Inside the turned cup: the new group stands where outer stood, in the cup's frame.
    const int inner = groupItems(s, {object(2), object(4)}, &r, &why);
    ASSERT_GE(inner, 0) << why;
    EXPECT_EQ(layout(s),
              "a/group b/group outer/group2 inner/group2 ring/handle"
              " | group@0 cup@2 group2<cup@2 handle<cup@4 empty@5");
    expectSamePlaces(worldPlaces(s, kAll), before);
    EXPECT_EQ(problems(s), "");
}

TEST(SceneTree, UngroupPutsTheChildrenInItsPlace) {
    Scene s = load(kCupScene);
    const std::vector<Placement> before = worldPlaces(s, kAll);
    Renumbering r;
    std::string why;
    ASSERT_TRUE(ungroup(s, 0, &r, &why)) << why;
    EXPECT_EQ(layout(s), "a outer ring/handle inner b | handle@2 empty@4");
    expectSamePlaces(worldPlaces(s, kAll), before);
    EXPECT_TRUE(s.objects[1].dynamic());  // the cup's motion, each
    EXPECT_EQ(s.objects[1].mass, 2.0f);
    EXPECT_TRUE(s.groups[0].dynamic());
    EXPECT_EQ(r.groups, (std::vector<int>{-1, 0, 1}));
    EXPECT_EQ(problems(s), "");
    EXPECT_FALSE(ungroup(s, 5, &r, &why));
}

// Hundreds of edits chosen at random, each checked: the tree order holds and the file loads.
TEST(SceneTree, EveryEditKeepsTheTreeInOrderAndTheFileLoading) {
    Scene s = load(kCupScene);
    std::mt19937 rng(7);
    auto pick = [&](int n) { return int(rng() % unsigned(std::max(n, 1))); };
    auto anyItem = [&] {
        const bool g = !s.groups.empty() && rng() % 3 == 0;
        return g ? group(pick(int(s.groups.size()))) : object(pick(int(s.objects.size())));
    };
    Renumbering r;
    std::vector<Item> copies;
    std::string why;
    for (int step = 0; step < 400; ++step) {
        const TreeSpot spot{pick(int(s.groups.size()) + 1) - 1, pick(6) - 1};
        switch (step % 7) {
            case 0:
                insertObject(s, Object{}, spot, &r, &why);
                break;
            case 1:
                if (s.objects.size() > 4) eraseItems(s, {anyItem()});
                break;
            case 2:
                moveItem(s, anyItem(), spot, &r, &why);
                break;
            case 3:
                shiftItem(s, anyItem(), pick(3) - 1, &r, &why);
                break;
            case 4:
                if (s.objects.size() < 40)
                    duplicateItems(s, {anyItem()}, {1, 0, 0}, &copies, &r, &why);
                break;
            case 5:
                groupItems(s, {anyItem(), anyItem()}, &r, &why);
                break;
            case 6:
                if (!s.groups.empty() && rng() % 2)
                    ungroup(s, pick(int(s.groups.size())), &r, &why);
                break;
        }
        ASSERT_EQ(problems(s), "") << "after step " << step;
    }
}

//-----------------------------------------------------------------------------
// Copy and paste as scene text
//-----------------------------------------------------------------------------
static void expectSamePose(const Placement& a, const Placement& b) {
    EXPECT_NEAR(glm::distance(a.pos, b.pos), 0.0f, 1e-5f);
    EXPECT_NEAR(std::abs(glm::dot(a.turn, b.turn)), 1.0f, 1e-6f);
}

TEST(Clipboard, ACopyPastedIntoAnotherSceneStandsWhereItStood) {
    const Scene from = load(kCupScene);
    const std::string text = copyText(from, {group(0), object(4)});
    Scene to = load("scene version:3\nmaterial name:steel r:0.5 g:0.5 b:0.5\n"
                    "object type:sphere pos:0,1,0\n");
    std::vector<Item> pasted;
    std::string why;
    ASSERT_TRUE(pasteText(to, text, &pasted, &why)) << why;
    EXPECT_EQ(layout(to), " outer/cup ring/handle inner/cup b | cup@1 handle<cup@2");
    EXPECT_EQ(pasted, (std::vector<Item>{group(0), object(4)}));
    EXPECT_EQ(problems(to), "");
    expectSamePose(itemPose(to, object(3)), itemPose(from, object(3)));  // inner, two deep
    EXPECT_EQ(to.materials.size(), 2u);  // the cup's red came along
    EXPECT_EQ(to.materials[size_t(to.objects[1].material)].color, glm::vec3(1, 0, 0));
    EXPECT_EQ(to.groups[0].mass, 2.0f);  // the body's keys too
}

TEST(Clipboard, AMemberCopiedAloneComesOutWhereItStandsInTheWorld) {
    const Scene from = load(kCupScene);
    Scene to = load("scene version:3\nmaterial r:1 g:0 b:0\n");
    std::vector<Item> pasted;
    std::string why;
    ASSERT_TRUE(pasteText(to, copyText(from, {object(2)}), &pasted, &why)) << why;
    ASSERT_EQ(to.objects.size(), 1u);
    EXPECT_EQ(to.objects[0].group, -1);
    expectSamePose(itemPose(to, object(0)), itemPose(from, object(2)));
    EXPECT_EQ(to.materials.size(), 1u);  // "material0" in both: matched by name
}

TEST(Clipboard, PastedIntoItsOwnSceneTheCopiesTakeFreshNames) {
    Scene s = load(kCupScene);
    std::vector<Item> pasted;
    std::string why;
    ASSERT_TRUE(pasteText(s, copyText(s, {group(0)}), &pasted, &why)) << why;
    EXPECT_EQ(layout(s), "a outer/cup ring/handle inner/cup b outer.001/cup.001 "
                         "ring.001/handle.001 inner.001/cup.001 | cup@1 handle<cup@2 empty@4 "
                         "cup.001@5 handle.001<cup.001@6");
    EXPECT_EQ(problems(s), "");
}

TEST(Clipboard, RecordsTypedWithoutAHeaderPasteAsTheCurrentVersion) {
    Scene s = load(kCupScene);
    std::vector<Item> pasted;
    std::string why;
    ASSERT_TRUE(pasteText(s, "object type:box pos:1,2,3 name:typed\n", &pasted, &why)) << why;
    ASSERT_EQ(pasted, std::vector<Item>{object(5)});
    EXPECT_TRUE(s.objects[5].dynamic());  // version 1 would load a box static
    EXPECT_EQ(s.objects[5].pos, glm::vec3(1, 2, 3));
}

TEST(Clipboard, TextThatIsNoSceneIsRefusedAndChangesNothing) {
    Scene s = load(kCupScene);
    const std::string before = formatScene(s);
    std::vector<Item> pasted;
    std::string why;
    EXPECT_FALSE(pasteText(s, "hello there\n", &pasted, &why));
    EXPECT_EQ(why.rfind("the clipboard holds no scene text (line 1: ", 0), 0u) << why;
    EXPECT_FALSE(pasteText(s, "camera pos:0,1,-5 target:0,0,0\n", &pasted, &why));
    EXPECT_EQ(why, "the clipboard's scene text holds no objects");
    EXPECT_EQ(formatScene(s), before);
}
