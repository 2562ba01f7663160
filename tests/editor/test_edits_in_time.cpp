// test_edits_in_time.cpp — what the fields show at a time of the run, and edits made there that
// cannot change the motion.
#include "editor_session.h"

#include "marchbox/editor/picking.h"
#include "marchbox/scene/sdf.h"

#include <cmath>
#include <glm/gtc/quaternion.hpp>

using namespace mb;
using namespace mb::test;

// A box tumbling as it falls: its turn changes every frame.
static const char* kTumbler =
    "scene version:3\n"
    "material r:1 g:0 b:0\n"
    "object type:box pos:0,4,0 size:0.5,0.2,0.3 rot:0,0,-30 spin:2,1,5\n";

// The turn rot's angles give, against the exact one: 1 where they are the same turn.
static float agreement(const Object& o) {
    return std::abs(glm::dot(glm::quat_cast(rotationFromEuler(o.rot)), *o.orient));
}

// The domino scrubbed to 0.60 s showed pos, vel and spin of that time and rot of the start.
TEST(EditsInTime, TheTurnShownIsTheFramesAtEveryTime) {
    Editor e = openEditor(writeFile("tumbler.txt", kTumbler));
    run(e, 60);
    const auto check = [&](const char* when) {
        const Object& o = e.scene().objects[0];
        ASSERT_TRUE(o.orient) << when;
        EXPECT_GT(agreement(o), 1.0f - 1e-6f) << when << ": rot " << o.rot.x << "," << o.rot.y
                                               << "," << o.rot.z;
    };
    check("paused");
    ASSERT_TRUE(e.seek(0.6));
    check("scrubbed");
    ASSERT_TRUE(e.seek(0.3));
    e.undo();
    check("undone");
    e.togglePlay();
    for (int i = 0; i < 7; ++i) e.frame(1.0 / 60);
    check("playing over the bake");
    e.togglePlay();
}

// Angles typed or loaded stay as they are while the body has not turned: (83.8, 169.8, 116.8)
// and (-96.2, 10.2, -63.2) are the same turn, and only the first is what the user wrote.
TEST(EditsInTime, TurnsStayAsLoadedUntilTheBodyTurns) {
    Editor e = openEditor(writeFile("still.txt",
                                    "scene version:3\nworld gravity:0\nmaterial r:1 g:0 b:0\n"
                                    "object type:box pos:0,4,0 rot:83.8,169.8,116.8\n"));
    run(e, 30);
    const Object& o = e.scene().objects[0];
    ASSERT_TRUE(o.orient);
    EXPECT_EQ(o.rot, glm::vec3(83.8f, 169.8f, 116.8f));
}

TEST(EditsInTime, AnglesOfAnExactTurnHaveNoMinusZero) {
    const glm::quat aboutY = glm::angleAxis(glm::radians(30.0f), glm::vec3(0, 1, 0));
    const glm::vec3 shown = anglesShowing(aboutY, glm::vec3(0, 0, 45));
    EXPECT_NEAR(shown.y, 30.0f, 1e-4f);
    EXPECT_FALSE(std::signbit(shown.x));
    EXPECT_FALSE(std::signbit(shown.z));
}

// A box renamed at t = 1.95 s cut a 10 s run back to 1.95 s, and Save left the name out.
TEST(EditsInTime, ARenameAtALaterTimeKeepsTheRunAndIsSaved) {
    const std::string path = writeFile("rename.txt", kScene);
    Editor e = openEditor(path);
    run(e, 60);
    ASSERT_TRUE(e.seek(0.5));
    const glm::vec3 at = e.scene().objects[0].pos;
    e.select(ItemKind::Object, 0);
    Object named = e.scene().objects[0];
    named.name = "ball";
    e.editObjects(e.scene().objects[0], named, 0);
    EXPECT_NEAR(e.simulation().cache().end(), 1.0, 1e-9);  // the run is whole
    EXPECT_NEAR(e.document().time(), 0.5, 1e-9);
    EXPECT_EQ(e.scene().objects[0].pos, at);  // and the pose shown
    EXPECT_FALSE(e.document().runEdits());    // nothing Save would leave out
    EXPECT_EQ(e.document().start().objects[0].pos, glm::vec3(0, 3, 0));
    ASSERT_TRUE(e.seek(0.75));
    EXPECT_EQ(e.scene().objects[0].name, "ball");
    std::string error;
    ASSERT_TRUE(e.save(&error)) << error;
    EXPECT_EQ(saved(path).objects[0].name, "ball");
    EXPECT_EQ(saved(path).objects[0].pos, glm::vec3(0, 3, 0));
    ASSERT_TRUE(e.seek(0));
    EXPECT_EQ(e.scene().objects[0].name, "ball");
}

TEST(EditsInTime, AMaterialChosenAtALaterTimeKeepsTheRunAndUndoes) {
    Editor e = openEditor(writeFile("material.txt", std::string(kScene) + "material r:0 g:1 b:0\n"));
    run(e, 60);
    ASSERT_TRUE(e.seek(0.5));
    e.select(ItemKind::Object, 0);
    Object green = e.scene().objects[0];
    green.material = 1;
    e.editObjects(e.scene().objects[0], green, 0);
    EXPECT_NEAR(e.simulation().cache().end(), 1.0, 1e-9);
    EXPECT_EQ(e.document().start().objects[0].material, 1);
    ASSERT_TRUE(e.undo());
    EXPECT_EQ(e.scene().objects[0].material, 0);
    EXPECT_EQ(e.document().start().objects[0].material, 0);
    EXPECT_NEAR(e.document().time(), 0.5, 1e-9);
    ASSERT_TRUE(e.seek(0.9));  // the run is still there to scrub
    EXPECT_NEAR(e.document().time(), 0.9, 1e-9);
}

