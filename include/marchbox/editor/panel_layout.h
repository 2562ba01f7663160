// marchbox/editor/panel_layout.h — where the editor's panels go: two columns docked to the
// window's sides, the lists (Objects, Materials, Lights) on the left and the settings (View,
// Simulation, Render, Controls) on the right, below the statistics overlay. The open panels of
// a column share its height equally, top to bottom in this order, so none covers another and
// none runs off the window; a panel is as tall as its fields up to its share and scrolls past it.
#pragma once

#include <array>

namespace mb {

enum class Panel : int { Objects, Materials, Lights, View, Simulation, Render, Controls };
constexpr int kPanelCount = 7;

constexpr unsigned panelBit(Panel p) { return 1u << int(p); }

struct PanelRect {
    float x = 0, y = 0, width = 0, height = 0;  // height: the most the panel may take

    bool operator==(const PanelRect&) const = default;
};

// The room the panels have, in window pixels from the top-left corner.
struct PanelFrame {
    float width = 0, height = 0;  // the window
    float top = 0;                // below the menu bar
    float rightTop = 0;           // below the statistics overlay, which sits top right
};

constexpr float kPanelMargin = 10.0f;     // from the window's edges
constexpr float kPanelMinHeight = 40.0f;  // a title bar and a line: kept even in a tiny window

// The place of each panel whose panelBit is set in `open`; the others' are left empty.
std::array<PanelRect, kPanelCount> layoutPanels(const PanelFrame& frame, unsigned open);

// The room no open panel covers, in window pixels: between the columns as layoutPanels() puts
// them, below the menu bar and above frame.height (the timeline). Where the columns leave less
// than a quarter of the window's width between them, the whole width: a sliver frames nothing.
PanelRect uncoveredRoom(const PanelFrame& frame, unsigned open);

// Whether the statistics overlay at `stats` leaves the open panels room, with frame.rightTop at
// its bottom: it covers none of them and each column's panels fit above the window's bottom
// margin. In a small window it does not, and the overlay gives way (View > Statistics).
bool statisticsFit(PanelFrame frame, unsigned open, const PanelRect& stats);

}  // namespace mb
