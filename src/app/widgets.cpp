// widgets.cpp — validated ImGui fields, their tooltips, and the widget marks of the event log.
#include "widgets.h"

#include "marchbox/editor/events.h"
#include "ui.h"

#include <imgui_internal.h>  // the active item's text state: typing is told apart from dragging

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>

namespace mb {

namespace {

constexpr double kTooltipDelay = 0.5;  // s the mouse rests on a field before its tooltip shows

// True while a text field has the keyboard: a clicked drag, a Ctrl+clicked slider, a text box.
bool typingNow() {
    ImGuiID active = ImGui::GetActiveID();
    return active != 0 && ImGui::GetInputTextState(active) != nullptr;
}

// ImGui 1.86 applies a Ctrl+clicked field's text at every key, so "1e40" passes through 1e4 on
// its way. What is typed waits here, by widget id, until the field lets go of the keyboard.
struct Typed {
    std::array<float, 3> value{};
    bool edited = false;  // a key changed the value
    int frame = 0;        // the last frame the field was typed into
};
std::map<ImGuiID, Typed>& typedFields() {
    static std::map<ImGuiID, Typed> fields;
    return fields;
}

// This frame's outcome of field `id` of n floats, after the widget ran: true with `value` set
// when there is a value to check now. Drags give one every frame; typing gives one when it ends.
bool settleTyping(ImGuiID id, const std::string& path, bool edited, float* value, int n) {
    static ImGuiID typingId = 0;  // the field that has the keyboard, told once to the event log
    const int frame = ImGui::GetFrameCount();
    auto& typed = typedFields();
    if (ImGui::IsItemActive() && typingNow()) {
        if (typingId != id) emitEvent("typing " + path);
        typingId = id;
        Typed& t = typed[id];
        t.frame = frame;
        if (edited) std::copy(value, value + n, t.value.begin());
        t.edited |= edited;
        return false;
    }
    if (typingId == id) typingId = 0;
    auto it = typed.find(id);
    if (it == typed.end()) return edited;
    // The field let go this frame: Return or a click elsewhere takes the text, Esc drops it.
    // An entry from an earlier frame belongs to a field that went away while typed into.
    const Typed t = it->second;
    typed.erase(it);
    if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) return false;
    if (edited) return true;  // the last key and Return in one frame: this value is the text
    if (!t.edited || t.frame != frame - 1) return false;
    std::copy(t.value.begin(), t.value.begin() + n, value);
    return true;
}

// A field typed into goes on from what was typed so far: Tab and Shift+Tab move the keyboard to
// the next part of a vector, and the parts typed before it must not fall back to the stored
// value while the field waits for Return.
void resumeTyping(ImGuiID id, float* value, int n) {
    auto it = typedFields().find(id);
    if (it != typedFields().end() && it->second.edited)
        std::copy(it->second.value.begin(), it->second.value.begin() + n, value);
}

void refuse(FieldEdit& e, const std::string& why) {
    if (e.error) *e.error = why;
    emitEvent("refuse " + why);
}

void take(const char* label, FieldEdit& e) {
    e.changed = true;
    e.key = ImGui::GetID(label);  // the widget's own id: same label, same stack
    if (e.error) e.error->clear();
}

// A value that would print as "-0.0" shows as 0.0: the sign of a rounding error says nothing.
// Only what is shown: the stored value changes when the field is edited, as ever.
void withoutMinusZero(const char* format, float* v, int n) {
    const char* dot = std::strchr(format, '.');
    const float half = 0.5f * std::pow(10.0f, -float(dot ? std::atoi(dot + 1) : 0));
    for (int i = 0; i < n; ++i)
        if (std::abs(v[i]) < half) v[i] = 0.0f;
}

bool drawFloats(const char* label, Field f, float* v, int n) {
    const FieldSpec& s = fieldSpec(f);
    withoutMinusZero(s.format, v, n);
    resumeTyping(ImGui::GetID(label), v, n);
    if (s.slider)
        return ImGui::SliderScalarN(label, ImGuiDataType_Float, v, n, &s.dragMin, &s.dragMax,
                                    s.format);
    // Drags move at a pace set by their comfortable range and stop at the accepted range.
    float lo = s.minExclusive ? s.dragMin : float(s.min), hi = float(s.max);
    float speed = (s.dragMax - s.dragMin) / 400.0f;
    return ImGui::DragScalarN(label, ImGuiDataType_Float, v, n, speed, &lo, &hi, s.format);
}

// The common end of every numeric field: mark, typing, check, store, tooltip.
void finishFloats(const char* label, Field f, bool edited, float* value, float* stored, int n,
                  FieldEdit& e, float button = 0.0f) {
    const std::string path = itemPath(label);
    markItem(path);
    markParts(path, n, button);
    bool ready = settleTyping(ImGui::GetID(label), path, edited, value, n);
    if (ready && !std::equal(value, value + n, stored)) {
        std::string why;
        bool ok = n == 1 ? acceptField(f, value[0], stored[0], &why)
                         : acceptVec(f, {value[0], value[1], value[2]},
                                     {stored[0], stored[1], stored[2]}, &why);
        if (ok) {
            std::copy(value, value + n, stored);
            take(label, e);
        } else {
            refuse(e, why);
        }
    }
    itemTooltip(path, fieldTooltip(f));
}

}  // namespace

