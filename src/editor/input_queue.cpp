// input_queue.cpp — one frame's worth of the window's queued input at a time.
#include "marchbox/editor/input_queue.h"

#include <algorithm>

namespace mb {

namespace {

constexpr double kMaxLag = 0.25;  // s: more and motion is merged rather than replayed

using Kind = InputEvent::Kind;

bool inRange(int code, int count) { return code >= 0 && code < count; }

// Whether `e` changes a button's or a key's state: a release of a key never seen down does not.
bool changesState(const InputState& s, const InputEvent& e) {
    if (e.kind == Kind::Button)
        return inRange(e.code, InputState::kButtons) && s.buttons[size_t(e.code)] != e.down;
    if (e.kind == Kind::Key)
        return inRange(e.code, InputState::kKeys) && s.keys[size_t(e.code)] != e.down;
    return false;
}

// The frame being taken, and what changed in it so far.
class Frame {
public:
    Frame(InputState* s, bool typing, bool behind) : s_(*s), typing_(typing), behind_(behind) {}

    // Whether `e` may join this frame. typingKey: a key that types a character while a field
    // has the keyboard, whose state nobody needs to see.
    bool fits(const InputEvent& e, bool typingKey) const;
    // typesText: a press whose character comes next.
    void apply(const InputEvent& e, bool typingKey, bool typesText);

private:
    InputState& s_;
    bool typing_;
    bool behind_;  // the queue's oldest event is kMaxLag old: motion joins wheels
    std::bitset<InputState::kButtons> buttons_;  // changed in this frame
    std::bitset<InputState::kKeys> keys_;
    bool keyWentDown_ = false, silentKeyWentDown_ = false, wheeled_ = false;
};

// A press and the motion after it are seen apart, so a drag starts where the button went down
// and a click stays a click. Text and keys after a click go to what the click chose. A key that
// goes down is seen with the keys held as it went (Ctrl+A released Ctrl first is still Ctrl+A).
// ImGui reads a frame's text before its keys, so nothing is typed after a key that types nothing
// (Return then "x" must not put the x into the field Return closes). A wheel turns under the
// mouse where it was, so motion after it waits, unless the queue has fallen behind: a touchpad
// sends wheel and motion in turn, and a frame each would replay a scroll seconds late.
bool Frame::fits(const InputEvent& e, bool typingKey) const {
    const bool clicked = buttons_.any();
    switch (e.kind) {
        case Kind::Move:
        case Kind::Leave:
            return !clicked && (!wheeled_ || behind_);
        case Kind::Wheel:
            return true;
        case Kind::Text:
            return !clicked && !silentKeyWentDown_;
        case Kind::Button:
            return !changesState(s_, e) || !buttons_[size_t(e.code)];
        case Kind::Key:
            if (!changesState(s_, e)) return true;
            if (clicked) return false;
            if (typingKey) return !silentKeyWentDown_;
            return !keys_[size_t(e.code)] && !(typing_ ? silentKeyWentDown_ : keyWentDown_);
    }
    return true;
}

void Frame::apply(const InputEvent& e, bool typingKey, bool typesText) {
    const bool change = changesState(s_, e);
    switch (e.kind) {
        case Kind::Move:
            s_.mouse = e.at;
            s_.mouseIn = true;
            break;
        case Kind::Leave:
            s_.mouseIn = false;
            break;
        case Kind::Wheel:
            s_.wheel += e.at;
            wheeled_ = true;
            break;
        case Kind::Text:
            s_.text.push_back(unsigned(e.code));
            break;
        case Kind::Button:
            if (!change) break;
            s_.buttons[size_t(e.code)] = e.down;
            buttons_.set(size_t(e.code));
            break;
        case Kind::Key:
            if (!change) break;
            s_.keys[size_t(e.code)] = e.down;
            if (!typingKey) keys_.set(size_t(e.code));
            if (!e.down) break;
            keyWentDown_ = true;
            silentKeyWentDown_ = silentKeyWentDown_ || !typesText;
            s_.presses.push_back({e.code, e.mods});
            break;
    }
}

}  // namespace

void InputQueue::takeFrame(InputState* s, double now, bool typing) {
    s->wheel = glm::vec2(0.0f);
    s->text.clear();
    s->presses.clear();
    Frame frame(s, typing, !events_.empty() && now - events_.front().time > kMaxLag);
    double last = s->time;
    while (!events_.empty()) {
        const InputEvent& e = events_.front();
        const bool key = e.kind == Kind::Key && inRange(e.code, InputState::kKeys);
        // GLFW gives a key's character right after its press.
        const bool typesText = key && e.down && events_.size() > 1 && events_[1].kind == Kind::Text;
        const bool typingKey = typing && key && (e.down ? typesText : typedKeys_[size_t(e.code)]);
        if (!frame.fits(e, typingKey)) break;
        if (key && changesState(*s, e)) typedKeys_[size_t(e.code)] = typesText;
        frame.apply(e, typingKey, typesText);
        last = e.time;
        events_.pop_front();
    }
    const double time = events_.empty() ? now : last;
    s->seconds = std::max(0.0, time - s->time);
    s->time = std::max(s->time, time);
}

}  // namespace mb
