// test_editor.cpp — the editor's rules: open failures, unsaved work, edits while simulating.
#include "editor_session.h"

#include "marchbox/editor/camera_keys.h"
#include "marchbox/editor/editor.h"
#include "marchbox/scene/camera_path.h"
#include "marchbox/scene/scene_io.h"
#include "marchbox/scene/sdf.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

using namespace mb;
using namespace mb::test;
namespace fs = std::filesystem;

TEST(Editor, FailedOpenLeavesTheSceneAndSaysWhere) {
    Editor e = openEditor(writeFile("good.txt", kScene));
    std::string bad = writeFile("bad.txt", "material r:1 g:0 b:0\nobject type:sphere pos:0,1\n");
    std::vector<std::string> errors;
    EXPECT_FALSE(e.request(Leave::Open, bad, &errors));
    ASSERT_FALSE(errors.empty());
    EXPECT_EQ(errors[0].rfind(bad + ":2:", 0), 0u) << errors[0];
    EXPECT_EQ(e.scene().objects.size(), 2u);
    EXPECT_EQ(e.document().path(), tempPath("good.txt"));
}

TEST(Editor, LeavingUnsavedWorkWaitsForAnAnswer) {
    Editor e = openEditor(writeFile("leave.txt", kScene));
    std::vector<std::string> errors;
    e.request(Leave::Exit, "", &errors);
    EXPECT_TRUE(e.quitRequested());  // nothing unsaved: leaves at once

    Editor f = openEditor(writeFile("leave.txt", kScene));
    f.kick();
    f.request(Leave::NewScene, "", &errors);
    EXPECT_EQ(f.pendingLeave(), Leave::NewScene);
    EXPECT_EQ(f.scene().objects.size(), 2u);
    f.cancelLeave();
    EXPECT_EQ(f.pendingLeave(), Leave::None);
    f.request(Leave::Exit, "", &errors);
    EXPECT_FALSE(f.quitRequested());
    f.confirmLeave();
    EXPECT_TRUE(f.quitRequested());
}

// Open asked whether to save before finding out the file could not open.
TEST(Editor, OpenReadsTheFileBeforeAskingAboutUnsavedWork) {
    Editor e = openEditor(writeFile("asker.txt", kScene));
    e.kick();
    ASSERT_TRUE(e.document().dirty());
    std::string bad = writeFile("broken.txt", "object type:sphere pos:0,1\n");
    std::vector<std::string> errors;
    EXPECT_FALSE(e.request(Leave::Open, bad, &errors));
    EXPECT_EQ(e.pendingLeave(), Leave::None);  // nothing asked
    ASSERT_FALSE(errors.empty());
    EXPECT_EQ(errors[0].rfind(bad + ":1:", 0), 0u) << errors[0];
    EXPECT_FALSE(e.request(Leave::Open, tempPath("missing.txt"), &errors));
    EXPECT_EQ(e.pendingLeave(), Leave::None);
    EXPECT_TRUE(e.document().dirty());  // the work is still there

    // A file that loads asks, and opens what was read when it was asked for.
    std::string good = writeFile("other.txt", "material r:0 g:1 b:0\nobject type:box pos:0,1,0\n");
    EXPECT_TRUE(e.request(Leave::Open, good, &errors));
    EXPECT_EQ(e.pendingLeave(), Leave::Open);
    writeFile("other.txt", "this no longer loads\n");
    e.confirmLeave();
    EXPECT_EQ(e.document().path(), good);
    ASSERT_EQ(e.scene().objects.size(), 1u);
    EXPECT_EQ(e.scene().objects[0].type, ShapeType::Box);
    EXPECT_FALSE(e.document().dirty());
}

TEST(Editor, SaveAsWritesAFileThatLoadsAndCleans) {
    Editor e = openEditor(writeFile("src.txt", kScene));
    e.kick();
    EXPECT_TRUE(e.document().dirty());
    std::string out = tempPath("saved-as.txt"), error;
    ASSERT_TRUE(e.saveAs(out, &error)) << error;
    EXPECT_FALSE(e.document().dirty());
    EXPECT_EQ(e.document().path(), out);
    Scene back;
    std::vector<std::string> errors;
    ASSERT_TRUE(loadScene(out, &back, &errors));
    EXPECT_EQ(back, e.scene());
}

TEST(Editor, TheLastFileOutlivesNew) {
    std::string path = writeFile("last.txt", kScene);
    Editor e = openEditor(path);
    EXPECT_EQ(e.lastFile(), path);
    std::vector<std::string> errors;
    e.request(Leave::NewScene, "", &errors);
    EXPECT_EQ(e.document().path(), "");
    EXPECT_EQ(e.lastFile(), path);
    std::string error, saved = tempPath("last-saved.txt");
    ASSERT_TRUE(e.saveAs(saved, &error)) << error;
    EXPECT_EQ(e.lastFile(), saved);
}

TEST(Editor, SaveWithoutAFileAsksForSaveAs) {
    Editor e;
    std::vector<std::string> errors;
    e.request(Leave::NewScene, "", &errors);
    std::string error;
    EXPECT_FALSE(e.save(&error));
    EXPECT_NE(error.find("Save As"), std::string::npos);
}

