// marchbox/editor/input_queue.h — the window's input events, handed to the UI one state change
// at a time.
//
// Dear ImGui 1.86 reads the state of each button and key once a frame. When a frame takes longer
// than a click or a tap (a software renderer, a script), the press and its release both come
// before the next frame and the UI sees neither. So the window queues every event here as it
// comes, and each frame takes events off the front until the next would change a button or key
// that already changed in this frame: each press is seen down for at least one frame, and events
// keep their order (what ImGui 1.87 does inside with its input queue). While a text field has the
// keyboard, the keys that type characters need not be seen down, and a frame takes all the text
// up to the next key that types nothing (Return, Ctrl+A), so typing keeps up with the typist.
//
// Rules: positions in window pixels from the top left; times in seconds on the window's clock;
// buttons and keys are the window's own codes (GLFW_MOUSE_BUTTON_*, GLFW_KEY_*). No GLFW or
// ImGui here.
#pragma once

#include <glm/vec2.hpp>

#include <bitset>
#include <deque>
#include <vector>

namespace mb {

struct InputEvent {
    enum class Kind {
        Move,    // the mouse is at `at`
        Leave,   // the mouse left the window
        Button,  // `code` went down or up
        Wheel,   // scrolled by `at` (x, y) notches
        Key,     // `code` went down or up, with modifiers `mods` (no repeats: ImGui makes its own)
        Text,    // typed the character `code` (a Unicode code point)
    };
    Kind kind = Kind::Move;
    double time = 0.0;  // when the window received it
    int code = 0;
    bool down = false;
    int mods = 0;
    glm::vec2 at{0.0f};
};

// A key going down, for the shortcuts.
struct KeyPress {
    int key;   // GLFW_KEY_*
    int mods;  // GLFW_MOD_*
};

// What one frame of the UI reads: the state after the events taken, and what they brought.
struct InputState {
    static constexpr int kButtons = 8;  // GLFW_MOUSE_BUTTON_LAST + 1
    static constexpr int kKeys = 512;   // ImGui 1.86's io.KeysDown; GLFW_KEY_LAST is 348

    // Kept from frame to frame.
    glm::vec2 mouse{0.0f};
    bool mouseIn = false;  // false until the mouse moves over the window, and after it leaves
    std::bitset<kButtons> buttons;
    std::bitset<kKeys> keys;
    double time = 0.0;  // the moment this state stands for
    // This frame's alone.
    double seconds = 0.0;  // time since the last frame's state
    glm::vec2 wheel{0.0f};
    std::vector<unsigned> text;
    std::vector<KeyPress> presses;
};

class InputQueue {
public:
    void push(const InputEvent& e) { events_.push_back(e); }
    bool empty() const { return events_.empty(); }

    // Moves `s` on by one frame's events; `typing`: a text field has the keyboard. The state
    // stands for the time of the last event taken while more wait, and for `now` once the queue
    // is empty, so a catching-up UI sees the events' own spacing (a double-click stays one).
    void takeFrame(InputState* s, double now, bool typing = false);

private:
    std::deque<InputEvent> events_;
    std::bitset<InputState::kKeys> typedKeys_;  // held keys whose press typed a character
};

}  // namespace mb
