// panels_menu.cpp — the main menu bar, and the keys that do what its items do.
#include "ui.h"
#include "widgets.h"

#include "marchbox/editor/events.h"
#include "marchbox/scene/shapes.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <algorithm>
#include <filesystem>
#include <imgui.h>
#include <imgui_internal.h>  // the popup stack: Esc closes the topmost popup
#include <utility>
#include <vector>

namespace mb {

// BeginMenu with a widget mark, so tests find the menu where a person would. Only while
// closed: once open, the last item is inside the menu's window.
static bool beginMenu(const char* name) {
    bool open = ImGui::BeginMenu(name);
    if (!open) markItem(name);
    markPopup(std::string("menu ") + name, open);
    return open;
}

static bool menuItem(const char* menu, const char* label, const char* shortcut = nullptr,
                     bool selected = false, bool enabled = true) {
    bool clicked = ImGui::MenuItem(label, shortcut, selected, enabled);
    markItem(std::string(menu) + "/" + label);
    return clicked;
}

static void request(UiContext& c, Leave what) {
    std::vector<std::string> errors;
    c.editor.request(what, "", &errors);
}

// Each file by name, its folder in the shortcut column; marked by its whole path.
static void recentMenu(UiContext& c) {
    const std::vector<std::string> paths = c.ui.recent.paths();  // a pick changes the list
    for (size_t i = 0; i < paths.size(); ++i) {
        std::filesystem::path p(paths[i]);
        ImGui::PushID(int(i));
        bool clicked =
            ImGui::MenuItem(p.filename().string().c_str(), p.parent_path().string().c_str());
        markItem("Open Recent/" + paths[i]);
        ImGui::PopID();
        if (clicked) openFile(c, paths[i]);
    }
    ImGui::Separator();
    if (menuItem("Open Recent", "Clear list")) {
        std::string why = c.ui.recent.clear();
        if (!why.empty()) c.ui.messages.say(Place::Status, why);
    }
}

// Why Delete refused: in the selection's panel when it is open, else on the status line.
static std::string* deleteMessage(UiContext& c) {
    const Place panel = itemPlace(c.editor.selection().kind);
    return c.ui.messages.at(c.ui.messages.onScreen(panel) ? panel : Place::Status);
}

static void fileMenu(UiContext& c) {
    if (menuItem("File", "New", "Ctrl+N")) request(c, Leave::NewScene);
    if (menuItem("File", "Open...", "Ctrl+O")) c.ui.wantOpen = true;
    const bool any = !c.ui.recent.paths().empty();
    if (ImGui::BeginMenu("Open Recent", any)) {
        recentMenu(c);
        ImGui::EndMenu();
    } else {
        markItem("File/Open Recent");
    }
    if (menuItem("File", "Save", "Ctrl+S")) saveFile(c);
    if (menuItem("File", "Save As...")) c.ui.wantSaveAs = true;
    // The two render windows share one place, so one is open at a time.
    if (menuItem("File", "Render...", nullptr, c.ui.showRender))
        c.ui.showRender = !c.ui.showRender, c.ui.showAnimation = c.ui.showExport = false;
    if (menuItem("File", "Render Animation...", nullptr, c.ui.showAnimation))
        c.ui.showAnimation = !c.ui.showAnimation, c.ui.showRender = c.ui.showExport = false;
    if (menuItem("File", "Export Mesh...", nullptr, c.ui.showExport))
        c.ui.showExport = !c.ui.showExport, c.ui.showRender = c.ui.showAnimation = false;
    ImGui::Separator();
    if (menuItem("File", "Exit", "Ctrl+Q")) request(c, Leave::Exit);
}

// Why Group or Ungroup refused: in Objects when it is open, else on the status line.
static std::string* objectsMessage(UiContext& c) {
    return c.ui.messages.at(c.ui.messages.onScreen(Place::Objects) ? Place::Objects
                                                                   : Place::Status);
}

// Select all, Group, Ungroup and Select parent group: the selection's items and their groups.
static void groupItems(UiContext& c) {
    Editor& e = c.editor;
    const std::vector<Item> items = treeItems(e.selection());
    const bool group =
        std::any_of(items.begin(), items.end(), [](Item it) { return it.kind == ItemKind::Group; });
    if (menuItem("Edit", "Select all", "Ctrl+A")) e.selectAll();
    if (menuItem("Edit", "Select parent group", "[", false, !items.empty())) e.selectParent();
    if (menuItem("Edit", "Group", "Ctrl+G", false, !items.empty()))
        e.groupSelected(objectsMessage(c));
    if (menuItem("Edit", "Ungroup", "Ctrl+Alt+G", false, group))
        e.ungroupSelected(objectsMessage(c));
}

// Shift+D, as in Blender: copies of the selection, named on from the originals ("box.001"),
// that follow the mouse until a click places them (see ViewportInput).
static void duplicateToPlace(UiContext& c) {
    if (c.editor.duplicateSelected(deleteMessage(c))) c.ui.placeCopies = true;
}

// Ctrl+C and Ctrl+V go through the system clipboard as scene text, so they also work between
// two windows and with a text editor.
static void copySelection(UiContext& c) {
    const std::string text = c.editor.copySelection();
    if (!text.empty()) ImGui::SetClipboardText(text.c_str());
}

static void pasteClipboard(UiContext& c) {
    const char* text = ImGui::GetClipboardText();
    c.editor.paste(text ? text : "", objectsMessage(c));
}

static void editMenu(UiContext& c) {
    Editor& e = c.editor;
    const History& h = e.document().history();
    if (menuItem("Edit", ("Undo " + h.undoLabel()).c_str(), "Ctrl+Z", false, h.canUndo())) e.undo();
    if (menuItem("Edit", ("Redo " + h.redoLabel()).c_str(), "Ctrl+Y", false, h.canRedo())) e.redo();
    ImGui::Separator();
    if (menuItem("Edit", "Objects", nullptr, c.ui.showObjects))
        c.ui.showObjects = !c.ui.showObjects;
    if (menuItem("Edit", "Materials", nullptr, c.ui.showMaterials))
        c.ui.showMaterials = !c.ui.showMaterials;
    if (menuItem("Edit", "Lights", nullptr, c.ui.showLights)) c.ui.showLights = !c.ui.showLights;
    ImGui::Separator();
    if (ImGui::BeginMenu("Add")) {  // on the ground below the camera's target, clear of others
        std::string* why = c.ui.messages.at(Place::Status);
        for (const ShapeRow& row : kShapes)
            if (menuItem("Add", row.label))
                e.add(ItemKind::Object, why, row.type, viewWindow(c.ui));
        if (menuItem("Add", "Light")) e.add(ItemKind::Light, why);
        ImGui::EndMenu();
    } else {
        markItem("Edit/Add");
    }
    if (menuItem("Edit", "Duplicate", "Shift+D", false, !e.selection().empty()))
        duplicateToPlace(c);
    if (menuItem("Edit", "Copy", "Ctrl+C", false, !treeItems(e.selection()).empty()))
        copySelection(c);
    if (menuItem("Edit", "Paste", "Ctrl+V")) pasteClipboard(c);
    if (menuItem("Edit", "Delete selected", "Del", false, !e.selection().empty()))
        e.removeSelected(deleteMessage(c));
    ImGui::Separator();
    groupItems(c);
    ImGui::Separator();
    if (menuItem("Edit", "Random velocities", "J")) e.kick();
}

static void simulationMenu(UiContext& c) {
    Editor& e = c.editor;
    if (menuItem("Simulation", e.simulation().playing() ? "Pause" : "Play", "Space"))
        e.togglePlay();
    if (menuItem("Simulation", "Step")) e.step();
    const bool moved = e.document().time() > 0;
    if (menuItem("Simulation", "Reset", nullptr, false, moved)) e.resetSimulation();
    if (menuItem("Simulation", "Keep simulated poses", nullptr, false, moved)) e.keepPoses();
    if (menuItem("Simulation", "Loop", nullptr, e.simulation().loop()))
        e.setLoop(!e.simulation().loop());
    ImGui::Separator();
    if (menuItem("Simulation", "Timeline", nullptr, c.ui.showTimeline))
        c.ui.showTimeline = !c.ui.showTimeline;
    if (menuItem("Simulation", "Settings", nullptr, c.ui.showSimulation))
        c.ui.showSimulation = !c.ui.showSimulation;
}

static void togglePost(RenderOptions& o, PostMode mode) {
    o.post = o.post == PostMode::None ? mode : PostMode::None;
}

static const char* kNoFog = "this scene has no fog to show: set View > fog above 0 first";

// F and View > Fog show or hide the scene's fog. A scene without fog has none to show: rather
// than tick a box that changes nothing, the key says so and the menu item is disabled.
static void toggleFog(UiContext& c) {
    if (c.editor.scene().render.fog > 0.0f) {
        c.ui.render.fog = !c.ui.render.fog;
        return;
    }
    c.ui.messages.say(Place::Status, kNoFog);
    emitEvent(std::string("refuse ") + kNoFog);
}

// Frame all (Home) and Frame selected (numpad .), into the part of the view no panel covers.
// With nothing to frame the status line says so rather than nothing happening.
static void frameView(UiContext& c, bool all) {
    const ViewWindow view = viewWindow(c.ui);
    if (all ? c.editor.frameAll(view) : c.editor.frameSelected(view)) {
        emitEvent(all ? "frame all" : "frame selected");
        return;
    }
    const char* why = all ? "nothing to frame: the scene has no objects"
                          : "nothing to frame: select an object or a point light first";
    c.ui.messages.say(Place::Status, why);
    emitEvent(std::string("refuse ") + why);
}

static void viewMenu(UiContext& c) {
    UiState& ui = c.ui;
    if (menuItem("View", "Camera and render", nullptr, ui.showView)) ui.showView = !ui.showView;
    if (ImGui::BeginMenu("Debug view")) {
        for (int m = 0; m < kRenderModeCount; ++m)
            if (menuItem("View", renderModeName(RenderMode(m)), nullptr, int(ui.render.mode) == m))
                ui.render.mode = RenderMode(m);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Quality")) {  // what the view refines to; previews are drafts
        for (int p = 0; p < kQualityPresetCount; ++p)
            if (menuItem("View", qualityPresetName(QualityPreset(p)), nullptr,
                         int(ui.quality) == p))
                ui.quality = QualityPreset(p);
        ImGui::EndMenu();
    } else {
        markItem("View/Quality");
    }
    const bool fog = c.editor.scene().render.fog > 0.0f;
    if (menuItem("View", "Fog", "F", fog && ui.render.fog, fog)) toggleFog(c);
    if (!fog) itemTooltip("View/Fog", kNoFog);
    if (menuItem("View", "FXAA", "P", ui.render.post != PostMode::None))
        togglePost(ui.render, PostMode::Fxaa);
    if (menuItem("View", "Frame selected", "Numpad .")) frameView(c, false);
    if (menuItem("View", "Frame all", "Home")) frameView(c, true);
    if (menuItem("View", "Orbit preview", "1", ui.previewOrbit)) ui.previewOrbit = !ui.previewOrbit;
    if (menuItem("View", "Statistics", nullptr, ui.showStats)) ui.showStats = !ui.showStats;
    ImGui::Separator();
    static const char* const handles[kGizmoModeCount][2] = {
        {"Move handles", "G"}, {"Rotate handles", "R"}, {"Scale handles", "T"}};
    for (int m = 0; m < kGizmoModeCount; ++m)
        if (menuItem("View", handles[m][0], handles[m][1], int(ui.gizmo) == m))
            setGizmoMode(ui, GizmoMode(m));
    ImGui::Separator();
    if (menuItem("View", "Add camera key")) c.editor.addCameraKey();
    if (menuItem("View", "Delete nearest camera key", nullptr, false,
                 !c.editor.scene().keyframes.empty()))
        c.editor.deleteCameraKey();
    ImGui::Separator();
    if (menuItem("View", "Screenshot", "F12")) ui.wantScreenshot = true;
}

// Help > About: the version (MARCHBOX_VERSION, the one `marchbox --version` prints) and what
// the editor is built on.
static void aboutWindow(UiState& ui) {
    if (!ui.showAbout) return;
    // Centred, as dialogs are, rather than wherever ImGui's default puts it (over Objects).
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing,
                            ImVec2(0.5f, 0.5f));
    if (ImGui::Begin("About Marchbox", &ui.showAbout, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::Text("Marchbox %s", MARCHBOX_VERSION);
        markItem("About/version " MARCHBOX_VERSION);
        ImGui::TextUnformatted(
            "A desktop editor for scenes made of signed distance functions:\n"
            "raymarched on the GPU, simulated on the CPU.");
        ImGui::Separator();
        ImGui::Text("Scene files: version 1 (SCENE_FORMAT.md)   Dear ImGui %s", IMGUI_VERSION);
        ImGui::TextDisabled("build/marchbox --help lists the command line.");
    }
    ImGui::End();
}

// The file the editor last opened or saved goes first in the recent files: the one it started
// on, an Open, a Save As. Watching lastFile() catches every way in, dialogs and prompts alike.
static void noteRecentFile(UiContext& c) {
    const std::string& last = c.editor.lastFile();
    if (last.empty() || last == c.ui.recentNoted) return;
    c.ui.recentNoted = last;
    std::string why = c.ui.recent.add(last);
    if (!why.empty()) emitEvent("recent-failed " + why);
}

// The file's name at the bar's right end and, while saving would change the file, "unsaved
// changes" beside it: the title's `*` is out of sight in a full-screen window. Edits of the
// run that the start lacks are said too: Save does not write them. At t > 0 the time leads
// the name: what shows is not what Save writes.
static void fileStatus(const Document& d) {
    const std::string name = (d.time() > 0 ? timeLabel(d.time()) + "   " : "") + d.name();
    std::vector<std::pair<const char*, const char*>> notes;  // text, widget mark
    if (d.dirty()) notes.push_back({"unsaved changes", "menu/unsaved"});
    if (d.runEdits()) notes.push_back({"edits at t > 0 not in the start", "menu/run-edits"});
    const ImGuiStyle& style = ImGui::GetStyle();
    float width = ImGui::CalcTextSize(name.c_str()).x + style.FramePadding.x;
    for (const auto& n : notes) width += ImGui::CalcTextSize(n.first).x + style.ItemSpacing.x;
    ImGui::SameLine(
        std::max(ImGui::GetCursorPosX(), ImGui::GetWindowWidth() - width - style.WindowPadding.x));
    for (const auto& n : notes) {
        ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "%s", n.first);
        markItem(n.second);
        ImGui::SameLine();
    }
    ImGui::TextDisabled("%s", name.c_str());
}