TEST(Editor, SaveAsWithoutAFileNameAsksForOneAndKeepsTheScene) {
    std::string path = writeFile("unnamed.txt", kScene);
    Editor e = openEditor(path);
    e.kick();
    std::string error;
    EXPECT_FALSE(e.saveAs("", &error));
    EXPECT_EQ(error, "type a file name to save the scene to");
    EXPECT_TRUE(e.document().dirty());
    EXPECT_EQ(e.document().path(), path);
    EXPECT_EQ(e.lastFile(), path);
}

TEST(Editor, ASimulationRunIsOneUndoStep) {
    Editor e = openEditor(writeFile("run.txt", kScene));
    const glm::vec3 start = e.scene().objects[0].pos;
    e.togglePlay();
    for (int i = 0; i < 30; ++i) e.frame(1.0 / 60);
    EXPECT_LT(e.scene().objects[0].pos.y, start.y);  // it fell
    e.togglePlay();
    const double t = e.document().time();
    EXPECT_NEAR(t, 0.5, 1e-9);
    EXPECT_FALSE(e.document().dirty());  // Save would write the start: nothing to lose
    EXPECT_EQ(e.document().history().undoLabel(), "Simulation run");
    ASSERT_TRUE(e.undo());
    EXPECT_EQ(e.scene().objects[0].pos, start);
    EXPECT_EQ(e.document().time(), 0.0);
    ASSERT_TRUE(e.redo());
    EXPECT_LT(e.scene().objects[0].pos.y, start.y);
    EXPECT_EQ(e.document().time(), t);
}

TEST(Editor, AnEditWhilePlayingSplitsTheRun) {
    Editor e = openEditor(writeFile("split.txt", kScene));
    e.togglePlay();
    for (int i = 0; i < 10; ++i) e.frame(1.0 / 60);
    e.edit("Gravity", [](Scene& s) { s.world.gravity = 1; });
    for (int i = 0; i < 10; ++i) e.frame(1.0 / 60);
    e.togglePlay();
    EXPECT_EQ(e.document().history().size(), 3u);  // run, edit, run
    e.undo();
    EXPECT_EQ(e.document().history().undoLabel(), "Gravity");
    EXPECT_EQ(e.scene().world.gravity, 1.0f);
}

TEST(Editor, ResetReturnsToWhenPlayWasPressed) {
    Editor e = openEditor(writeFile("reset.txt", kScene));
    const Scene start = e.scene();
    e.togglePlay();
    for (int i = 0; i < 20; ++i) e.frame(1.0 / 60);
    e.resetSimulation();
    EXPECT_FALSE(e.simulation().playing());
    EXPECT_EQ(e.scene(), start);
    e.undo();  // undo the reset: back to where the run got to
    EXPECT_NE(e.scene().objects[0].pos, start.objects[0].pos);
}

// After Reset the title kept its '*' though the file would be identical. A run alone never
// marks the scene unsaved: Save writes the start, which the run leaves as it was.
TEST(Editor, ResetBackToTheFileLeavesNothingUnsaved) {
    Editor e = openEditor(writeFile("reset-clean.txt", kScene));
    e.togglePlay();
    for (int i = 0; i < 20; ++i) e.frame(1.0 / 60);
    EXPECT_FALSE(e.document().dirty());
    e.togglePlay();
    e.resetSimulation();
    EXPECT_FALSE(e.document().dirty());
    std::vector<std::string> errors;
    e.request(Leave::Exit, "", &errors);
    EXPECT_TRUE(e.quitRequested());  // nothing to ask about

    // An edit before Play stays unsaved after Reset.
    Editor f = openEditor(writeFile("reset-edit.txt", kScene));
    f.edit("Gravity", [](Scene& s) { s.world.gravity = 2; });
    f.togglePlay();
    for (int i = 0; i < 20; ++i) f.frame(1.0 / 60);
    f.resetSimulation();
    EXPECT_TRUE(f.document().dirty());
}

// The camera is saved with the file but never marks the scene unsaved,
// whether it moved in the view or was typed into the View panel.
TEST(Editor, TheCameraIsSavedButNeverMarksTheSceneUnsaved) {
    std::string path = writeFile("camera.txt", kScene);
    Editor e = openEditor(path);
    e.view().pos = {1, 2, -9};
    EXPECT_FALSE(e.document().dirty());
    e.edit("Edit camera", [](Scene& s) { s.camera.fov = 30; });
    EXPECT_FALSE(e.document().dirty());
    std::string error;
    ASSERT_TRUE(e.save(&error)) << error;
    Scene back;
    std::vector<std::string> errors;
    ASSERT_TRUE(loadScene(path, &back, &errors));
    EXPECT_EQ(back.camera.pos, glm::vec3(1, 2, -9));
    EXPECT_EQ(back.camera.fov, 30.0f);
}