// A move at a later time is still an event of the run: what followed goes.
TEST(EditsInTime, AMoveAtALaterTimeStillCutsTheRun) {
    Editor e = openEditor(writeFile("move.txt", kScene));
    run(e, 60);
    ASSERT_TRUE(e.seek(0.5));
    e.select(ItemKind::Object, 0);
    Object moved = e.scene().objects[0];
    moved.pos.x = 1;
    e.editObjects(e.scene().objects[0], moved, 0);
    EXPECT_NEAR(e.simulation().cache().end(), 0.5, 1e-9);
    EXPECT_TRUE(e.document().runEdits());
}

// A run undone and redone: the undo took its frames, and the redo brings back its last pose
// alone, a frame at 1 s with none before it. Scrubbed back to the start and played, time goes
// on from there, simulated anew, as it does after any edit. Planted: the frames before the
// cache's end taken as baked: the start was shown, still, until the play head passed 1 s.
TEST(EditsInTime, PlayAfterARunUndoneAndRedoneMovesTimeOn) {
    Editor e = openEditor(writeFile("redo.txt", kScene));
    run(e, 60);
    ASSERT_TRUE(e.undo());
    ASSERT_TRUE(e.redo());
    EXPECT_NEAR(e.document().time(), 1.0, 1e-9);
    ASSERT_TRUE(e.seek(0));
    e.togglePlay();
    double last = e.document().time();
    for (int i = 0; i < 30; ++i) {
        e.frame(1.0 / 60);
        EXPECT_GT(e.document().time(), last) << "frame " << i;
        last = e.document().time();
    }
    e.togglePlay();
}

// Baked at 60 frames a second and played at 120 or 144: each frame shows the baked frame at
// the play head, never the one before it, though the head's time is a sum of steps that rounds
// differently from the bake's. The bake holds every second step (dt = 1/120 s).
TEST(EditsInTime, PlaybackFasterThanTheBakeShowsTheFrameAtThePlayHead) {
    for (double fps : {120.0, 144.0}) {
        Editor e = openEditor(writeFile("fast.txt", kScene));
        run(e, 60);
        ASSERT_TRUE(e.seek(0));
        const double dt = e.simulation().settings().dt;
        StepAccumulator clock;  // the play head, counted apart from the editor's
        int steps = 0;
        e.togglePlay();
        for (int i = 0; i < int(fps) - 2; ++i) {
            e.frame(1.0 / fps);
            steps += clock.advance(1.0 / fps, e.simulation().settings());
            EXPECT_NEAR(e.document().time(), (steps / 2) * 2 * dt, 1e-9)
                << fps << " fps, frame " << i << ", head at step " << steps;
        }
        e.togglePlay();
    }
}

// Nothing could be hidden or locked. The eye and the lock are the session's: undoable, never
// unsaved, never saved.
TEST(EditsInTime, AHiddenObjectLeavesTheViewAndTheClicksAndComesBackWithUndo) {
    const std::string path = writeFile("hide.txt",
                                       "material r:1 g:0 b:0\n"
                                       "object type:sphere pos:0,3,0 radius:0.5\n"
                                       "object type:sphere pos:0,3,2 radius:1\n");
    Editor e = openEditor(path);
    e.view() = Camera{{0, 3, -6}, {0, 3, 0}, 50};
    e.select(ItemKind::Object, 0);
    e.setHidden(0, true);
    EXPECT_TRUE(e.selection().empty());  // it can no longer be clicked: it leaves
    EXPECT_FALSE(e.document().dirty());
    EXPECT_EQ(e.pick({320.5f, 180.5f}, {640, 360}), 1);  // seen through, to the one behind
    Renumbering r;
    const Scene shown = visibleScene(e.scene(), &r);
    ASSERT_EQ(shown.objects.size(), 1u);
    EXPECT_EQ(shown.objects[0].radius, 1.0f);
    EXPECT_EQ(r.objects, (std::vector<int>{-1, 0}));
    std::string error;
    ASSERT_TRUE(e.saveAs(path, &error)) << error;
    EXPECT_EQ(saved(path).objects.size(), 2u);  // the file has both, neither hidden
    EXPECT_FALSE(saved(path).objects[0].hidden);
    EXPECT_EQ(e.document().history().undoLabel(), "Hide object");
    ASSERT_TRUE(e.undo());
    EXPECT_FALSE(e.scene().objects[0].hidden);
    EXPECT_EQ(e.pick({320.5f, 180.5f}, {640, 360}), 0);
}

TEST(EditsInTime, ALockedObjectIsDrawnButPassedByClicksAndBoxes) {
    Editor e = openEditor(writeFile("lock.txt",
                                    "material r:1 g:0 b:0\n"
                                    "object type:sphere pos:0,3,0 radius:0.5\n"
                                    "object type:sphere pos:0,3,2 radius:1\n"));
    e.view() = Camera{{0, 3, -6}, {0, 3, 0}, 50};
    e.setLocked(0, true);
    Renumbering r;
    EXPECT_EQ(visibleScene(e.scene(), &r).objects.size(), 2u);
    EXPECT_EQ(e.pick({320.5f, 180.5f}, {640, 360}), 1);
    EXPECT_EQ(objectsInBox(e.scene(), {0, 0}, {640, 360}, {640, 360}),
              (std::vector<Item>{{ItemKind::Object, 1}}));
    e.setLocked(0, false);
    EXPECT_EQ(e.pick({320.5f, 180.5f}, {640, 360}), 0);
}
