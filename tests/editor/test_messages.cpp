// test_messages.cpp — a message shows where it was raised, and only while its context lasts.
#include "marchbox/editor/messages.h"

#include <gtest/gtest.h>

using namespace mb;

namespace {

Selection selected(ItemKind k, int i) { return Selection{k, i}; }

// One frame in which `places` are drawn.
void frame(Messages& m, std::initializer_list<Place> places, const Selection& sel, double t = 0.0) {
    for (Place p : places) m.shown(p);
    m.endFrame(sel, t);
}

}  // namespace

// The first case: a refusal in the Lights panel, then a click on a sphere.
TEST(Messages, ALightsRefusalGoesWhenASphereIsSelected) {
    Messages m;
    const Selection light = selected(ItemKind::Light, 0);
    frame(m, {Place::Objects, Place::Lights}, light);
    *m.at(Place::Lights) = "intensity must be between 0 and 10000";
    EXPECT_TRUE(m.isNew(Place::Lights));
    frame(m, {Place::Objects, Place::Lights}, light);
    EXPECT_FALSE(m.isNew(Place::Lights)) << "seen by a frame's end";
    EXPECT_EQ(m.text(Place::Objects), "") << "it belongs to the Lights panel only";
    frame(m, {Place::Objects, Place::Lights}, light);
    EXPECT_NE(m.text(Place::Lights), "") << "it stays while the light is selected";
    frame(m, {Place::Objects, Place::Lights}, selected(ItemKind::Object, 0));
    EXPECT_EQ(m.text(Place::Lights), "");
}

// The second case: Save As fails, the dialog is cancelled.
TEST(Messages, ASaveAsFailureStaysInItsDialogAndGoesWithIt) {
    Messages m;
    const Selection sphere = selected(ItemKind::Object, 0);
    *m.at(Place::SaveAs) = "cannot write /nowhere/a.txt";
    frame(m, {Place::Objects, Place::SaveAs}, sphere);
    frame(m, {Place::Objects, Place::SaveAs}, sphere);
    EXPECT_EQ(m.text(Place::Objects), "");
    EXPECT_NE(m.text(Place::SaveAs), "");
    frame(m, {Place::Objects}, sphere);  // cancelled: the dialog is gone
    EXPECT_EQ(m.text(Place::SaveAs), "");
}

// Ctrl+S fails on a read-only file and opens Save As to say why: raised in a frame that does not
// show the dialog yet, the message waits for it.
TEST(Messages, AMessageRaisedBeforeItsPlaceOpensWaitsOneFrame) {
    Messages m;
    *m.at(Place::SaveAs) = "cannot write a.txt: read-only";
    frame(m, {Place::Objects}, Selection{});
    EXPECT_NE(m.text(Place::SaveAs), "");
    frame(m, {Place::SaveAs}, Selection{});
    EXPECT_NE(m.text(Place::SaveAs), "") << "shown: it stays";
}

TEST(Messages, APlaceIsOnScreenWhenTheLastFrameShowedIt) {
    Messages m;
    EXPECT_FALSE(m.onScreen(Place::Lights));
    frame(m, {Place::Lights}, Selection{});
    EXPECT_TRUE(m.onScreen(Place::Lights));
    frame(m, {}, Selection{});
    EXPECT_FALSE(m.onScreen(Place::Lights));
}

TEST(Messages, ASettingsPanelKeepsItsMessageAcrossSelections) {
    Messages m;
    *m.at(Place::View) = "fog must be between 0 and 10";
    frame(m, {Place::View}, selected(ItemKind::Object, 0));
    frame(m, {Place::View}, selected(ItemKind::Object, 1));
    EXPECT_NE(m.text(Place::View), "")
        << "the camera and render settings do not depend on the selection";
    frame(m, {}, selected(ItemKind::Object, 1));  // closed
    EXPECT_EQ(m.text(Place::View), "");
}

TEST(Messages, TheStatusLineClearsAfterItsTime) {
    ASSERT_EQ(Messages::kStatusSeconds, 8.0) << "the status line stays 8 s";
    Messages m;
    *m.at(Place::Status) = "cannot write the screenshot";
    frame(m, {}, Selection{}, 10.0);
    frame(m, {}, selected(ItemKind::Object, 2), 10.0 + Messages::kStatusSeconds - 0.1);
    EXPECT_NE(m.text(Place::Status), "") << "neither selection nor place ends it";
    frame(m, {}, Selection{}, 10.0 + Messages::kStatusSeconds);
    EXPECT_EQ(m.text(Place::Status), "");
}

TEST(Messages, TheSameStatusSaidAgainStartsItsTimeAgain) {
    Messages m;
    m.say(Place::Status, "this scene has no fog");
    frame(m, {}, Selection{}, 10.0);
    m.say(Place::Status, "this scene has no fog");  // F again, 6 s later
    EXPECT_TRUE(m.isNew(Place::Status));
    frame(m, {}, Selection{}, 16.0);
    frame(m, {}, Selection{}, 10.0 + Messages::kStatusSeconds);
    EXPECT_EQ(m.text(Place::Status), "this scene has no fog")
        << "timed from the first time it was said";
}
