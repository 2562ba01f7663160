// marchbox/editor/messages.h — refusals and failures, each shown in the place that raised it and
// only while what it was about is still there: a panel's or dialog's message goes when that
// place closes, an item panel's (and the object popup's) also when the selection changes, and
// the status line's, for what no panel owns (a screenshot that could not be written), after
// kStatusSeconds.
#pragma once

#include "marchbox/editor/selection.h"

#include <array>
#include <string>

namespace mb {

enum class Place : int {
    Objects,
    Materials,
    Lights,
    ObjectPopup,
    View,
    Simulation,
    SaveAs,
    Status
};
constexpr int kPlaceCount = 8;

Place itemPlace(ItemKind k);  // the list panel of k: Objects (groups too), Materials or Lights

class Messages {
public:
    static constexpr double kStatusSeconds = 8.0;

    // Where a place's fields and buttons write their refusals; empty: nothing to say.
    std::string* at(Place p) { return &entries_[size_t(p)].text; }
    const std::string& text(Place p) const { return entries_[size_t(p)].text; }
    // Raises `text` at p as new even when the same text already shows (F pressed twice: the
    // status line's time starts again).
    void say(Place p, const std::string& text);

    void shown(Place p);  // the place is on screen this frame (its message, if any, with it)
    bool onScreen(Place p) const { return entries_[size_t(p)].wasShown; }  // in the last frame
    bool isNew(Place p) const;  // raised (or changed) since the last endFrame

    // Ends a frame at `seconds` (any clock) with the selection as it now is. A message raised
    // during the frame stays (a dialog it opened shows it next frame); an older one goes when
    // its place was not shown, when it belongs to the selection and that changed, or, on the
    // status line, after kStatusSeconds.
    void endFrame(const Selection& selection, double seconds);

private:
    struct Entry {
        std::string text;
        std::string before;  // the text at the last endFrame: a difference is a new message
        double since = 0.0;  // when it was raised
        bool said = false;   // raised through say() since the last endFrame
        bool shown = false, wasShown = false;  // this frame, the last one
    };
    std::array<Entry, kPlaceCount> entries_;
    Selection selection_;
};

}  // namespace mb