// A drag's or a slider's typed value is a temporary input over it: every other text field is
// one for text.
bool typingText() {
    const ImGuiID active = ImGui::GetActiveID();
    return ImGui::GetInputTextState(active) && !ImGui::TempInputIsActive(active);
}

void fieldFloat(const char* label, Field f, float* v, FieldEdit& e) {
    float value = *v;
    bool edited = drawFloats(label, f, &value, 1);
    finishFloats(label, f, edited, &value, v, 1, e);
}

void fieldInt(const char* label, Field f, int* v, FieldEdit& e) {
    const FieldSpec& s = fieldSpec(f);
    int value = *v;
    bool edited = ImGui::SliderInt(label, &value, int(s.dragMin), int(s.dragMax));
    // Whole numbers up to 4096 are exact as floats.
    float asFloat = float(value), stored = float(*v);
    finishFloats(label, f, edited, &asFloat, &stored, 1, e);
    *v = int(stored);
}

void fieldVec3(const char* label, Field f, glm::vec3* v, FieldEdit& e) {
    glm::vec3 value = *v;
    bool edited = drawFloats(label, f, &value.x, 3);
    finishFloats(label, f, edited, &value.x, &v->x, 3, e);
}

void fieldColor(const char* label, Field f, glm::vec3* v, FieldEdit& e) {
    glm::vec3 value = *v;
    resumeTyping(ImGui::GetID(label), &value.x, 3);
    bool edited =
        ImGui::ColorEdit3(label, &value.x, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
    const float swatch = ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x;
    finishFloats(label, f, edited, &value.x, &v->x, 3, e, swatch);
}

void fieldFlag(const char* label, bool* v, FieldEdit& e, const char* tooltip) {
    if (ImGui::Checkbox(label, v)) take(label, e);
    markItem(itemPath(label));
    itemTooltip(itemPath(label), tooltip);
}

void fieldCombo(const char* label, int* v, const char* const names[], int count, FieldEdit& e,
                const char* tooltip) {
    const std::string path = itemPath(label);
    if (ImGui::BeginCombo(label, *v >= 0 && *v < count ? names[*v] : "")) {
        for (int i = 0; i < count; ++i) {
            if (ImGui::Selectable(names[i], i == *v) && i != *v) {
                *v = i;
                take(label, e);
            }
            markItem(path + "/" + names[i]);  // "Objects/op/subtract", where the list shows it
        }
        ImGui::EndCombo();
    }
    markItem(path);
    itemTooltip(path, tooltip);
}

void itemTooltip(const std::string& name, const std::string& text) {
    // The rest starts when the mouse comes to an item and ends when it leaves or presses.
    static std::string resting;
    static double since = 0.0;
    static int seenFrame = -2, shownFrame = -2;
    const int frame = ImGui::GetFrameCount();
    // A disabled item still says why it is disabled.
    if (!ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled) || ImGui::IsItemActive()) {
        if (resting == name) resting.clear();
        return;
    }
    if (resting != name || seenFrame != frame - 1) {
        resting = name;
        since = ImGui::GetTime();
    }
    seenFrame = frame;
    if (ImGui::GetTime() - since < kTooltipDelay) return;
    ImGui::SetTooltip("%s", text.c_str());
    if (shownFrame != frame - 1) emitEvent("tooltip " + name);
    shownFrame = frame;
}

void fieldErrorLine(const std::string& error) {
    if (error.empty()) return;
    // Wrapped at the window's edge: a refusal names two values and ran off a panel.
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextWrapped("%s", error.c_str());
    ImGui::PopStyleColor();
}

void hintLine(const std::string& hint) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", hint.c_str());
    ImGui::PopStyleColor();
}

std::string itemPath(const char* label) {
    return std::string(ImGui::GetCurrentWindowRead()->Name) + "/" + label;
}

// Writes `line` when it differs from the last one written for `name`, or when `name` shows
// again after a gap of a frame or more.
static void markChange(const std::string& name, const std::string& line) {
    struct Mark {
        std::string line;
        int frame;
    };
    static std::map<std::string, Mark> last;
    const int frame = ImGui::GetFrameCount();
    auto it = last.find(name);
    bool same = it != last.end() && it->second.frame == frame - 1 && it->second.line == line;
    last[name] = {line, frame};
    if (!same) emitEvent(line);
}

static std::string whole(float v) { return std::to_string(int(v)); }

// A window's first frame lays it out before it knows its size (auto-resized popups move on the
// next frame): a mark from then would send a click to the wrong place.
static bool marking() { return eventsOn() && !ImGui::IsWindowAppearing(); }

