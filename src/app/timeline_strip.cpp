// timeline_strip.cpp — the strip of simulated time in the Simulation window: the baked frames,
// the time shown and the camera keys, drawn with ImGui's draw list; a click or a drag scrubs.
#include "marchbox/editor/timeline.h"
#include "ui.h"
#include "widgets.h"

#include <cmath>
#include <imgui.h>

namespace mb {

static constexpr float kStripHeight = 24.0f;  // px
static constexpr float kKeyReach = 6.0f;  // px either side of a key's marker that take its click

// A click on a key's marker goes to the key, and dragging it on moves the key; any other
// click, and a drag, go to the time under the mouse. One press is one undo step ("Scrub",
// "Move camera key"). *held is the key the press landed on, -1 for none.
static void scrub(Editor& e, const TimelineStrip& strip, ImGuiID id, int* held) {
    const std::vector<Keyframe>& keys = e.scene().keyframes;
    const ImGuiIO& io = ImGui::GetIO();
    const bool pressed = ImGui::IsItemActivated();
    const bool dragged = ImGui::IsItemActive() && io.MouseDelta.x != 0.0f;
    if (pressed) *held = keyMarkerAt(strip, keys, io.MousePos.x, kKeyReach);
    if (pressed && *held >= 0) {
        e.seekKey(*held, id);
    } else if (dragged && *held >= 0) {
        const int to = e.moveCameraKey(*held, float(strip.time(io.MousePos.x)), id + 1);
        if (to >= 0) *held = to;  // refused where another key is: it stays where it was
    } else if (pressed || dragged) {
        e.seek(strip.time(io.MousePos.x), id);
    }
    if (ImGui::IsItemDeactivated()) e.endEdit(), *held = -1;
}

// Ticks at 1, 2 or 5 times a power of ten seconds, about 40 px apart or more.
static double tickStep(const TimelineStrip& strip) {
    const double least = strip.span * 40.0 / strip.width;
    double step = std::pow(10.0, std::floor(std::log10(least)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (step * m >= least) return step * m;
    return step * 10.0;
}

static void drawStrip(const TimelineStrip& strip, float top, const Editor& e) {
    ImDrawList* d = ImGui::GetWindowDrawList();
    const float bottom = top + kStripHeight, right = strip.left + strip.width;
    d->AddRectFilled({strip.left, top}, {right, bottom}, ImGui::GetColorU32(ImGuiCol_FrameBg));
    const float baked = strip.x(e.simulation().cache().end());
    d->AddRectFilled({strip.left, top + 8}, {baked, bottom},
                     ImGui::GetColorU32(ImGuiCol_PlotHistogram, 0.6f));
    const double step = tickStep(strip);
    for (double t = 0; t <= strip.span; t += step)
        d->AddLine({strip.x(t), bottom - 5}, {strip.x(t), bottom},
                   ImGui::GetColorU32(ImGuiCol_Text));
    for (const Keyframe& k : e.scene().keyframes) {  // diamonds along the top
        const float x = strip.x(k.t), y = top + 5;
        d->AddQuadFilled({x, y - 4}, {x + 4, y}, {x, y + 4}, {x - 4, y},
                         IM_COL32(255, 210, 60, 255));
    }
    if (e.simulation().loop()) {  // where Play goes back to t = 0
        const float end = strip.x(loopEnd(e.scene().keyframes, e.simulation().cache().end()));
        d->AddLine({end, top}, {end, bottom}, ImGui::GetColorU32(ImGuiCol_Text), 1.0f);
    }
    const float now = strip.x(e.document().time());
    d->AddLine({now, top}, {now, bottom}, IM_COL32(255, 80, 80, 255), 2.0f);
}

static void keyTooltip(const TimelineStrip& strip, const std::vector<Keyframe>& keys) {
    if (!ImGui::IsItemHovered()) return;
    const int key = keyMarkerAt(strip, keys, ImGui::GetIO().MousePos.x, kKeyReach);
    if (key < 0) return;
    char text[64];
    std::snprintf(text, sizeof text, "camera key at %.2f s: click to go there, drag to move it",
                  double(keys[size_t(key)].t));
    itemTooltip("Simulation/timeline key", text);
}

void drawTimeline(UiContext& c) {
    Editor& e = c.editor;
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float width = ImGui::GetContentRegionAvail().x;
    const TimelineStrip strip = timelineStrip(at.x, width, e.simulation().cache().end(),
                                              e.scene().keyframes, e.document().time());
    const ImGuiID id = ImGui::GetID("timeline");
    ImGui::InvisibleButton("timeline", ImVec2(strip.width, kStripHeight));
    markItem("Simulation/timeline");
    scrub(e, strip, id, &c.ui.heldKey);
    keyTooltip(strip, e.scene().keyframes);
    drawStrip(strip, at.y, e);
    const FrameCache& cache = e.simulation().cache();
    ImGui::Text("%s   baked to %.2f s: %zu frames, %.1f MB", timeLabel(e.document().time()).c_str(),
                cache.end(), cache.frames(), double(cache.bytes()) / 1e6);
    itemTooltip("Simulation/baked",
                "Each frame holds every dynamic body's state. Past 512 MB "
                "every other frame goes, and frames are kept half as often.");
}

}  // namespace mb