void drawMenuBar(UiContext& c) {
    noteRecentFile(c);
    if (!ImGui::BeginMainMenuBar()) return;
    if (beginMenu("File")) {
        fileMenu(c);
        ImGui::EndMenu();
    }
    if (beginMenu("Edit")) {
        editMenu(c);
        ImGui::EndMenu();
    }
    if (beginMenu("Simulation")) {
        simulationMenu(c);
        ImGui::EndMenu();
    }
    if (beginMenu("View")) {
        viewMenu(c);
        ImGui::EndMenu();
    }
    if (beginMenu("Help")) {
        if (menuItem("Help", "Controls", nullptr, c.ui.showHelp)) c.ui.showHelp = !c.ui.showHelp;
        if (menuItem("Help", "About Marchbox", nullptr, c.ui.showAbout))
            c.ui.showAbout = !c.ui.showAbout;
        ImGui::EndMenu();
    }
    fileStatus(c.editor.document());
    ImGui::EndMainMenuBar();
    aboutWindow(c.ui);
}

static void ctrlShortcut(UiContext& c, const KeyPress& k) {
    const bool shift = k.mods & GLFW_MOD_SHIFT;
    switch (k.key) {
        case GLFW_KEY_A:
            c.editor.selectAll();
            break;
        case GLFW_KEY_C:
            copySelection(c);
            break;
        case GLFW_KEY_V:
            pasteClipboard(c);
            break;
        case GLFW_KEY_G:  // Blender's: Ctrl+G a new collection, Ctrl+Alt+G out of it
            if (k.mods & GLFW_MOD_ALT) c.editor.ungroupSelected(objectsMessage(c));
            else c.editor.groupSelected(objectsMessage(c));
            break;
        case GLFW_KEY_N:
            request(c, Leave::NewScene);
            break;
        case GLFW_KEY_O:
            c.ui.wantOpen = true;
            break;
        case GLFW_KEY_S:
            shift ? void(c.ui.wantSaveAs = true) : saveFile(c);
            break;
        case GLFW_KEY_Z:
            shift ? void(c.editor.redo()) : void(c.editor.undo());
            break;
        case GLFW_KEY_Y:
            c.editor.redo();
            break;
        case GLFW_KEY_Q:
            request(c, Leave::Exit);
            break;
        default:
            break;
    }
}