TEST(Editor, StepIsOneFixedStep) {
    Editor e = openEditor(writeFile("step.txt", kScene));
    Scene expected = e.scene();
    simulate(expected, e.simulation().settings().dt);
    e.step();
    EXPECT_EQ(e.scene().objects[0].pos, expected.objects[0].pos);
    EXPECT_EQ(e.document().history().undoLabel(), "Simulation step");
}

TEST(Editor, FramesOfAnyLengthMatchTheFixedStepSimulation) {
    // The accumulator turns uneven frames into whole steps: 0.5 s in frames of 7, 23 and 13 ms
    // ends exactly where simulate() ends after the same number of steps.
    Editor e = openEditor(writeFile("frames.txt", kScene));
    Scene expected = e.scene();
    e.togglePlay();
    const double frames[] = {0.007, 0.023, 0.013};
    double total = 0;
    for (int i = 0; total + 0.023 < 0.5; ++i) {
        e.frame(frames[i % 3]);
        total += frames[i % 3];
    }
    e.togglePlay();
    simulate(expected, std::floor(total / e.simulation().settings().dt + 1e-9) *
                           e.simulation().settings().dt);
    EXPECT_EQ(e.scene().objects[0].pos, expected.objects[0].pos);
}

TEST(Editor, SelectionSurvivesDeletesAndUndo) {
    Editor e = openEditor(writeFile("sel.txt", kScene));
    e.select(ItemKind::Object, 1);
    std::string why;
    ASSERT_TRUE(e.remove(ItemKind::Object, 0, &why));
    EXPECT_EQ(e.selection().object(), 0);  // the box moved down the list
    ASSERT_TRUE(e.removeSelected(&why));
    EXPECT_TRUE(e.selection().empty());
    EXPECT_TRUE(e.scene().objects.empty());
    e.undo();
    e.undo();
    EXPECT_EQ(e.scene().objects.size(), 2u);
}

TEST(Editor, PickSelectsTheObjectUnderTheMouse) {
    Editor e = openEditor(writeFile("pick.txt", kScene));
    e.view() = Camera{{0, 3, -6}, {0, 3, 0}, 50};
    EXPECT_EQ(e.pick({320.5f, 180.5f}, {640, 360}), 0);  // the sphere straight ahead
    EXPECT_EQ(e.selection().object(), 0);
    EXPECT_EQ(e.pick({320.5f, 350.5f}, {640, 360}), -1);  // sky above
    EXPECT_TRUE(e.selection().empty());
    EXPECT_FALSE(e.document().dirty());  // picking and looking are no edits
}

TEST(Editor, AddAndDuplicateSelectTheNewItem) {
    Editor e = openEditor(writeFile("add.txt", kScene));
    std::string why;
    ASSERT_TRUE(e.add(ItemKind::Light, &why));
    EXPECT_TRUE(e.selection().is(ItemKind::Light, 0));
    ASSERT_TRUE(e.duplicate(ItemKind::Object, 1, &why));
    EXPECT_TRUE(e.selection().is(ItemKind::Object, 2));
    e.clear(ItemKind::Object);
    EXPECT_TRUE(e.selection().empty());
    EXPECT_EQ(e.document().history().undoLabel(), "Clear objects");
}

// The CSG chain follows the list: Move up and down change it as one undo step each, the
// selection going with the object and its comment lines with it.
TEST(Editor, MovingAnObjectUpAndDownIsUndoable) {
    Editor e = openEditor(writeFile("order.txt",
                                    "material r:1 g:0 b:0\n"
                                    "object type:sphere pos:0,1,0\n"
                                    "# the lid\n"
                                    "object type:box pos:0,2,0 op:subtract\n"));
    std::string why;
    ASSERT_TRUE(e.reorder(1, -1, &why)) << why;
    EXPECT_EQ(e.scene().objects[0].type, ShapeType::Box);
    EXPECT_EQ(e.scene().objects[0].comment, "# the lid\n");
    EXPECT_EQ(e.scene().objects[1].type, ShapeType::Sphere);
    EXPECT_TRUE(e.selection().is(ItemKind::Object, 0));
    EXPECT_EQ(e.document().history().undoLabel(), "Move object up");
    EXPECT_FALSE(e.reorder(0, -1, &why));  // already first: refused, saying so
    EXPECT_EQ(why, "object 0 is already first");
    ASSERT_TRUE(e.undo());
    EXPECT_EQ(e.scene().objects[0].type, ShapeType::Sphere);
    ASSERT_TRUE(e.reorder(0, 1, &why)) << why;
    EXPECT_EQ(e.scene().objects[1].type, ShapeType::Sphere);
    EXPECT_FALSE(e.reorder(1, 1, &why));
    EXPECT_EQ(why, "object 1 is already last");
}

//-----------------------------------------------------------------------------
// The start (t = 0) and the simulated time
//-----------------------------------------------------------------------------
// Play then Save wrote the resting poses over the start without a word.
TEST(Editor, SaveWritesTheStartNotTheSimulatedPoses) {
    std::string path = writeFile("start.txt", kScene);
    Editor e = openEditor(path);
    const glm::vec3 start = e.scene().objects[0].pos;
    run(e, 30);
    ASSERT_LT(e.scene().objects[0].pos.y, start.y);
    std::string error;
    ASSERT_TRUE(e.save(&error)) << error;
    EXPECT_EQ(saved(path).objects[0].pos, start);
    EXPECT_LT(e.scene().objects[0].pos.y, start.y);  // the view still shows where it got to
    ASSERT_TRUE(e.saveAs(tempPath("start-as.txt"), &error)) << error;
    EXPECT_EQ(saved(tempPath("start-as.txt")).objects[0].pos, start);
}

