// panel_layout.cpp — the editor's two columns of panels (see panel_layout.h).
#include "marchbox/editor/panel_layout.h"

#include <algorithm>

namespace mb {

namespace {

constexpr float kColumnWidth = 360.0f;  // room for a label beside ImGui's 208-pixel fields
constexpr float kGap = 6.0f;            // between panels of a column

// Stacks the open panels first..last from y `top` to `bottom` in equal shares.
void stack(std::array<PanelRect, kPanelCount>& out, unsigned open, Panel first, Panel last, float x,
           float width, float top, float bottom) {
    int n = 0;
    for (int p = int(first); p <= int(last); ++p) n += (open & panelBit(Panel(p))) != 0;
    if (n == 0) return;
    const float share = std::max((bottom - top - kGap * float(n - 1)) / float(n), kPanelMinHeight);
    float y = top;
    for (int p = int(first); p <= int(last); ++p) {
        if (!(open & panelBit(Panel(p)))) continue;
        out[size_t(p)] = {x, y, width, share};
        y += share + kGap;
    }
}

bool overlap(const PanelRect& a, const PanelRect& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height &&
           b.y < a.y + a.height;
}

}  // namespace

bool statisticsFit(PanelFrame frame, unsigned open, const PanelRect& stats) {
    frame.rightTop = stats.y + stats.height;
    const std::array<PanelRect, kPanelCount> rects = layoutPanels(frame, open);
    for (int p = 0; p < kPanelCount; ++p) {
        const PanelRect& r = rects[size_t(p)];
        if (!(open & panelBit(Panel(p)))) continue;
        // A column too crowded for its panels' least height runs past the bottom (by more than
        // the shares' rounding).
        if (overlap(r, stats) || r.y + r.height > frame.height - kPanelMargin + 0.5f) return false;
    }
    return true;
}

std::array<PanelRect, kPanelCount> layoutPanels(const PanelFrame& frame, unsigned open) {
    std::array<PanelRect, kPanelCount> out{};
    // Two columns and three margins across; a narrow window narrows the columns.
    const float width =
        std::max(std::min(kColumnWidth, (frame.width - 3.0f * kPanelMargin) / 2.0f), 1.0f);
    const float bottom = frame.height - kPanelMargin;
    stack(out, open, Panel::Objects, Panel::Lights, kPanelMargin, width, frame.top + kPanelMargin,
          bottom);
    stack(out, open, Panel::View, Panel::Controls, frame.width - kPanelMargin - width, width,
          std::max(frame.top, frame.rightTop) + kPanelMargin, bottom);
    return out;
}

PanelRect uncoveredRoom(const PanelFrame& frame, unsigned open) {
    const std::array<PanelRect, kPanelCount> rects = layoutPanels(frame, open);
    float left = 0.0f, right = frame.width;
    for (int p = 0; p < kPanelCount; ++p) {
        if (!(open & panelBit(Panel(p)))) continue;
        const PanelRect& r = rects[size_t(p)];
        if (Panel(p) <= Panel::Lights) left = std::max(left, r.x + r.width + kPanelMargin);
        else right = std::min(right, r.x - kPanelMargin);
    }
    if (right - left < 0.25f * frame.width) left = 0.0f, right = frame.width;
    return {left, frame.top, right - left, std::max(frame.height - frame.top, 1.0f)};
}

}  // namespace mb
