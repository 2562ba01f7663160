// test_editor_groups.cpp — the editor on a scene with groups: every edit of the tree is one undo
// step that keeps the tree order, picking and the gizmo see members where the world does, and
// several items selected are acted on at once.
#include "marchbox/editor/editor.h"
#include "marchbox/editor/frame_cache.h"
#include "marchbox/editor/picking.h"
#include "marchbox/scene/scene_io.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

using namespace mb;

namespace {

// A cup turned a quarter about y, its handle a group in it; a ball; a static box. Objects:
// ball(0) outer(1) knob(2) inner(3) box(4); groups cup(0) handle(1).
const char* kScene =
    "scene version:3\n"
    "camera pos:0,3,-8 target:0,1,0 fov:50\n"
    "material r:1 g:0 b:0\n"
    "object type:sphere pos:-2,3,0 radius:0.5 name:ball\n"
    "group name:cup pos:2,1,0 rot:0,90,0 static:1\n"
    "object in:cup type:cylinder pos:0,0,0 radius:0.5 height:0.8 name:outer\n"
    "group name:handle in:cup pos:0,0,0.7\n"
    "object in:handle type:sphere pos:0,0,0 radius:0.2 name:knob\n"
    "object in:cup type:cylinder pos:0,0.06,0 radius:0.44 height:0.8 op:subtract name:inner\n"
    "object type:box pos:-4,0.5,0 static:1 name:box\n";

Editor editorOn(const char* text) {
    Scene s;
    std::vector<SceneError> errors;
    EXPECT_TRUE(parseScene(text, &s, &errors));
    Editor e;
    e.start(s, "");
    return e;
}

Item object(int i) { return {ItemKind::Object, i}; }
Item group(int g) { return {ItemKind::Group, g}; }

void expectInOrder(const Editor& e) {
    std::string why;
    EXPECT_TRUE(treeInOrder(e.scene(), &why)) << why;
}

void expectNear(glm::vec3 a, glm::vec3 b, float tolerance) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], tolerance) << k;
}

// Where the scene's camera shows point p, in a 640x360 view.
const glm::vec2 kView(640, 360);
glm::vec2 pixelOf(const Scene& s, glm::vec3 p) {
    glm::vec2 px;
    EXPECT_TRUE(projectToPixel(s.camera, p, kView, &px));
    return px;
}

}  // namespace

// Group, undo, redo, ungroup: each one step, the tree in order after each, undo exact.
TEST(EditorGroups, GroupAndUngroupAreUndoSteps) {
    Editor e = editorOn(kScene);
    const std::string start = formatScene(e.scene());
    e.select(ItemKind::Object, 0);
    e.toggle(object(4));
    std::string why;
    ASSERT_TRUE(e.groupSelected(&why)) << why;
    EXPECT_TRUE(e.selection().is(ItemKind::Group, 0));  // the new group, first in preorder
    EXPECT_EQ(treeItems(e.selection()).size(), 1u);
    EXPECT_EQ(e.document().history().undoLabel(), "Group");
    ASSERT_EQ(e.scene().groups.size(), 3u);
    expectInOrder(e);
    const std::string grouped = formatScene(e.scene());
    e.undo();
    EXPECT_EQ(formatScene(e.scene()), start);
    e.redo();
    EXPECT_EQ(formatScene(e.scene()), grouped);
    ASSERT_TRUE(e.ungroupSelected(&why)) << why;
    EXPECT_EQ(treeItems(e.selection()), (std::vector<Item>{object(0), object(1)}));  // in place
    expectInOrder(e);
    EXPECT_FALSE(e.ungroupSelected(&why));  // objects selected, no group
    EXPECT_EQ(why, "select a group to ungroup");
}