static void plainShortcut(UiContext& c, const KeyPress& k) {
    Editor& e = c.editor;
    switch (k.key) {
        case GLFW_KEY_SPACE:
            e.togglePlay();
            break;
        case GLFW_KEY_DELETE:
            e.removeSelected(deleteMessage(c));
            break;
        case GLFW_KEY_J:
            e.kick();
            break;
        case GLFW_KEY_D:
            if (k.mods & GLFW_MOD_SHIFT) duplicateToPlace(c);
            break;
        case GLFW_KEY_HOME:  // as in Blender, for the area under the mouse
            c.ui.overTimeline ? void(e.seek(0)) : frameView(c, true);
            break;
        case GLFW_KEY_KP_DECIMAL:
            frameView(c, false);
            break;
        case GLFW_KEY_LEFT_BRACKET:  // Blender's Select Hierarchy: parent
            e.selectParent();
            break;
        case GLFW_KEY_LEFT:  // as Blender's Shift+Left: to the start
            if (k.mods & GLFW_MOD_SHIFT) e.seek(0);
            break;
        case GLFW_KEY_1:
            c.ui.previewOrbit = !c.ui.previewOrbit;
            break;
        case GLFW_KEY_F:
            toggleFog(c);
            break;
        case GLFW_KEY_P:
            togglePost(c.ui.render, PostMode::Fxaa);
            break;
        case GLFW_KEY_G:  // Blender's grab; W, E and S fly
            setGizmoMode(c.ui, GizmoMode::Move);
            break;
        case GLFW_KEY_R:
            setGizmoMode(c.ui, GizmoMode::Rotate);
            break;
        case GLFW_KEY_T:
            setGizmoMode(c.ui, GizmoMode::Scale);
            break;
        default:
            break;
    }
}