TEST(Editor, KeepSimulatedPosesMakesThemTheStartAsOneStep) {
    std::string path = writeFile("keep.txt", kScene);
    Editor e = openEditor(path);
    const glm::vec3 start = e.scene().objects[0].pos;
    EXPECT_FALSE(e.keepPoses());  // at t = 0 there is nothing to keep
    run(e, 30);
    const glm::vec3 fallen = e.scene().objects[0].pos;
    ASSERT_TRUE(e.keepPoses());
    EXPECT_EQ(e.document().time(), 0.0);
    EXPECT_EQ(e.scene().objects[0].pos, fallen);
    EXPECT_TRUE(e.document().dirty());
    EXPECT_EQ(e.document().history().undoLabel(), "Keep simulated poses");
    std::string error;
    ASSERT_TRUE(e.save(&error)) << error;
    EXPECT_EQ(saved(path).objects[0].pos, fallen);

    ASSERT_TRUE(e.undo());  // back to t = 0.5 s over the old start
    EXPECT_NEAR(e.document().time(), 0.5, 1e-9);
    EXPECT_EQ(e.scene().objects[0].pos, fallen);
    ASSERT_TRUE(e.save(&error)) << error;
    EXPECT_EQ(saved(path).objects[0].pos, start);
}

// The camera is a view, not the bodies: editing it keeps the time and what Save writes.
TEST(Editor, EditingTheCameraKeepsTheSimulatedTime) {
    Editor e = openEditor(writeFile("camera-time.txt", kScene));
    const glm::vec3 start = e.scene().objects[0].pos;
    run(e, 30);
    const glm::vec3 fallen = e.scene().objects[0].pos;
    e.edit("Edit camera", [](Scene& s) { s.camera.fov = 30; });
    e.view().pos = {1, 2, -9};
    EXPECT_NEAR(e.document().time(), 0.5, 1e-9);
    EXPECT_EQ(e.scene().objects[0].pos, fallen);
    EXPECT_EQ(e.document().start().objects[0].pos, start);
    EXPECT_EQ(e.document().start().camera.fov, 30.0f);
}

// Gravity edited at t > 0 goes to the start too and the run carries on; moving an object at
// t > 0 is an event of the run, made there: the time and the start stay.
TEST(Editor, AnEditAtALaterTimeIsMadeAtThatTime) {
    Editor e = openEditor(writeFile("edit-later.txt", kScene));
    run(e, 30);
    e.edit("Gravity", [](Scene& s) { s.world.gravity = 2; });
    EXPECT_NEAR(e.document().time(), 0.5, 1e-9);
    EXPECT_EQ(e.document().start().world.gravity, 2.0f);

    const glm::vec3 fallen = e.scene().objects[0].pos;
    e.moveObject(1, {4, 0.5f, 0}, 0);
    EXPECT_NEAR(e.document().time(), 0.5, 1e-9);
    EXPECT_EQ(e.scene().objects[0].pos, fallen);
    EXPECT_EQ(e.scene().objects[1].pos, glm::vec3(4, 0.5f, 0));
    EXPECT_EQ(e.document().start().objects[1].pos, glm::vec3(3, 0.5f, 0));
    e.undo();
    EXPECT_NEAR(e.document().time(), 0.5, 1e-9);
    EXPECT_EQ(e.scene().objects[1].pos, glm::vec3(3, 0.5f, 0));

    std::string why;
    ASSERT_TRUE(e.add(ItemKind::Object, &why)) << why;  // the others stay where they are shown
    EXPECT_NEAR(e.document().time(), 0.5, 1e-9);
    EXPECT_EQ(e.scene().objects.size(), 3u);
    EXPECT_EQ(e.scene().objects[0].pos, fallen);
    EXPECT_EQ(e.document().start().objects.size(), 2u);
}

// A move at t > 0 is in the run, not in the start Save writes: leaving lost it unasked, as the
// start still matched the file. Leaving asks while the run holds it; not once it is undone, or
// kept as the start and saved.
TEST(Editor, LeavingAsksWhileTheRunHoldsAnEditTheStartLacks) {
    std::vector<std::string> errors;
    Editor e = openEditor(writeFile("run-edit.txt", kScene));
    run(e, 30);
    e.moveObject(1, {4, 0.5f, 0}, 0);
    EXPECT_FALSE(e.document().dirty());
    EXPECT_TRUE(e.document().runEdits());
    e.request(Leave::Exit, "", &errors);
    EXPECT_EQ(e.pendingLeave(), Leave::Exit);
    EXPECT_FALSE(e.quitRequested());
    e.cancelLeave();
    ASSERT_TRUE(e.undo());
    EXPECT_FALSE(e.document().runEdits());
    e.request(Leave::Exit, "", &errors);
    EXPECT_TRUE(e.quitRequested());  // the run as the simulator made it: nothing to lose

    Editor f = openEditor(writeFile("run-edit-kept.txt", kScene));
    run(f, 30);
    f.moveObject(1, {4, 0.5f, 0}, 0);
    ASSERT_TRUE(f.keepPoses());
    EXPECT_FALSE(f.document().runEdits());
    std::string error;
    ASSERT_TRUE(f.save(&error)) << error;
    f.request(Leave::Exit, "", &errors);
    EXPECT_TRUE(f.quitRequested());
}

