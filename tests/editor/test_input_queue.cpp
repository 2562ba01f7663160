// test_input_queue.cpp — queued input handed out one state change per frame, in order.
#include "marchbox/editor/input_queue.h"

#include <gtest/gtest.h>

using namespace mb;
using Kind = InputEvent::Kind;

namespace {

// Codes as GLFW numbers them (the queue knows none of them).
constexpr int kLeft = 0, kKeyA = 65, kKeyX = 88, kEnter = 257, kCtrl = 341, kModCtrl = 2;

InputEvent move(float x, float y, double t = 0.0) {
    return {.kind = Kind::Move, .time = t, .at = {x, y}};
}
InputEvent button(bool down, double t = 0.0) {
    return {.kind = Kind::Button, .time = t, .code = kLeft, .down = down};
}
InputEvent key(int code, bool down, int mods = 0) {
    return {.kind = Kind::Key, .code = code, .down = down, .mods = mods};
}
InputEvent text(char c) { return {.kind = Kind::Text, .code = c}; }

struct Frames {
    InputQueue queue;
    InputState state;
    void push(std::initializer_list<InputEvent> events) {
        for (const InputEvent& e : events) queue.push(e);
    }
    const InputState& next(double now = 0.0, bool typing = false) {
        queue.takeFrame(&state, now, typing);
        return state;
    }
    const InputState& nextTyping() { return next(0.0, true); }
};

}  // namespace

TEST(InputQueue, AClickInsideOneFrameIsSeenDownThenUp) {
    Frames f;
    f.push({button(true), button(false)});
    EXPECT_TRUE(f.next().buttons[kLeft]);
    EXPECT_FALSE(f.next().buttons[kLeft]);
    EXPECT_TRUE(f.queue.empty());
}

TEST(InputQueue, AShortTapIsPressedOnceAndHeldForOneFrame) {
    Frames f;
    f.push({key(kKeyA, true), key(kKeyA, false)});
    const InputState& s = f.next();
    EXPECT_TRUE(s.keys[kKeyA]);
    ASSERT_EQ(s.presses.size(), 1u);
    EXPECT_EQ(s.presses[0].key, kKeyA);
    EXPECT_FALSE(f.next().keys[kKeyA]);
    EXPECT_TRUE(f.state.presses.empty());
}

TEST(InputQueue, ADragInsideOneFramePressesWhereItStartsAndReleasesWhereItEnds) {
    Frames f;
    f.push({move(10, 10), button(true), move(20, 10), move(40, 12), button(false)});
    const InputState& pressed = f.next();
    EXPECT_TRUE(pressed.buttons[kLeft]);
    EXPECT_EQ(pressed.mouse, glm::vec2(10, 10));
    const InputState& released = f.next();  // the motion and the release that ends it
    EXPECT_FALSE(released.buttons[kLeft]);
    EXPECT_EQ(released.mouse, glm::vec2(40, 12));
}

TEST(InputQueue, EachKeyPressGetsItsOwnFrame) {
    // Ctrl+A: Ctrl is down in the frame that sees A go down.
    Frames f;
    f.push({key(kCtrl, true), key(kKeyA, true, kModCtrl), key(kKeyA, false, kModCtrl),
            key(kCtrl, false)});
    EXPECT_TRUE(f.next().keys[kCtrl]);
    EXPECT_FALSE(f.state.keys[kKeyA]);
    const InputState& a = f.next();
    EXPECT_TRUE(a.keys[kCtrl] && a.keys[kKeyA]);
    ASSERT_EQ(a.presses.size(), 1u);
    EXPECT_EQ(a.presses[0].mods, kModCtrl);
    EXPECT_FALSE(f.next().keys[kKeyA]);
    EXPECT_FALSE(f.state.keys[kCtrl]);
}

TEST(InputQueue, TextTypedAfterReturnWaitsForReturnsFrame) {
    // ImGui reads a frame's text before its keys: an x with Return would go into the field
    // that Return closes.
    Frames f;
    f.push({text('1'), key(kEnter, true), key(kEnter, false), key(kKeyX, true), text('x')});
    const InputState& enter = f.next();
    EXPECT_EQ(enter.text, std::vector<unsigned>{'1'});
    EXPECT_TRUE(enter.keys[kEnter]);
    const InputState& x = f.next();
    EXPECT_FALSE(x.keys[kEnter]);
    EXPECT_EQ(x.text, std::vector<unsigned>{'x'});
}

TEST(InputQueue, IntoAFieldTheTextUpToAKeyThatTypesNothingIsOneFrame) {
    Frames f;
    f.push({key('1', true), text('1'), key('1', false), key('5', true), text('5'), key('5', false),
            key('5', true), text('5'), key('5', false), key(kEnter, true), key(kEnter, false),
            key(kKeyX, true), text('x')});
    const InputState& typed = f.nextTyping();
    EXPECT_EQ(typed.text, (std::vector<unsigned>{'1', '5', '5'}));
    EXPECT_TRUE(typed.keys[kEnter]);  // after the text, as ImGui reads them
    EXPECT_EQ(typed.presses.size(), 4u);
    const InputState& x = f.nextTyping();
    EXPECT_FALSE(x.keys[kEnter]);
    EXPECT_EQ(x.text, std::vector<unsigned>{'x'});
}