// Esc closes what is open, and never quits (a slip of the finger would lose the window): a
// dialog as its Cancel would (drawDialogs reads ui.escape), a menu or the object popup as a
// click elsewhere would, else the Render or About window. While a field in a menu or popup is
// typed into, Esc is the field's: ImGui puts its old text back.
static void escape(UiContext& c) {
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    const ImGuiWindow* top = g.OpenPopupStack.empty() ? nullptr : g.OpenPopupStack.back().Window;
    if (top && (top->Flags & ImGuiWindowFlags_Modal)) {
        c.ui.escape = true;
    } else if (ImGui::GetIO().WantTextInput) {
        return;
    } else if (!g.OpenPopupStack.empty()) {
        ImGui::ClosePopupToLevel(g.OpenPopupStack.Size - 1, true);
        emitEvent("escape closes a popup");
    } else if (bool* open = c.ui.showRender      ? &c.ui.showRender
                            : c.ui.showAnimation ? &c.ui.showAnimation
                            : c.ui.showExport    ? &c.ui.showExport
                            : c.ui.showAbout     ? &c.ui.showAbout
                                                 : nullptr) {
        *open = false;
        emitEvent("escape closes a window");
    }
}

// Keys reach the editor only when ImGui is not typing into a field or showing a prompt.
void handleShortcuts(UiContext& c, const std::vector<KeyPress>& keys) {
    const bool imguiHasKeys = ImGui::GetIO().WantCaptureKeyboard;
    for (const KeyPress& k : keys) {
        if (k.key == GLFW_KEY_F12) c.ui.wantScreenshot = true;  // even over a dialog
        else if (k.key == GLFW_KEY_ESCAPE) escape(c);
        else if (imguiHasKeys) continue;
        else if (k.mods & GLFW_MOD_CONTROL) ctrlShortcut(c, k);
        else plainShortcut(c, k);
    }
}

}  // namespace mb