// Gravity edited at t > 0 is made to the start too, so Save keeps it: nothing to ask.
TEST(Editor, AWorldEditAtALaterTimeIsNoEditOfTheRunToAskAbout) {
    Editor e = openEditor(writeFile("run-world.txt", kScene));
    run(e, 30);
    e.edit("Gravity", [](Scene& s) { s.world.gravity = 2; });
    EXPECT_FALSE(e.document().runEdits());
    std::string error;
    ASSERT_TRUE(e.save(&error)) << error;
    std::vector<std::string> errors;
    e.request(Leave::Exit, "", &errors);
    EXPECT_TRUE(e.quitRequested());

    // A world edit after a move at the same time replaces the move's run piece, not the move.
    Editor f = openEditor(writeFile("run-world-move.txt", kScene));
    run(f, 30);
    f.moveObject(1, {4, 0.5f, 0}, 0);
    f.edit("Gravity", [](Scene& s) { s.world.gravity = 2; });
    EXPECT_TRUE(f.document().runEdits());
}

// Simulating from before the edit replaces what followed, the edit with it: nothing is left.
TEST(Editor, SimulatingFromBeforeAnEditOfTheRunDropsIt) {
    Editor e = openEditor(writeFile("run-replay.txt", kScene));
    run(e, 30);
    e.moveObject(1, {4, 0.5f, 0}, 0);
    ASSERT_TRUE(e.seek(0.25));
    run(e, 10);                            // plays the baked frames back: the run stays
    EXPECT_TRUE(e.document().runEdits());  // still there to scrub forward to
    e.step();
    EXPECT_FALSE(e.document().runEdits());
}

// A gizmo drag sends the whole drag so far every frame: one undo step puts the start back.
TEST(Editor, AGizmoDragOfAnObjectOrALightIsOneUndoStep) {
    Editor e = openEditor(
        writeFile("gizmo-drag.txt", std::string(kScene) + "light pos:0,4,-2 color:1,1,1\n"));
    const Scene start = e.scene();
    Object o = start.objects[1];
    for (float x : {3.2f, 3.4f, 3.6f}) {
        o.pos.x = x;
        o.size.y = x / 4.0f;
        e.setObject(1, o, "Scale object", 7);
    }
    e.endEdit();
    EXPECT_EQ(e.scene().objects[1].size.y, 0.9f);
    for (float y : {4.0f, 5.0f}) e.moveLight(0, {1, y, 2}, 8);
    e.endEdit();
    EXPECT_EQ(e.scene().lights[0].vec, glm::vec3(1, 5, 2));
    EXPECT_EQ(e.document().history().undoLabel(), "Move light");
    ASSERT_TRUE(e.undo());
    EXPECT_EQ(e.scene().lights[0].vec, start.lights[0].vec);
    EXPECT_EQ(e.scene().objects[1].pos.x, 3.6f);
    ASSERT_TRUE(e.undo());
    EXPECT_EQ(e.scene().objects[1].pos, start.objects[1].pos);
    EXPECT_EQ(e.scene().objects[1].size, start.objects[1].size);
    e.setObject(5, o, "Move object", 9);  // past the end: nothing, no step
    e.moveLight(3, {0, 0, 0}, 9);
    EXPECT_EQ(e.document().history().undoLabel(), "");
}

TEST(Editor, TimeLabelSaysTheSimulatedSeconds) { EXPECT_EQ(timeLabel(2.345678), "t = 2.35 s"); }

//-----------------------------------------------------------------------------
// Camera keyframes
//-----------------------------------------------------------------------------
TEST(Editor, CameraKeysAddAtTheSimulatedTimeAndDeleteTheNearest) {
    Editor e = openEditor(writeFile("keys.txt", kScene));
    EXPECT_FALSE(e.deleteCameraKey());
    e.view() = Camera{{0, 2, -8}, {0, 1, 0}, 50};
    e.addCameraKey();  // t = 0
    run(e, 60);        // t = 1 s
    e.view() = Camera{{6, 2, -8}, {0, 1, 0}, 40};
    e.addCameraKey();
    e.view().fov = 30;
    e.addCameraKey();  // the same t: the key takes the new view
    ASSERT_EQ(e.scene().keyframes.size(), 2u);
    EXPECT_EQ(e.scene().keyframes[1].t, 1.0f);
    EXPECT_EQ(e.scene().keyframes[1].pos, glm::vec3(6, 2, -8));
    EXPECT_EQ(e.scene().keyframes[1].fov, 30.0f);
    EXPECT_NEAR(e.document().time(), 1.0, 1e-9);           // keys are no edit of the bodies
    EXPECT_EQ(e.document().start().keyframes.size(), 2u);  // and Save writes them,
    EXPECT_EQ(e.document().start().keyframes[1].pos, glm::vec3(6, 2, -8));  // from the view

    ASSERT_TRUE(e.deleteCameraKey());  // the one at 1 s
    ASSERT_EQ(e.scene().keyframes.size(), 1u);
    EXPECT_EQ(e.scene().keyframes[0].t, 0.0f);
    e.undo();
    EXPECT_EQ(e.scene().keyframes.size(), 2u);
}