// The mark of `name` at `centre`, in window pixels.
static void markAt(const std::string& name, ImVec2 centre) {
    // Written when the widget moves or shows again after a gap (a popup reopened), so a test
    // can wait for a mark that belongs to what is on screen now. A clipped widget (scrolled
    // away, or a row the window has yet to grow to) is marked hidden: a click there would
    // land on something else.
    const bool shown = ImGui::GetCurrentWindow()->ClipRect.Contains(centre);
    markChange("widget " + name,
               shown ? "widget " + name + " " + whole(centre.x) + " " + whole(centre.y)
                     : "hidden " + name);
}

void markItem(const std::string& name) {
    if (!marking()) return;
    ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    markAt(name, ImVec2((lo.x + hi.x) * 0.5f, (lo.y + hi.y) * 0.5f));
}

void markParts(const std::string& name, int n, float button) {
    if (n < 2 || !marking()) return;
    // As ImGui splits the field's width (PushMultiItemsWidths): n parts, ItemInnerSpacing apart.
    const float spacing = ImGui::GetStyle().ItemInnerSpacing.x;
    const float part = (ImGui::CalcItemWidth() - button + spacing) / float(n);
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    for (int i = 0; i < n; ++i)
        markAt(name + "[" + std::to_string(i) + "]",
               ImVec2(lo.x + (float(i) + 0.5f) * part - spacing * 0.5f, (lo.y + hi.y) * 0.5f));
}

void markPanelHidden(const std::string& name) {
    if (eventsOn()) markChange("panel " + name, "hidden panel " + name);
}

void markPanel() {
    if (!marking()) return;
    const std::string name = ImGui::GetCurrentWindowRead()->Name;
    ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    markChange("panel " + name, "panel " + name + " " + whole(pos.x) + " " + whole(pos.y) + " " +
                                    whole(size.x) + " " + whole(size.y));
}

unsigned UiState::openPanels() const {
    const bool shown[kPanelCount] = {showObjects, showMaterials,  showLights,
                                     showView,    showSimulation,
                                     showRender || showAnimation || showExport,
                                     showHelp};
    unsigned open = 0;
    for (int p = 0; p < kPanelCount; ++p) open |= shown[p] ? panelBit(Panel(p)) : 0u;
    return open;
}

PanelFrame panelFrame(const UiState& ui) {
    const ImGuiIO& io = ImGui::GetIO();
    return {io.DisplaySize.x, io.DisplaySize.y - timelineBarHeight(ui), ImGui::GetFrameHeight(),
            ui.statsBottom};
}

ViewWindow viewWindow(const UiState& ui) {
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    if (size.x <= 0.0f || size.y <= 0.0f) return {};
    const PanelRect r = uncoveredRoom(panelFrame(ui), ui.openPanels());
    // Window pixels run right and down from the top-left; the view's units right and up.
    return {size.x / size.y,
            {2.0f * r.x / size.x - 1.0f, 1.0f - 2.0f * (r.y + r.height) / size.y},
            {2.0f * (r.x + r.width) / size.x - 1.0f, 1.0f - 2.0f * r.y / size.y}};
}

bool beginPanel(UiContext& c, Panel p, const char* title, bool* open) {
    const PanelFrame frame = panelFrame(c.ui);
    const PanelRect r = layoutPanels(frame, c.ui.openPanels())[size_t(p)];
    PanelRect& placed = c.ui.placed[size_t(p)];
    const bool moved = !(r == placed);
    placed = r;
    ImGui::SetNextWindowPos(ImVec2(r.x, r.y), moved ? ImGuiCond_Always : ImGuiCond_Appearing);
    // A panel dragged lower has less room before the window's bottom.
    const ImGuiWindow* w = ImGui::FindWindowByName(title);
    const float top = moved || !w ? r.y : w->Pos.y;
    const float room = std::max(frame.height - kPanelMargin - top, kPanelMinHeight);
    ImGui::SetNextWindowSizeConstraints(ImVec2(r.width, 0.0f),
                                        ImVec2(r.width, std::min(r.height, room)));
    bool shown = ImGui::Begin(title, open, ImGuiWindowFlags_AlwaysAutoResize);
    markPanel();
    return shown;
}

void statusLine(const std::string& status, std::string* shown, const std::string& name) {
    if (status.empty()) return;
    ImGui::TextWrapped("%s", status.c_str());
    markItem(name);
    if (status != *shown) ImGui::SetScrollHereY(1.0f);
    *shown = status;
}

void messageLine(UiContext& c, Place p) {
    c.ui.messages.shown(p);
    fieldErrorLine(c.ui.messages.text(p));
    if (c.ui.messages.isNew(p))
        ImGui::SetScrollHereY(1.0f);  // below a panel's fold it would go unseen
}

void markPopup(const std::string& name, bool open) {
    static std::map<std::string, bool> shown;
    bool& was = shown[name];
    if (was != open) emitEvent("popup " + name + (open ? " open" : " closed"));
    was = open;
}

void markTyping(const std::string& name) {
    if (ImGui::IsItemActivated()) emitEvent("typing " + name);
}

}  // namespace mb