TEST(EditorGroups, DeleteDuplicateAndMoveKeepTheTreeAndUndo) {
    Editor e = editorOn(kScene);
    const std::string start = formatScene(e.scene());
    std::string why;
    e.select(ItemKind::Object, 2);  // the knob, in the handle
    ASSERT_TRUE(e.removeSelected(&why));
    EXPECT_TRUE(e.selection().empty());
    expectInOrder(e);
    EXPECT_EQ(e.scene().groups[1].first, groupEnd(e.scene(), 1));  // the handle, empty
    e.select(ItemKind::Group, 0);
    ASSERT_TRUE(e.duplicateSelected(&why)) << why;
    EXPECT_TRUE(e.selection().is(ItemKind::Group, 2));  // the copy, after the cup's handle
    EXPECT_EQ(e.scene().groups[2].name, "cup.001");
    expectInOrder(e);
    ASSERT_TRUE(e.reorder(group(2), -1, &why)) << why;  // above the box
    EXPECT_EQ(e.document().history().undoLabel(), "Move group up");
    expectInOrder(e);
    ASSERT_TRUE(e.moveTo(object(0), {0, 0}, &why)) << why;  // the ball into the cup, first
    EXPECT_EQ(e.document().history().undoLabel(), "Move object into group");
    EXPECT_TRUE(e.selection().is(ItemKind::Object, 0));
    EXPECT_EQ(e.scene().objects[0].group, 0);
    expectNear(worldPose(e.scene(), e.scene().objects[0]).pos, {-2, 3, 0}, 1e-5f);
    expectInOrder(e);
    for (int i = 0; i < 4; ++i) e.undo();
    EXPECT_EQ(formatScene(e.scene()), start);
}

// The knob stands at the cup's (2,1,0) plus the cup's quarter turn of (0,0,0.7): (2.7,1,0).
TEST(EditorGroups, AClickPicksAMemberWhereTheWorldSeesItThenItsGroups) {
    Editor e = editorOn(kScene);
    const Scene& s = e.scene();
    expectNear(worldPose(s, s.objects[2]).pos, {2.7f, 1, 0}, 1e-6f);
    const glm::vec2 knob = pixelOf(s, {2.7f, 1.1f, -0.15f});  // its near side, above the cup
    EXPECT_EQ(e.pick(knob, kView, Editor::Pick::Climb), 2);
    EXPECT_TRUE(e.selection().is(ItemKind::Object, 2));
    e.pick(knob, kView, Editor::Pick::Climb);  // again: its group
    EXPECT_TRUE(e.selection().is(ItemKind::Group, 1));
    e.pick(knob, kView, Editor::Pick::Climb);  // again: the group holding that
    EXPECT_TRUE(e.selection().is(ItemKind::Group, 0));
    e.pick(knob, kView, Editor::Pick::Climb);  // at the top: the object once more
    EXPECT_TRUE(e.selection().is(ItemKind::Object, 2));
    EXPECT_TRUE(e.selectParent());
    EXPECT_TRUE(e.selection().is(ItemKind::Group, 1));
    e.pick(pixelOf(s, {-2, 3, 0}), kView, Editor::Pick::Toggle);  // Shift+click adds the ball
    EXPECT_EQ(treeItems(e.selection()), (std::vector<Item>{object(0), group(1)}));
    EXPECT_TRUE(e.selection().is(ItemKind::Object, 0));
}

TEST(EditorGroups, TheGizmoMovesAMemberInTheWorld) {
    Editor e = editorOn(kScene);
    e.select(ItemKind::Object, 2);
    const glm::vec3 before = worldPose(e.scene(), e.scene().objects[2]).pos;
    GizmoFrame f;
    GizmoMode shown;
    ASSERT_TRUE(selectionGizmo(e.scene(), e.selection(), GizmoMode::Move, kView, &f, &shown));
    expectNear(f.centre, before, 1e-6f);  // the handles are where the knob shows
    const GizmoHold hold = holdSelection(e.scene(), e.selection());
    GizmoDelta d;
    d.move = {1, 0, 0};  // along world x: along the cup's -z, turned as it is
    e.dragSelection(hold, d, "Move object", 1);
    d.move = {2, 0, 0};  // the next frame of the same drag: from the press again
    e.dragSelection(hold, d, "Move object", 1);
    e.endEdit();
    expectNear(worldPose(e.scene(), e.scene().objects[2]).pos, before + glm::vec3(2, 0, 0), 1e-5f);
    EXPECT_EQ(e.scene().groups[1].pos, glm::vec3(0, 0, 0.7f));  // its group stays
    EXPECT_EQ(e.document().history().size(), 1u);               // one drag, one step
}