// Adding a light at t > 0 is made to the start too, and the start keeps its own bodies there,
// not the poses the run shows.
TEST(Editor, AnEditOfTheLightsAtALaterTimeLeavesTheStartsBodies) {
    Editor e = openEditor(writeFile("light-later.txt", kScene));
    const glm::vec3 start = e.scene().objects[0].pos;
    run(e, 30);
    ASSERT_NE(e.scene().objects[0].pos, start);
    std::string why;
    ASSERT_TRUE(e.add(ItemKind::Light, &why)) << why;
    EXPECT_EQ(e.document().start().objects[0].pos, start);
    EXPECT_EQ(e.document().start().lights.size(), e.scene().lights.size());
}

// A key dragged along the timeline: its view goes with it, the keys stay in order, another
// key's time refuses it, and the whole drag is one undo step.
TEST(Editor, DraggingACameraKeyMovesItInOneUndoStep) {
    Editor e = openEditor(writeFile("move-keys.txt", kScene));
    Scene s = e.scene();
    for (float t : {0.0f, 1.0f, 2.0f}) setCameraKey(s, t, Camera{{t, 2, -8}, {0, 1, 0}, 50});
    e.start(s, "");
    EXPECT_EQ(e.moveCameraKey(0, 1.5f, 7), 1);  // past the key at 1 s: now second
    EXPECT_EQ(e.moveCameraKey(1, 2.5f, 7), 2);  // on past the one at 2 s, the same drag
    const std::vector<Keyframe>& keys = e.scene().keyframes;
    ASSERT_EQ(keys.size(), 3u);
    EXPECT_EQ(keys[2].t, 2.5f);
    EXPECT_EQ(keys[2].pos, glm::vec3(0, 2, -8));  // the view it held
    EXPECT_EQ(keys[0].t, 1.0f);
    EXPECT_EQ(e.moveCameraKey(2, 2.0f, 7), -1);  // another key's time: refused, nothing moved
    EXPECT_EQ(e.scene().keyframes[2].t, 2.5f);
    e.endEdit();
    ASSERT_TRUE(e.undo());
    EXPECT_EQ(e.scene().keyframes[0].t, 0.0f);
    EXPECT_EQ(e.scene().keyframes[0].pos, glm::vec3(0, 2, -8));
    EXPECT_FALSE(e.document().history().canUndo());
}

TEST(Editor, ThePlayingViewFollowsTheKeyframesAndTheRecordOtherwise) {
    Editor e = openEditor(writeFile("follow.txt", kScene));
    const Camera rest{{0, 2, -8}, {0, 1, 0}, 50};
    e.edit("Keys", [&](Scene& s) {
        s.keyframes = {Keyframe{0, {0, 2, -8}, {0, 1, 0}, 50},
                       Keyframe{1, {8, 2, -8}, {0, 1, 0}, 50}};
        s.camera = rest;
    });
    e.togglePlay();
    for (int i = 0; i < 30; ++i) e.frame(1.0 / 60);
    const Camera path = cameraAt(e.scene().keyframes, rest, e.document().time());
    EXPECT_EQ(e.shownCamera().pos, path.pos);
    EXPECT_GT(e.shownCamera().pos.x, 1.0f);     // half way along: well off the record
    EXPECT_EQ(e.scene().camera.pos, rest.pos);  // the record stays the view at rest
    e.togglePlay();
    EXPECT_EQ(e.shownCamera().pos, rest.pos);  // paused: editing the view again
}

//-----------------------------------------------------------------------------
// The baked frames and the timeline
//-----------------------------------------------------------------------------
TEST(Editor, ScrubbingShowsEachBakedFrameAndGoesForwardAgain) {
    Editor e = openEditor(writeFile("scrub.txt", kScene));
    const Scene start = e.scene();
    EXPECT_FALSE(e.seek(0.25));  // nothing has run
    const Scene quarter = playedFor(15);
    run(e, 60);
    const glm::vec3 end = e.scene().objects[0].pos;
    EXPECT_NEAR(e.simulation().cache().end(), 1.0, 1e-9);

    ASSERT_TRUE(e.seek(0.25));
    EXPECT_NEAR(e.document().time(), 0.25, 1e-9);
    EXPECT_EQ(e.scene().objects[0].pos, quarter.objects[0].pos);
    ASSERT_TRUE(e.seek(0));  // Home
    EXPECT_EQ(e.document().time(), 0.0);
    EXPECT_EQ(e.scene(), start);
    ASSERT_TRUE(e.seek(0.25));
    ASSERT_TRUE(e.seek(2.0));  // past the end: the last frame
    EXPECT_EQ(e.scene().objects[0].pos, end);
    e.undo();  // each scrub is a step
    EXPECT_NEAR(e.document().time(), 0.25, 1e-9);
    EXPECT_EQ(e.scene().objects[0].pos, quarter.objects[0].pos);
}

