// test_scene_edit.cpp — Edit menu commands keep the scene loadable.
#include "marchbox/editor/scene_edit.h"
#include "marchbox/editor/selection.h"
#include "marchbox/scene/scene_io.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

using namespace mb;

// What saving and loading would say about the scene: empty when it loads.
static std::string problems(const Scene& s) {
    Scene back;
    std::vector<SceneError> errors;
    if (parseScene(formatScene(s), &back, &errors)) return "";
    return errors.front().message;
}

static Scene threeMaterials() {
    Scene s;
    std::string why;
    for (int i = 0; i < 3; ++i) addItem(s, ItemKind::Material, &why);
    for (int m = 0; m < 3; ++m) {
        Object o;
        o.material = m;
        s.objects.push_back(o);
    }
    return s;
}

TEST(SceneEdit, AddingAnObjectBringsAMaterial) {
    Scene s;
    std::string why;
    EXPECT_EQ(addItem(s, ItemKind::Object, &why), 0);
    EXPECT_EQ(s.materials.size(), 1u);
    EXPECT_EQ(problems(s), "");
}

TEST(SceneEdit, NewSceneLoads) {
    Scene s = newScene();
    EXPECT_EQ(problems(s), "");
    EXPECT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.lights.size(), 1u);
}

TEST(SceneEdit, AnEmptySceneHasTheGroundAndOneLightAndLoads) {
    Scene s = emptyScene();
    EXPECT_EQ(problems(s), "");
    EXPECT_TRUE(s.objects.empty());
    EXPECT_TRUE(s.world.ground);
    EXPECT_EQ(s.lights.size(), 1u);
}

// A new type rests where the old one stood: its lowest point, turned as the object is, stays.
TEST(SceneEdit, ARetypedObjectKeepsItsLowestPoint) {
    Object sphere;  // r = 0.5 on the ground
    sphere.pos = {1, 0.5f, 2};
    sphere.height = 1.0f;
    Object capsule = retyped(sphere, ShapeType::Capsule);
    EXPECT_EQ(capsule.type, ShapeType::Capsule);
    EXPECT_FLOAT_EQ(capsule.pos.y, 0.5f + 0.5f);  // r + h/2
    EXPECT_EQ(glm::vec2(capsule.pos.x, capsule.pos.z), glm::vec2(1, 2));
    EXPECT_FLOAT_EQ(retyped(capsule, ShapeType::Cylinder).pos.y, 0.5f);  // h/2
    EXPECT_FLOAT_EQ(retyped(capsule, ShapeType::Box).pos.y, 0.5f);       // size.y
    EXPECT_FLOAT_EQ(retyped(capsule, ShapeType::Torus).pos.y, 0.1f);     // the tube, lying
    EXPECT_FLOAT_EQ(retyped(capsule, ShapeType::Sphere).pos.y, 0.5f);    // back as it was

    Object lying = sphere;  // turned 90 degrees about z: local y lies along x
    lying.rot = {0, 0, 90};
    lying.radius = 0.2f;
    lying.pos.y = 2.2f;  // in the air: the lowest point is 2 m up, not on the ground
    EXPECT_NEAR(retyped(lying, ShapeType::Capsule).pos.y, 2.2f, 1e-6f);   // r, lying
    EXPECT_NEAR(retyped(lying, ShapeType::Cylinder).pos.y, 2.2f, 1e-6f);  // r, lying
    EXPECT_NEAR(retyped(lying, ShapeType::Torus).pos.y, 2.3f, 1e-6f);     // R + minor, on edge

    Object box = sphere;  // a cube of half side 0.5 turned 45 degrees about z stands on an edge
    box.type = ShapeType::Box;
    box.rot = {0, 0, 45};
    box.pos.y = 0.5f * std::sqrt(2.0f);
    EXPECT_NEAR(retyped(box, ShapeType::Sphere).pos.y, 0.5f, 1e-6f);
}

TEST(SceneEdit, DeletingAMaterialRenumbersObjects) {
    Scene s = threeMaterials();
    std::string why;
    ASSERT_TRUE(deleteItem(s, ItemKind::Material, 1, &why));
    EXPECT_EQ(s.objects[0].material, 0);
    EXPECT_EQ(s.objects[1].material, 0);  // used the deleted one
    EXPECT_EQ(s.objects[2].material, 1);
    EXPECT_EQ(problems(s), "");
}

TEST(SceneEdit, LastMaterialStaysWhileObjectsNeedIt) {
    Scene s;
    std::string why;
    addItem(s, ItemKind::Object, &why);
    EXPECT_FALSE(deleteItem(s, ItemKind::Material, 0, &why));
    EXPECT_EQ(why, "the objects need at least one material");
    clearItems(s, ItemKind::Material);
    EXPECT_EQ(s.materials.size(), 1u);
    EXPECT_EQ(problems(s), "");
}