TEST(InputQueue, OutsideAFieldEveryKeyIsSeenDown) {
    // W flies the camera while a frame sees it down.
    Frames f;
    f.push(
        {key('1', true), text('1'), key('1', false), key('W', true), text('w'), key('W', false)});
    EXPECT_TRUE(f.next().keys['1']);
    EXPECT_TRUE(f.next().keys['W']);
    EXPECT_FALSE(f.next().keys['W']);
}

TEST(InputQueue, IntoAFieldCtrlAStillSelectsBeforeTheTextThatReplacesIt) {
    Frames f;  // Ctrl let go first, as xdotool's keyup ctrl+a does
    f.push({key(kCtrl, true), key(kKeyA, true, kModCtrl), key(kCtrl, false), key(kKeyA, false),
            key(kKeyX, true), text('x')});
    EXPECT_TRUE(f.nextTyping().keys[kCtrl]);
    const InputState& a = f.nextTyping();
    EXPECT_TRUE(a.keys[kCtrl] && a.keys[kKeyA] && a.text.empty());
    const InputState& x = f.nextTyping();
    EXPECT_FALSE(x.keys[kCtrl]);
    EXPECT_EQ(x.text, std::vector<unsigned>{'x'});
}

TEST(InputQueue, TypingAfterAClickWaitsForTheNextFrame) {
    Frames f;
    f.push({button(true), button(false), key(kKeyX, true), text('x')});
    EXPECT_TRUE(f.next().text.empty());
    EXPECT_TRUE(f.state.buttons[kLeft]);
    EXPECT_TRUE(f.next().text.empty());  // the release
    EXPECT_EQ(f.next().text, std::vector<unsigned>{'x'});
}

TEST(InputQueue, EventsThatChangeNothingNeverSplitAFrame) {
    Frames f;  // a release never seen pressed (pressed before the window opened), a bad code
    f.push({key(kKeyA, false), key(-1, true), key(InputState::kKeys, true), key(kKeyA, true),
            key(kKeyX, true)});
    const InputState& s = f.next();
    EXPECT_TRUE(s.keys[kKeyA]);
    EXPECT_EQ(s.presses.size(), 1u);
    EXPECT_FALSE(f.queue.empty());  // X waits: it is a second press
}

TEST(InputQueue, TheWheelAddsUpWithinAFrameAndTheMotionAfterItWaits) {
    Frames f;
    f.push({{.kind = Kind::Wheel, .at = {0, 1}}, {.kind = Kind::Wheel, .at = {0, 2}}, move(5, 5)});
    EXPECT_EQ(f.next().wheel, glm::vec2(0, 3));
    EXPECT_FALSE(f.state.mouseIn);
    EXPECT_EQ(f.next().wheel, glm::vec2(0, 0));
    EXPECT_TRUE(f.state.mouseIn);
}

TEST(InputQueue, ABackloggedScrollWithMotionIsMergedNotReplayed) {
    // A touchpad's wheel and motion in turn, 20 notches over 0.2 s.
    Frames f;
    for (int i = 0; i < 20; ++i)
        f.push({{.kind = Kind::Wheel, .time = 0.01 * i, .at = {0, 1}},
                move(float(i), 0, 0.01 * i + 0.005)});
    EXPECT_EQ(f.next(0.1).wheel, glm::vec2(0, 1));   // up to date: the motion waits for its frame
    EXPECT_EQ(f.next(1.0).wheel, glm::vec2(0, 19));  // a second behind: the rest in one frame
    EXPECT_EQ(f.state.mouse, glm::vec2(19, 0));
    EXPECT_TRUE(f.queue.empty());
}

TEST(InputQueue, TheMouseIsOutsideUntilItMovesInAndAfterItLeaves) {
    Frames f;
    EXPECT_FALSE(f.next().mouseIn);
    f.push({move(1, 2)});
    EXPECT_TRUE(f.next().mouseIn);
    f.push({{.kind = Kind::Leave}});
    EXPECT_FALSE(f.next().mouseIn);
}

TEST(InputQueue, ACatchingUpStateKeepsTheEventsSpacing) {
    // A double-click received in one poll at t = 5, read out over frames that start at 7, 8, 9:
    // both presses stand at t = 5, so the clicks are no further apart than they came.
    Frames f;
    f.push({button(true, 5.0), button(false, 5.0), button(true, 5.0), button(false, 5.0)});
    f.state.time = 4.0;
    EXPECT_EQ(f.next(7.0).time, 5.0);
    EXPECT_EQ(f.state.seconds, 1.0);
    EXPECT_EQ(f.next(8.0).time, 5.0);
    EXPECT_TRUE(f.next(9.0).buttons[kLeft]);
    EXPECT_EQ(f.state.time, 5.0);
    EXPECT_EQ(f.state.seconds, 0.0);
    // The last event: the state is now, as the frame starts.
    EXPECT_EQ(f.next(10.0).time, 10.0);
    EXPECT_EQ(f.state.seconds, 5.0);
    EXPECT_EQ(f.next(10.5).seconds, 0.5);
}