TEST(Editor, AnEditOfTheStartDropsTheBakedFrames) {
    Editor e = openEditor(writeFile("scrub-edit.txt", kScene));
    run(e, 30);
    ASSERT_TRUE(e.seek(0));
    e.moveObject(0, {1, 3, 0}, 0);
    EXPECT_EQ(e.simulation().cache().end(), 0.0);
    EXPECT_FALSE(e.seek(0.25));  // nothing has run from the new start
    run(e, 10);
    ASSERT_TRUE(e.seek(0.4));  // only the new run's frames: its last
    EXPECT_NEAR(e.document().time(), 10.0 / 60, 1e-9);
    EXPECT_EQ(e.scene().objects[0].pos.x, 1.0f);
}

// Dragging the sphere at 0.5 s of a 1 s run: what ran before stays to scrub, what came after
// goes, and the run goes on from the sphere where it was put.
TEST(Editor, AnEditAtALaterTimeDropsOnlyTheFramesAfterIt) {
    Editor e = openEditor(writeFile("scrub-later.txt", kScene));
    const Scene quarter = playedFor(15);
    run(e, 60);
    ASSERT_TRUE(e.seek(0.5));
    e.moveObject(0, {1, 3, 0}, 7);
    e.moveObject(0, {2, 3, 0}, 7);  // one drag: one edit at 0.5 s
    e.endEdit();
    EXPECT_NEAR(e.document().time(), 0.5, 1e-9);
    EXPECT_NEAR(e.simulation().cache().end(), 0.5, 1e-9);
    EXPECT_EQ(e.document().start().objects[0].pos, glm::vec3(0, 3, 0));

    ASSERT_TRUE(e.seek(0.25));
    EXPECT_EQ(e.scene().objects[0].pos, quarter.objects[0].pos);
    ASSERT_TRUE(e.seek(0.5));
    EXPECT_EQ(e.scene().objects[0].pos, glm::vec3(2, 3, 0));
    run(e, 15);
    EXPECT_NEAR(e.simulation().cache().end(), 0.75, 1e-9);
    EXPECT_EQ(e.scene().objects[0].pos.x, 2.0f);
    EXPECT_LT(e.scene().objects[0].pos.y, 3.0f);  // it fell on from where it was put

    for (int i = 0; i < 3; ++i) e.undo();  // the run and two scrubs
    EXPECT_EQ(e.document().history().undoLabel(), "Move object");
    e.undo();  // the drag: the frames made after it go
    EXPECT_NEAR(e.document().time(), 0.5, 1e-9);
    EXPECT_NEAR(e.simulation().cache().end(), 0.5, 1e-9);
    ASSERT_TRUE(e.seek(0.75));
    EXPECT_EQ(e.scene().objects[0].pos.x, 0.0f);
}

// Stepped on from before an edit, the run is simulated anew and the edit is no part of it.
TEST(Editor, SimulatingFromBeforeAnEditRunsWithoutIt) {
    Editor e = openEditor(writeFile("replay-edit.txt", kScene));
    run(e, 30);
    e.edit("Radius", [](Scene& s) { s.objects[0].radius = 1; });  // at 0.5 s
    ASSERT_TRUE(e.seek(0.25));
    EXPECT_EQ(e.scene().objects[0].radius, 0.5f);
    e.step();  // replaces what followed 0.25 s
    EXPECT_NEAR(e.simulation().cache().end(), 0.25 + 1.0 / 120, 1e-9);
    run(e, 30);  // simulated on, past 0.5 s
    EXPECT_EQ(e.scene().objects[0].radius, 0.5f);
    ASSERT_TRUE(e.seek(0.6));
    EXPECT_EQ(e.scene().objects[0].radius, 0.5f);
}

// Play from a scrub shows the frames baked after it rather than simulating them again, then
// simulates on past the last.
TEST(Editor, PlayingOverBakedFramesPlaysThemBack) {
    Editor e = openEditor(writeFile("play-back.txt", kScene));
    const Scene half = playedFor(30);
    run(e, 60);
    ASSERT_TRUE(e.seek(0.25));
    e.togglePlay();
    for (int i = 0; i < 15; ++i) e.frame(1.0 / 60);
    EXPECT_NEAR(e.document().time(), 0.5, 1e-9);
    EXPECT_EQ(e.scene().objects[0].pos, half.objects[0].pos);
    EXPECT_NEAR(e.simulation().cache().end(), 1.0, 1e-9);  // nothing made again
    for (int i = 0; i < 45; ++i) e.frame(1.0 / 60);
    EXPECT_NEAR(e.document().time(), 1.25, 1e-9);  // and on past the last
    EXPECT_NEAR(e.simulation().cache().end(), 1.25, 1e-9);
    e.togglePlay();
}

