// test_history.cpp — the snapshot undo stack and the document's dirty flag.
#include "marchbox/editor/document.h"
#include "marchbox/editor/history.h"

#include <gtest/gtest.h>

using namespace mb;

static Scene withGravity(float g) {
    Scene s;
    s.world.gravity = g;
    return s;
}

TEST(History, UndoRedoWalkTheSteps) {
    History h;
    h.push("a", withGravity(1), withGravity(2));
    h.push("b", withGravity(2), withGravity(3));
    ASSERT_TRUE(h.canUndo());
    EXPECT_EQ(h.undoLabel(), "b");
    EXPECT_EQ(h.undo()->before.world.gravity, 2.0f);
    EXPECT_EQ(h.undo()->before.world.gravity, 1.0f);
    EXPECT_EQ(h.undo(), nullptr);
    EXPECT_EQ(h.redo()->after.world.gravity, 2.0f);
    EXPECT_EQ(h.redoLabel(), "b");
}

TEST(History, EqualScenesAreNoStep) {
    History h;
    h.push("nothing", withGravity(1), withGravity(1));
    EXPECT_FALSE(h.canUndo());
}

TEST(History, NewStepDropsRedo) {
    History h;
    h.push("a", withGravity(1), withGravity(2));
    h.undo();
    h.push("c", withGravity(1), withGravity(5));
    EXPECT_FALSE(h.canRedo());
    EXPECT_EQ(h.size(), 1u);
}

TEST(History, MergeKeyFoldsADragUntilSealed) {
    History h;
    h.push("drag", withGravity(1), withGravity(2), 7);
    h.push("drag", withGravity(2), withGravity(3), 7);
    EXPECT_EQ(h.size(), 1u);
    h.seal();
    h.push("drag", withGravity(3), withGravity(4), 7);
    EXPECT_EQ(h.size(), 2u);
    EXPECT_EQ(h.undo()->before.world.gravity, 3.0f);
    EXPECT_EQ(h.undo()->before.world.gravity, 1.0f);
}

TEST(History, LengthIsBounded) {
    History h(3);
    for (int i = 0; i < 10; ++i) h.push("s", withGravity(float(i)), withGravity(float(i + 1)));
    EXPECT_EQ(h.size(), 3u);
    int undone = 0;
    while (h.undo()) ++undone;
    EXPECT_EQ(undone, 3);
}

TEST(Document, DirtyFollowsUndoBackToTheSavedState) {
    Document d;
    d.replace(withGravity(1), "a.txt");
    EXPECT_FALSE(d.dirty());
    d.apply("g", [](Scene& s) { s.world.gravity = 4; });
    EXPECT_TRUE(d.dirty());
    d.undo();
    EXPECT_FALSE(d.dirty());
    d.redo();
    EXPECT_TRUE(d.dirty());
    d.markSaved("a.txt");
    EXPECT_FALSE(d.dirty());
    d.undo();
    EXPECT_TRUE(d.dirty());  // the saved file has gravity 4
}

TEST(Document, MergedDragAfterSaveIsDirty) {
    Document d;
    d.apply(
        "drag", [](Scene& s) { s.world.friction = 1; }, 9);
    d.markSaved("a.txt");
    d.apply(
        "drag", [](Scene& s) { s.world.friction = 2; }, 9);
    EXPECT_TRUE(d.dirty());
}

TEST(Document, UndoKeepsTheViewUnlessTheStepMovedIt) {
    Document d;
    d.apply("g", [](Scene& s) { s.world.gravity = 2; });
    d.live().camera.pos = {5, 5, 5};  // looking around
    d.undo();
    EXPECT_EQ(d.scene().world.gravity, 9.81f);
    EXPECT_EQ(d.scene().camera.pos, glm::vec3(5, 5, 5));

    d.apply("fov", [](Scene& s) { s.camera.fov = 30; });
    d.undo();
    EXPECT_EQ(d.scene().camera.fov, 50.0f);
}

// A simulation running since the last save is unsaved work at once: quitting mid-run asks.
// The camera alone never is, though it is saved with the scene.
TEST(Document, LiveChangesAreUnsavedAtOnceButTheCameraNever) {
    Document d;
    Scene before = d.scene();
    d.live().camera.pos = {4, 4, 4};
    EXPECT_FALSE(d.dirty());
    d.live().world.floor = 1;
    EXPECT_TRUE(d.dirty());
    d.commit("run", before);
    EXPECT_TRUE(d.dirty());
    d.undo();
    EXPECT_EQ(d.scene().world.floor, 0.0f);
    EXPECT_FALSE(d.dirty());
}

TEST(Document, EditsThatComeBackToTheFileLeaveNothingUnsaved) {
    Document d;
    d.replace(withGravity(1), "a.txt");
    d.apply("g", [](Scene& s) { s.world.gravity = 4; });
    d.apply("g back", [](Scene& s) { s.world.gravity = 1; });
    EXPECT_EQ(d.history().size(), 2u);
    EXPECT_FALSE(d.dirty());
}
