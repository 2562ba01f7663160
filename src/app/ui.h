// ui.h — the ImGui side of the editor: which windows are open, the dialogs' fields, and one
// draw function per group of panels (panels_*.cpp).
#pragma once

#include "marchbox/editor/editor.h"
#include "marchbox/editor/gizmo.h"
#include "marchbox/editor/input_queue.h"
#include "marchbox/editor/messages.h"
#include "marchbox/editor/panel_layout.h"
#include "marchbox/editor/file_browser.h"
#include "marchbox/editor/recent.h"
#include "marchbox/gl/quality_preset.h"
#include "marchbox/gl/renderer.h"
#include "scene_image.h"
#include "scene_view.h"

#include <array>
#include <string>
#include <vector>

namespace mb {

// Frame timing for the statistics overlay: the window's frames (the UI answers at this rate)
// and the scene's picture (drawn a step a frame, see scene_image.h), kept apart.
struct FrameStats {
    static constexpr int kHistory = 120;
    float frameMs[kHistory] = {};     // a ring, newest at `next - 1`
    int next = 0, count = 0;          // count: frames recorded, up to kHistory
    float fps = 0.0f, meanMs = 0.0f;  // over the last kHistory / 2 frames: fps = 1000 / meanMs
    PictureStatus scene;
    void add(double seconds);
};

// The editor's view holds the selection ring, compiled in once, so selecting never recompiles.
inline RenderOptions viewOptions() {
    RenderOptions o;
    o.outline = true;
    return o;
}

struct UiState {
    // Windows, toggled from the menus.
    bool showObjects = true, showMaterials = false, showLights = false;
    bool showSimulation = false, showView = false, showHelp = false, showStats = true;
    bool showTimeline = true;
    bool showRender = false, showAnimation = false, showExport = false;  // one Render slot
    bool showAbout = false;

    // Requests raised by menus and shortcuts, carried out by drawDialogs() this frame.
    bool wantOpen = false, wantSaveAs = false, wantObjectPopup = false, wantScreenshot = false;
    bool placeCopies = false;  // Duplicate made copies: they follow the mouse until a click
    int material = -1;         // the Materials panel's own choice (shownMaterial())
    std::string pathField;                // the Open and Save As dialogs' path
    FolderView browsed;                   // the folder those dialogs show
    std::vector<BrowsePlace> places;      // the folders beside it: named ones, recent ones
    std::vector<std::string> openErrors;  // FILE:LINE lines of the last failed open or reload
    std::string errorsHeader;             // what failed to load, above them
    bool saveThenLeave = false;           // Save As was asked for by the unsaved-changes prompt
    std::string replacePath;              // Save As warned once that this file exists
    bool refocusPath = false;             // Save As failed on Enter: the field keeps the keys
    bool escape = false;                  // Esc this frame: the open dialog cancels
    int heldKey = -1;  // the camera key a press on the timeline landed on, dragged while held
    bool overTimeline = false;  // the mouse was over the timeline: Home rewinds

    Messages messages;                     // refusals and failures, each in its place, in red
    RenderOptions render = viewOptions();  // debug view and uber shader
    QualityPreset quality = QualityPreset::Normal;  // View > Quality, over the scene's; not saved
    bool previewOrbit = false;                      // key 1
    GizmoMode gizmo = GizmoMode::Move;              // the selection's handles: G, R, T
    std::string scenesDir;                          // scenes/ of the source tree, for File > Open
    RecentFiles recent{recentFilesPath()};          // File > Open Recent
    std::string recentNoted;  // the editor's last file, as last put in `recent`

    // Docked panels (panel_layout.h): where each was last put, and the statistics' bottom edge
    // as last drawn (0 while hidden).
    std::array<PanelRect, kPanelCount> placed{};
    // carvedAway() of the scene at document version carvedAt, for the Objects list's marks.
    std::vector<int> carved;
    uint64_t carvedAt = ~uint64_t(0);
    float statsBottom = 0.0f;
    unsigned openPanels() const;  // panelBit of each panel shown
};

// What the panels need from the rest of the window.
struct UiContext {
    Editor& editor;
    UiState& ui;
    const FrameStats& stats;
    const SceneView& view;
};

// [widgets.cpp] Begin for a docked panel: put where layoutPanels() says whenever that place
// changes (a panel opened or closed, the window resized), else left where it was dragged; as
// tall as its fields up to its place's height and the window's bottom, scrolling past that.
bool beginPanel(UiContext& c, Panel p, const char* title, bool* open);

// [widgets.cpp] The place's message in red, if it has one; the place is on screen this frame.
void messageLine(UiContext& c, Place p);

// [panels_menu.cpp] the main menu bar, Help > About's window, and the shortcuts that mirror the
// menus' items; each frame it puts the file last opened or saved first in the recent files.
void drawMenuBar(UiContext& c);
void handleShortcuts(UiContext& c, const std::vector<KeyPress>& keys);

// [panels_file.cpp] Open, Save As, the unsaved-changes prompt and load errors.
void drawDialogs(UiContext& c);
void openFile(UiContext& c, const std::string& path);  // through the unsaved-changes prompt
void saveFile(UiContext& c);                           // Save As when the scene has no file
// Each frame: the open scene's file, changed on disk, reloads or asks (Editor::watchFile).
void watchSceneFile(UiContext& c);

// [panels_edit.cpp] objects, materials, lights, and the right-click popup.
void drawEditWindows(UiContext& c);

// [panels_sim.cpp] Step, Reset, Keep poses, the world's settings and the step's statistics.
void drawSimulationWindow(UiContext& c);

// [gizmo_view.cpp] over the scene, under the panels: the selection's handles, `hot` lit (held
// or under the mouse), and a marker at each point light. viewSize in framebuffer pixels.
void drawGizmo(const UiContext& c, GizmoHandle hot, glm::vec2 viewSize);
void setGizmoMode(UiState& ui, GizmoMode m);  // G, R, T and the View menu

// [timeline_strip.cpp] The timeline across the window's bottom, under the view: Play, the time,
// the strip of simulated time (the baked frames, the time shown and the camera keys as markers;
// a click or drag scrubs, a click on a key's marker goes to the key), the bake's size and Loop.
// Its height (0 while Simulation > Timeline is off, or in a small window) is kept clear of the
// docked panels.
void drawTimelineBar(UiContext& c);
float timelineBarHeight(const UiState& ui);

// [widgets.cpp] The room the docked panels and the statistics overlay have this frame.
PanelFrame panelFrame(const UiState& ui);
// The part of the view no panel covers (uncoveredRoom()), for framing and for Add.
ViewWindow viewWindow(const UiState& ui);

// [panels_view.cpp] camera, render settings, debug views, help, statistics, shader log.
void drawViewWindows(UiContext& c);
void postModeCombo(UiState& ui);  // FXAA and its debug views

}  // namespace mb