// Played on past the baked frames after a scrub back, the run goes on from the physics world as
// the bake left it, not from a frame's floats: the bytes of a run never interrupted. kScene's
// sphere bounces, so a restart from rounded floats would show in the last bits by 2.25 s.
TEST(Editor, PlayingOnPastTheBakeAfterAScrubGoesOnAsOneRun) {
    Editor e = openEditor(writeFile("play-on.txt", kScene));
    const Scene whole = playedFor(135);
    run(e, 60);
    ASSERT_TRUE(e.seek(0.25));
    run(e, 120);
    EXPECT_NEAR(e.document().time(), 2.25, 1e-9);
    EXPECT_EQ(e.scene().objects[0].pos, whole.objects[0].pos);
    EXPECT_EQ(e.scene().objects[0].vel, whole.objects[0].vel);
    ASSERT_TRUE(e.seek(1.0));  // a step from the bake's end, shown again, goes on the same way
    ASSERT_TRUE(e.seek(2.25));
    e.step();
    Editor once = openEditor(writeFile("play-on-once.txt", kScene));
    run(once, 135);
    once.step();
    EXPECT_EQ(e.scene().objects[0].pos, once.scene().objects[0].pos);
}

// Loop over a baked second: past its end playing starts again at t = 0, from the baked frames.
TEST(Editor, LoopPlaysTheBakedFramesAgainFromTheStart) {
    Editor e = openEditor(writeFile("loop.txt", kScene));
    const Scene half = playedFor(30);
    run(e, 60);
    ASSERT_TRUE(e.seek(0.5));
    e.setLoop(true);
    e.togglePlay();
    for (int i = 0; i < 30; ++i) e.frame(1.0 / 60);
    EXPECT_NEAR(e.document().time(), 1.0, 1e-9);  // the end is still shown
    e.frame(1.0 / 60);
    EXPECT_EQ(e.document().time(), 0.0);  // then the start
    EXPECT_EQ(e.scene().objects[0].pos, glm::vec3(0, 3, 0));
    for (int i = 0; i < 30; ++i) e.frame(1.0 / 60);
    EXPECT_NEAR(e.document().time(), 0.5, 1e-9);
    EXPECT_EQ(e.scene().objects[0].pos, half.objects[0].pos);
    EXPECT_NEAR(e.simulation().cache().end(), 1.0, 1e-9);
    e.togglePlay();
}

// A ball that stops bouncing: its bounces lose all but a fifth of their speed.
static const char* kSettling =
    "world restitution:0.2\n"
    "material r:1 g:0 b:0\n"
    "object type:sphere pos:0,1,0 radius:0.5\n";

// Play ran on to t = 22 s after every body was at rest.
TEST(Editor, PlayStopsByItselfOnceEveryBodyIsAtRest) {
    Editor e = openEditor(writeFile("rest.txt", kSettling));
    e.togglePlay();
    int frames = 0;
    for (; frames < 600 && e.simulation().playing(); ++frames) e.frame(1.0 / 60);
    ASSERT_FALSE(e.simulation().playing()) << "still playing at 10 s";
    const double t = e.document().time();
    EXPECT_EQ(e.simulation().restedAt(), t);
    EXPECT_GT(t, 0.5);  // it fell, bounced and slept (half a second slow)
    EXPECT_LT(t, 5.0);
    EXPECT_EQ(e.document().history().undoLabel(), "Simulation run");  // paused as Space would
    e.togglePlay();  // again: at rest already, so at once
    e.frame(1.0 / 60);
    EXPECT_FALSE(e.simulation().playing());
}

TEST(Editor, PlayAtRestGoesOnToTheLastCameraKeyAndLoopsOnWithLoop) {
    Editor e = openEditor(writeFile("rest-keys.txt",
                                    std::string("scene version:2\nkeyframe t:8 pos:0,2,-6\n") +
                                        kSettling));
    e.togglePlay();
    for (int i = 0; i < 600 && e.simulation().playing(); ++i) e.frame(1.0 / 60);
    EXPECT_NEAR(e.document().time(), 8.0, 1.0 / 60);  // the camera's path played whole
    Editor loop = openEditor(writeFile("rest-loop.txt", kSettling));
    loop.setLoop(true);
    loop.togglePlay();
    for (int i = 0; i < 600; ++i) loop.frame(1.0 / 60);
    EXPECT_TRUE(loop.simulation().playing());
    loop.togglePlay();
}

// A key's time is a float, the frame it was added at a double a rounding above it (0.35 s).
TEST(Editor, GoingToACameraKeyShowsTheFrameItWasAddedAt) {
    Editor e = openEditor(writeFile("seek-key.txt", kScene));
    run(e, 21);
    const double added = e.document().time();
    const glm::vec3 there = e.scene().objects[0].pos;
    e.addCameraKey();
    run(e, 10);
    EXPECT_FALSE(e.seekKey(1));
    ASSERT_TRUE(e.seekKey(0));
    EXPECT_EQ(e.document().time(), added);
    EXPECT_EQ(e.scene().objects[0].pos, there);
}