// A turn of the cup about its origin carries every member with it, their own poses untouched.
TEST(EditorGroups, TheGizmoTurnsAndSizesAGroupAsOne) {
    Editor e = editorOn(kScene);
    const Scene start = e.scene();
    e.select(ItemKind::Group, 0);
    const GizmoHold hold = holdSelection(e.scene(), e.selection());
    EXPECT_EQ(hold.centre, glm::vec3(2, 1, 0));
    GizmoDelta d;
    d.turn = glm::angleAxis(glm::half_pi<float>(), glm::vec3(0, 0, 1));  // about world z
    e.dragSelection(hold, d, "Rotate group", 2);
    const Scene& s = e.scene();
    for (int i = 1; i <= 3; ++i) {
        const glm::vec3 was = worldPose(start, start.objects[size_t(i)]).pos - hold.centre;
        expectNear(worldPose(s, s.objects[size_t(i)]).pos, hold.centre + d.turn * was, 1e-5f);
        EXPECT_EQ(s.objects[size_t(i)].pos, start.objects[size_t(i)].pos);
    }
    e.endEdit();
    GizmoDelta twice;
    twice.scaleAxis = 0;  // any handle sizes a group in every direction
    twice.scale = 2.0f;
    e.dragSelection(holdSelection(e.scene(), e.selection()), twice, "Scale group", 3);
    EXPECT_EQ(e.scene().objects[1].radius, 1.0f);
    EXPECT_EQ(e.scene().objects[1].height, 1.6f);
    EXPECT_EQ(e.scene().groups[1].pos, glm::vec3(0, 0, 1.4f));  // the handle twice as far out
    EXPECT_EQ(e.scene().groups[0].pos, glm::vec3(2, 1, 0));     // about its own origin
    expectInOrder(e);
}

TEST(EditorGroups, SeveralSelectedAreDeletedAndDuplicatedInOneStep) {
    Editor e = editorOn(kScene);
    std::string why;
    e.selectAll();  // the top level: ball, cup, box
    EXPECT_EQ(treeItems(e.selection()), (std::vector<Item>{object(0), object(4), group(0)}));
    ASSERT_TRUE(e.duplicateSelected(&why)) << why;
    EXPECT_EQ(e.document().history().undoLabel(), "Duplicate 3 items");
    EXPECT_EQ(e.scene().objects.size(), 10u);
    EXPECT_EQ(treeItems(e.selection()).size(), 3u);  // the copies
    expectInOrder(e);
    ASSERT_TRUE(e.removeSelected(&why));
    EXPECT_EQ(e.document().history().undoLabel(), "Delete 3 items");
    EXPECT_EQ(formatScene(e.scene()), formatScene(editorOn(kScene).scene()));
    e.undo();
    EXPECT_EQ(e.scene().objects.size(), 10u);
}

// Typing pos.x with the ball and the box selected sets x on both, each keeping its y and z.
TEST(EditorGroups, AFieldEditedWithSeveralSelectedIsSetOnEach) {
    Editor e = editorOn(kScene);
    e.select(ItemKind::Object, 4);
    e.toggle(object(2));  // the knob, a member, joins; active
    e.toggle(object(0));  // and the ball, active now
    const Object before = e.scene().objects[0];
    Object after = before;
    after.pos.x = 5.0f;
    after.isStatic = true;
    e.editObjects(before, after, 0);
    const Scene& s = e.scene();
    EXPECT_EQ(s.objects[0].pos, glm::vec3(5, 3, 0));
    EXPECT_EQ(s.objects[4].pos, glm::vec3(5, 0.5f, 0));
    EXPECT_EQ(s.objects[2].pos, glm::vec3(5, 0, 0));  // in its own group's frame
    EXPECT_FALSE(s.objects[2].isStatic);              // a member has no motion to set
    EXPECT_EQ(e.document().history().size(), 1u);
    const Group was = s.groups[0];
    Group g = was;
    e.select(ItemKind::Group, 1);
    e.toggle(group(0));  // the cup active, the handle beside it
    g.blend = 0.1f;
    e.editGroups(was, g, 0);
    EXPECT_EQ(e.scene().groups[1].blend, 0.1f);
}

