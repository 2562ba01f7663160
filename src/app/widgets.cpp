// widgets.cpp — validated ImGui fields and the widget marks of the event log.
#include "widgets.h"

#include "marchbox/editor/events.h"

#include <cfloat>
#include <cmath>
#include <map>

namespace mb {

// Records the outcome of one widget: a valid value is taken, an invalid one only explained.
template <typename T>
static void settle(const char* label, bool edited, const T& value, bool valid,
                   const std::string& why, T* out, FieldEdit& e) {
    if (!edited) return;
    if (!valid) {
        if (e.error) *e.error = why;
        return;
    }
    *out = value;
    e.changed = true;
    e.key = ImGui::GetID(label);  // the widget's own id: same label, same stack
    if (e.error) e.error->clear();
}

static bool drawFloats(const char* label, Field f, float* v, int n) {
    const FieldSpec& s = fieldSpec(f);
    if (std::isfinite(s.max) && std::isfinite(s.min))
        return ImGui::SliderScalarN(label, ImGuiDataType_Float, v, n, &s.dragMin, &s.dragMax, s.format);
    // Unbounded fields drag at a pace set by their comfortable range, clamped only below.
    float lo = std::isfinite(s.min) ? (s.minExclusive ? s.dragMin : float(s.min)) : -FLT_MAX;
    float hi = FLT_MAX;
    float speed = (s.dragMax - s.dragMin) / 400.0f;
    return ImGui::DragScalarN(label, ImGuiDataType_Float, v, n, speed, &lo, &hi, s.format);
}

void fieldFloat(const char* label, Field f, float* v, FieldEdit& e) {
    float value = *v;
    bool edited = drawFloats(label, f, &value, 1);
    std::string why;
    bool valid = edited && validateField(f, value, &why);
    settle(label, edited, value, valid, why, v, e);
}

void fieldInt(const char* label, Field f, int* v, FieldEdit& e) {
    const FieldSpec& s = fieldSpec(f);
    int value = *v, lo = int(s.dragMin), hi = int(s.dragMax);
    bool edited = ImGui::SliderInt(label, &value, lo, hi);
    std::string why;
    bool valid = edited && validateField(f, value, &why);
    settle(label, edited, value, valid, why, v, e);
}

void fieldVec3(const char* label, Field f, glm::vec3* v, FieldEdit& e) {
    glm::vec3 value = *v;
    bool edited = drawFloats(label, f, &value.x, 3);
    std::string why;
    bool valid = edited && validateVec(f, value, &why);
    settle(label, edited, value, valid, why, v, e);
}

void fieldColor(const char* label, Field f, glm::vec3* v, FieldEdit& e) {
    glm::vec3 value = *v;
    bool edited = ImGui::ColorEdit3(label, &value.x, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
    std::string why;
    bool valid = edited && validateVec(f, value, &why);
    settle(label, edited, value, valid, why, v, e);
}

void fieldFlag(const char* label, bool* v, FieldEdit& e) {
    bool value = *v;
    bool edited = ImGui::Checkbox(label, &value);
    settle(label, edited, value, true, "", v, e);
}

void fieldCombo(const char* label, int* v, const char* const names[], int count, FieldEdit& e) {
    int value = *v;
    bool edited = ImGui::Combo(label, &value, names, count);
    settle(label, edited, value, true, "", v, e);
}

void fieldErrorLine(const std::string& error) {
    if (!error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", error.c_str());
}

void markItem(const std::string& name) {
    // A window's first frame lays it out before it knows its size (auto-resized popups move
    // on the next frame): a mark from then would send a click to the wrong place.
    if (!eventsOn() || ImGui::IsWindowAppearing()) return;
    struct Mark {
        ImVec2 centre;
        int frame;
    };
    static std::map<std::string, Mark> last;
    ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    ImVec2 centre((lo.x + hi.x) * 0.5f, (lo.y + hi.y) * 0.5f);
    const int frame = ImGui::GetFrameCount();
    auto it = last.find(name);
    // Written when the widget moves or shows again after a gap (a popup reopened), so a test
    // can wait for a mark that belongs to what is on screen now.
    bool same = it != last.end() && it->second.frame == frame - 1 &&
                it->second.centre.x == centre.x && it->second.centre.y == centre.y;
    last[name] = {centre, frame};
    if (same) return;
    emitEvent("widget " + name + " " + std::to_string(int(centre.x)) + " " + std::to_string(int(centre.y)));
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
