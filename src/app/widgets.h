// widgets.h — ImGui fields that only ever hand back values the editor accepts, each with a
// tooltip, and marks that tell the event log where a widget is (end-to-end tests click them like
// a person would).
#pragma once

#include "marchbox/editor/fields.h"

#include <glm/vec3.hpp>
#include <imgui.h>
#include <string>

namespace mb {

// What a panel's fields did this frame: whether one changed, which widget (its ImGui id keys the
// undo step, so one drag is one step), and why a typed value was refused.
struct FieldEdit {
    bool changed = false;
    ImGuiID key = 0;
    std::string* error = nullptr;  // the message of the panel's place (messages.h)
};

// Sliders where the field's spec asks for one, drags for the rest; a click on a drag (Ctrl+click
// on a slider) types a value, which is taken when the field lets go of the keyboard (Return, a
// click elsewhere; Esc drops it), never at each key. Each writes *v only when acceptField()
// takes the new value; a refusal goes to the message line and to the event log ("refuse
// MESSAGE"). Hovering shows fieldTooltip(). With the event log on, each is marked as
// "WINDOW/LABEL".
void fieldFloat(const char* label, Field f, float* v, FieldEdit& e);
void fieldInt(const char* label, Field f, int* v, FieldEdit& e);
void fieldVec3(const char* label, Field f, glm::vec3* v, FieldEdit& e);
void fieldColor(const char* label, Field f, glm::vec3* v, FieldEdit& e);  // picker, HDR allowed
void fieldFlag(const char* label, bool* v, FieldEdit& e, const char* tooltip);
// A combo's choices are marked too while its list is open: "WINDOW/LABEL/CHOICE".
void fieldCombo(const char* label, int* v, const char* const names[], int count, FieldEdit& e,
                const char* tooltip);

// Whether a field for text (a name, a path) has the keyboard. Anywhere else a typed ',' is the
// decimal point, as where the user writes numbers so: "0,5" (ImGui's number filter dropped the
// comma, and 0.5 became 5). A click and the keys after it can come in one frame, before the
// number field they go to has the keyboard: so not "a number field has it".
bool typingText();

// The tooltip of the last item while the mouse rests on it; told to the event log as
// "tooltip NAME" when it shows.
void itemTooltip(const std::string& name, const std::string& text);

// The refusal of the last typed value, in red and wrapped at the window's edge, while there is
// one.
void fieldErrorLine(const std::string& error);

// A hint in the panel's faint text, wrapped at the window's edge rather than cut off there.
void hintLine(const std::string& hint);

// A dialog's status under its fields, wrapped, marked as `name`; scrolled into sight when it
// changes (*shown: the status last drawn), since a panel short of room clips its last lines.
void statusLine(const std::string& status, std::string* shown, const std::string& name);

// With the event log on, writes "widget NAME X Y" (the last item's centre in window pixels)
// when the item shows up or moves.
void markItem(const std::string& name);

// The same for each part of the last item, an n-part field (pos, colour): "NAME[0]" to
// "NAME[n-1]"; `button` is the width right of the parts that is no part (a colour's swatch).
void markParts(const std::string& name, int n, float button);

// With the event log on, writes "panel NAME X Y W H" (the window being drawn, in window pixels)
// when it shows up, moves or changes size.
void markPanel();

// With the event log on, writes "hidden panel NAME" when a panel that showed gives way.
void markPanelHidden(const std::string& name);

// With the event log on, writes "typing NAME" when the last item (a text field) takes the
// keyboard: from then on typed characters reach it.
void markTyping(const std::string& name);

// Writes "popup NAME open" or "popup NAME closed" when a popup's state changes; call it every
// frame with what BeginPopup returned.
void markPopup(const std::string& name, bool open);

// "NAME" under the window being drawn: "Objects/radius".
std::string itemPath(const char* label);

}  // namespace mb