TEST(SceneEdit, ListsStopAtTheirLimits) {
    Scene s;
    std::string why;
    for (int i = 0; i < kMaxLights; ++i) ASSERT_GE(addItem(s, ItemKind::Light, &why), 0);
    EXPECT_EQ(addItem(s, ItemKind::Light, &why), -1);
    EXPECT_EQ(why, "a scene holds at most 16 lights");
    EXPECT_EQ(duplicateItem(s, ItemKind::Light, 0, &why), -1);
    EXPECT_EQ(int(s.lights.size()), kMaxLights);
}

TEST(SceneEdit, DuplicateAppendsAMovedCopy) {
    Scene s = newScene();
    std::string why;
    int copy = duplicateItem(s, ItemKind::Object, 0, &why);
    ASSERT_EQ(copy, 1);
    EXPECT_EQ(s.objects[1].pos, s.objects[0].pos + glm::vec3(1, 0, 0));
    EXPECT_EQ(duplicateItem(s, ItemKind::Object, 7, &why), -1);
    EXPECT_EQ(why, "no object 7");
}

TEST(SceneEdit, RandomVelocitiesTouchOnlyDynamicBodies) {
    Scene s = threeMaterials();
    s.objects[1].isStatic = true;
    s.objects[2].type = ShapeType::Box;  // a box with a mass moves too
    EXPECT_EQ(randomizeVelocities(s, 1), 2);
    EXPECT_NE(s.objects[0].vel, glm::vec3(0.0f));
    EXPECT_EQ(s.objects[1].vel, glm::vec3(0.0f));
    EXPECT_NE(s.objects[2].vel, glm::vec3(0.0f));
    Scene again = threeMaterials();
    again.objects[1].isStatic = true;
    again.objects[2].type = ShapeType::Box;
    randomizeVelocities(again, 1);
    EXPECT_EQ(again.objects[0].vel, s.objects[0].vel);  // seeded: repeatable
}

TEST(Selection, FollowsItsItemThroughDeletes) {
    Selection sel{ItemKind::Object, 3};
    selectionAfterDelete(sel, ItemKind::Material, 0);
    EXPECT_EQ(sel.index, 3);
    selectionAfterDelete(sel, ItemKind::Object, 1);
    EXPECT_EQ(sel.index, 2);
    selectionAfterDelete(sel, ItemKind::Object, 2);
    EXPECT_TRUE(sel.empty());
}

TEST(Selection, ClampsToTheList) {
    Scene s = newScene();
    Selection sel{ItemKind::Light, 4};
    selectionClamp(sel, s);
    EXPECT_TRUE(sel.empty());
    sel = {ItemKind::Object, 0};
    selectionClamp(sel, s);
    EXPECT_EQ(sel.object(), 0);
}

// A drag in the Objects list moves a row several places; the rows it passes close up behind.
TEST(SceneEdit, ReorderMovesAnObjectPastSeveralKeepingTheOthersInOrder) {
    Scene s;
    for (int i = 0; i < 4; ++i) s.objects.emplace_back().name = std::to_string(i);
    auto order = [&] {
        std::string o;
        for (const Object& obj : s.objects) o += obj.name;
        return o;
    };
    std::string why;
    EXPECT_EQ(reorderObject(s, 0, 3, &why), 3);
    EXPECT_EQ(order(), "1230");
    EXPECT_EQ(reorderObject(s, 3, -2, &why), 1);
    EXPECT_EQ(order(), "1023");
    EXPECT_EQ(reorderObject(s, 1, 3, &why), -1);  // past the end: refused, nothing moved
    EXPECT_EQ(order(), "1023");
}

TEST(SceneEdit, ACopyIsNamedAsBlenderNamesIt) {
    std::vector<std::string> names = {"box", "box.001", "lamp.7"};
    auto used = [&](const std::string& n) {
        return std::find(names.begin(), names.end(), n) != names.end();
    };
    EXPECT_EQ(copyName("box", used), "box.002");  // box.001 is taken
    EXPECT_EQ(copyName("box.001", used), "box.002");
    EXPECT_EQ(copyName("ball", used), "ball.001");
    EXPECT_EQ(copyName("lamp.7", used), "lamp.7.001");  // not Blender's three digits
    EXPECT_EQ(copyName("", used), "");
}

// A group's mirror, repeat and spacing edited with several groups selected go to each, a
// vector's parts one by one, as every other field does.
TEST(SceneEdit, AGroupsCopiesEditedGoToEachSelectedGroup) {
    Scene s;
    s.groups.resize(2);
    s.groups[0].name = "a", s.groups[1].name = "b";
    s.groups[1].repeat = {1, 3, 1};
    Group before = s.groups[0], after = before;
    after.mirror.x = true;
    after.repeat.x = 4;
    after.spacing.z = 2.5f;
    applyGroupEdit(s, {0, 1}, before, after);
    for (const Group& g : s.groups) {
        EXPECT_EQ(g.mirror, glm::bvec3(true, false, false)) << g.name;
        EXPECT_EQ(g.spacing, glm::vec3(1, 1, 2.5f)) << g.name;
    }
    EXPECT_EQ(s.groups[0].repeat, glm::ivec3(4, 1, 1));
    EXPECT_EQ(s.groups[1].repeat, glm::ivec3(4, 3, 1));  // its own y count stays
}
