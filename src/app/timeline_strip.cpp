// timeline_strip.cpp — the timeline under the view: Play, the strip of simulated time (the baked
// frames, the time shown and the camera keys, drawn with ImGui's draw list; a click or a drag
// scrubs), what the bake holds, and Loop.
#include "marchbox/editor/timeline.h"
#include "ui.h"
#include "widgets.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <imgui.h>

namespace mb {

static constexpr float kStripHeight = 24.0f;  // px
static constexpr float kStripLeft = 180.0f;   // px: Play and the time before it (e2e reads it)
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

static constexpr float kTickGap = 48.0f;  // px: room for a label such as "12.5"

static void drawStrip(const TimelineStrip& strip, float top, const Editor& e) {
    ImDrawList* d = ImGui::GetWindowDrawList();
    const float bottom = top + kStripHeight, right = strip.left + strip.width;
    d->AddRectFilled({strip.left, top}, {right, bottom}, ImGui::GetColorU32(ImGuiCol_FrameBg));
    const float baked = strip.x(e.simulation().cache().end());
    d->AddRectFilled({strip.left, top + 8}, {baked, bottom},
                     ImGui::GetColorU32(ImGuiCol_PlotHistogram, 0.6f));
    const double step = tickStep(strip, kTickGap);
    for (int i = 0; i * step <= strip.span; ++i) {  // counted, not summed: no drift in labels
        const double t = i * step;
        d->AddLine({strip.x(t), bottom - 5}, {strip.x(t), bottom},
                   ImGui::GetColorU32(ImGuiCol_Text));
        d->AddText({strip.x(t) + 2, top}, ImGui::GetColorU32(ImGuiCol_TextDisabled),
                   tickLabel(t, step).c_str());
    }
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

static void strip(UiContext& c, float width) {
    Editor& e = c.editor;
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const TimelineStrip strip = timelineStrip(at.x, width, e.simulation().cache().end(),
                                              e.scene().keyframes, e.document().time());
    const ImGuiID id = ImGui::GetID("timeline");
    ImGui::InvisibleButton("timeline", ImVec2(strip.width, kStripHeight));
    markItem("Timeline/strip");
    scrub(e, strip, id, &c.ui.heldKey);
    keyTooltip(strip, e.scene().keyframes);
    drawStrip(strip, at.y, e);
}

// How far the bake goes and its size: kB below a megabyte, never "0.0 MB".
static std::string bakeLabel(const FrameCache& cache) {
    const double megabytes = double(cache.bytes()) / 1e6;
    char text[64];
    if (megabytes < 1.0)
        std::snprintf(text, sizeof text, "baked %.2f s, %.0f kB", cache.end(), megabytes * 1e3);
    else std::snprintf(text, sizeof text, "baked %.2f s, %.1f MB", cache.end(), megabytes);
    return text;
}

static void bakeTooltip(const FrameCache& cache) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "%zu frames, each every dynamic body's state. Past %zu MB every other frame "
                  "goes, and frames are kept half as often.",
                  cache.frames(), FrameCache::kDefaultBudget >> 20);
    itemTooltip("Timeline/baked", text);
}

static void loopBox(Editor& e) {
    bool loop = e.simulation().loop();
    if (ImGui::Checkbox("Loop", &loop)) e.setLoop(loop);
    markItem("Timeline/Loop");
    itemTooltip("Timeline/Loop",
                "Play goes back to t = 0 at the last camera key, or without "
                "keys at the end of the baked frames.");
}

// The time shown, or where Play stopped by itself: "at rest, 4.20 s".
static void timeText(const Editor& e) {
    const double t = e.document().time();
    if (e.simulation().restedAt() != t) {
        ImGui::Text("%s", timeLabel(t).c_str());
        return;
    }
    ImGui::Text("at rest, %.2f s", t);
    markItem("Timeline/at rest");
    itemTooltip("Timeline/at rest",
                "Play stopped here by itself: every body is at rest, and nothing more would "
                "change.\nLoop plays on from the start instead.");
}

// In a window smaller than this the timeline gives way, as the statistics overlay does: the
// docked panels need the height, and the strip would be a few pixels wide.
static constexpr float kTimelineMinWidth = 560.0f, kTimelineMinHeight = 360.0f;  // px

static bool timelineShown(const UiState& ui) {
    const ImVec2 window = ImGui::GetIO().DisplaySize;
    return ui.showTimeline && window.x >= kTimelineMinWidth && window.y >= kTimelineMinHeight;
}

float timelineBarHeight(const UiState& ui) {
    return timelineShown(ui) ? kStripHeight + 2.0f * ImGui::GetStyle().WindowPadding.y : 0.0f;
}

void drawTimelineBar(UiContext& c) {
    c.ui.overTimeline = false;
    if (!timelineShown(c.ui)) {
        markPanelHidden("##timeline");
        return;
    }
    Editor& e = c.editor;
    const ImGuiIO& io = ImGui::GetIO();
    const ImGuiStyle& style = ImGui::GetStyle();
    ImGui::SetNextWindowPos(ImVec2(0, io.DisplaySize.y), ImGuiCond_Always, ImVec2(0, 1));
    ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, timelineBarHeight(c.ui)));
    ImGui::SetNextWindowBgAlpha(0.75f);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav |
                                   ImGuiWindowFlags_NoSavedSettings;
    if (ImGui::Begin("##timeline", nullptr, flags)) {
        markPanel();
        c.ui.overTimeline = ImGui::IsWindowHovered(ImGuiHoveredFlags_ChildWindows);
        // Every widget of the row as tall as the strip, its text level with the strip's middle.
        ImGui::PushStyleVar(
            ImGuiStyleVar_FramePadding,
            ImVec2(style.FramePadding.x, 0.5f * (kStripHeight - ImGui::GetFontSize())));
        if (ImGui::Button(e.simulation().playing() ? "Pause" : "Play", ImVec2(56, 0)))
            e.togglePlay();
        markItem("Timeline/PlayPause");
        ImGui::SameLine();
        ImGui::AlignTextToFramePadding();
        timeText(e);
        ImGui::SameLine(kStripLeft);
        const std::string baked = bakeLabel(e.simulation().cache());
        const float after = ImGui::CalcTextSize(baked.c_str()).x + ImGui::GetFrameHeight() +
                            ImGui::CalcTextSize("Loop").x + 4.0f * style.ItemSpacing.x;
        strip(c, std::max(ImGui::GetContentRegionAvail().x - after, 40.0f));
        ImGui::SameLine();
        ImGui::TextUnformatted(baked.c_str());
        bakeTooltip(e.simulation().cache());
        ImGui::SameLine();
        loopBox(e);
        ImGui::PopStyleVar();
    }
    ImGui::End();
}

}  // namespace mb