TEST(EditorGroups, ABoxSelectsTheObjectsWhoseCentresItCovers) {
    Editor e = editorOn(kScene);
    const Scene& s = e.scene();
    const glm::vec2 ball = pixelOf(s, {-2, 3, 0}), box = pixelOf(s, {-4, 0.5f, 0});
    const std::vector<Item> both =
        objectsInBox(s, glm::min(ball, box) - 5.0f, glm::max(ball, box) + 5.0f, kView);
    EXPECT_EQ(both, (std::vector<Item>{object(0), object(4)}));
    e.selectItems(both, false);
    e.selectItems(
        objectsInBox(s, pixelOf(s, {2.7f, 1, 0}) - 3.0f, pixelOf(s, {2.7f, 1, 0}) + 3.0f, kView),
        true);  // Shift: the knob joins
    EXPECT_EQ(treeItems(e.selection()), (std::vector<Item>{object(0), object(2), object(4)}));
}

// At t > 0 a change of the groups is an event of the run: the start, which Save writes, keeps
// its own groups, and leaving asks first.
TEST(EditorGroups, GroupingAtATimeIsAnEditOfTheRun) {
    Editor e = editorOn(kScene);
    e.step();
    ASSERT_GT(e.document().time(), 0.0);
    e.select(ItemKind::Object, 0);
    e.toggle(object(4));
    std::string why;
    ASSERT_TRUE(e.groupSelected(&why)) << why;
    EXPECT_EQ(e.scene().groups.size(), 3u);
    EXPECT_EQ(e.document().start().groups.size(), 2u);
    EXPECT_TRUE(e.document().runEdits());
    const std::string start = formatScene(e.document().start());
    e.select(ItemKind::Group, 1);  // the cup, after the new group
    const Group was = e.scene().groups[1];
    Group cup = was;
    cup.blend = 0.2f;  // a change of a group alone is an edit of the run too
    e.editGroups(was, cup, 0);
    EXPECT_EQ(e.scene().groups[1].blend, 0.2f);
    EXPECT_EQ(formatScene(e.document().start()), start);
}

TEST(EditorGroups, AFrameKeepsADynamicGroupsMotion) {
    Scene s = editorOn(kScene).scene();
    s.groups[0].isStatic = false;
    s.groups[0].pos = {2, 0.7f, 0};
    s.groups[0].vel = {0, -1, 0};
    auto run = std::make_shared<const RunPiece>();
    FrameCache cache;
    cache.record(run, 0.5, s);
    ASSERT_EQ(cache.last()->bodies.size(), 2u);  // the ball and the cup
    Scene shown = editorOn(kScene).scene();
    applyFrame(*cache.last(), shown);
    EXPECT_EQ(shown.groups[0].pos, glm::vec3(2, 0.7f, 0));
    EXPECT_EQ(shown.groups[0].vel, glm::vec3(0, -1, 0));
    // A piece begun by an edit of the groups at its time shows them as edited.
    s.groups[1].blend = 0.3f;
    auto edited = std::make_shared<const RunPiece>(
        RunPiece{0.5, std::make_shared<const std::vector<Object>>(s.objects), run, true,
                 std::make_shared<const std::vector<Group>>(s.groups)});
    cache.record(edited, 0.6, s);
    shown = editorOn(kScene).scene();
    applyFrame(*cache.last(), shown);
    EXPECT_EQ(shown.groups[1].blend, 0.3f);
}
