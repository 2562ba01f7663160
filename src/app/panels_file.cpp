// panels_file.cpp — File > Open and Save As dialogs, the unsaved-changes prompt, load errors.
#include "ui.h"

#include "marchbox/editor/events.h"
#include "widgets.h"

#include "marchbox/editor/file_browser.h"
#include "marchbox/editor/files.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <imgui.h>
#include <imgui_stdlib.h>

namespace mb {

static const char* kOpenPopup = "Open scene";
static const char* kSaveAsPopup = "Save scene as";
static const char* kUnsavedPopup = "Unsaved changes";
static const char* kErrorsPopup = "Cannot open";
static const char* kDiskPopup = "Changed on disk";

// BeginPopupModal, its state told to the event log.
static bool beginModal(const char* name) {
    bool open = ImGui::BeginPopupModal(name, nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    markPopup(name, open);
    if (open) markPanel();
    return open;
}

void openFile(UiContext& c, const std::string& path) {
    c.ui.openErrors.clear();
    c.ui.errorsHeader = "The file did not load; the open scene is unchanged.";
    c.editor.request(Leave::Open, path, &c.ui.openErrors);
}

void saveFile(UiContext& c) {
    if (c.editor.document().path().empty()) {
        c.ui.wantSaveAs = true;
        return;
    }
    // A read-only file, say: Save As opens with the reason. A change on disk asks instead.
    if (!c.editor.save(c.ui.messages.at(Place::SaveAs)) && !c.editor.diskChanged())
        c.ui.wantSaveAs = true;
}

void watchSceneFile(UiContext& c) {
    std::vector<std::string> errors;
    c.editor.watchFile(&errors);
    if (errors.empty()) return;
    c.ui.openErrors = std::move(errors);
    c.ui.errorsHeader = c.editor.document().name() +
                        " changed on disk and does not load; the open scene is unchanged.";
}

// Esc over a dialog: the dialog's Cancel (handleShortcuts raised it).
static bool escaped(UiContext& c) {
    bool esc = c.ui.escape;
    c.ui.escape = false;
    return esc;
}

// Return over a dialog with no field: its OK. Only in the frame Return goes down, so the press
// that opened the dialog (Return in Open's path field), held on, does not also close it.
static bool returnPressed() {
    return ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false) ||
           ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_KeyPadEnter), false);
}

// A button with a widget mark.
static bool button(const char* popup, const char* label) {
    bool clicked = ImGui::Button(label);
    markItem(std::string(popup) + "/" + label);
    return clicked;
}

// The path field, focused when the dialog appears or `refocus` asks; Enter confirms. Wide
// enough to show the whole path, up to the window's width.
static bool pathField(const char* popup, std::string* path, bool refocus = false) {
    if (ImGui::IsWindowAppearing() || refocus) ImGui::SetKeyboardFocusHere();
    const float pad = 2.0f * ImGui::GetStyle().FramePadding.x + ImGui::GetFontSize();
    const float room = ImGui::GetIO().DisplaySize.x - 120.0f;  // the label and the window's edges
    ImGui::SetNextItemWidth(
        std::max(480.0f, std::min(ImGui::CalcTextSize(path->c_str()).x + pad, room)));
    const ImGuiInputTextFlags flags =
        ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll;
    bool enter = ImGui::InputText("path", path, flags);  // typing replaces the suggestion
    markItem(std::string(popup) + "/path");
    markTyping(std::string(popup) + "/path");
    return enter;
}

// Shows `folder` in the browser. Save As keeps the file name typed, to save it there; Open
// puts the folder in the field, to type a name into or pick one from.
static void browseTo(UiState& ui, const std::string& folder, bool keepName) {
    ui.browsed = readFolder(folder);
    std::string name = keepName ? std::filesystem::path(ui.pathField).filename().string() : "";
    ui.pathField = entryPath(ui.browsed.folder, name);
}

// Open on a path that names a folder goes into it, as file dialogs do, rather than failing.
// (Save As keeps refusing a folder with the save's own reason: the name to write is missing.)
static bool intoFolder(UiState& ui, bool go) {
    std::error_code ec;
    if (!go || !std::filesystem::is_directory(ui.pathField, ec)) return false;
    browseTo(ui, ui.pathField, false);
    return true;
}

// The places to jump to (placesToBrowse()); a path too long for the list shows its end.
static std::string placesList(UiState& ui) {
    std::string go;
    ImGui::BeginChild("places", ImVec2(160, 240), true);
    const float room = ImGui::GetContentRegionAvail().x;
    for (size_t i = 0; i < ui.places.size(); ++i) {
        const BrowsePlace& place = ui.places[i];
        std::string label = place.label;
        while (label.size() > 4 && ImGui::CalcTextSize(label.c_str()).x > room)
            label = "..." + label.substr(4);
        ImGui::PushID(int(i));
        if (ImGui::Selectable(label.c_str(), place.folder == ui.browsed.folder)) go = place.folder;
        ImGui::PopID();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", place.folder.c_str());
    }
    ImGui::EndChild();
    return go;
}

// The folder's listing above the path field: a click on a folder goes into it, on a file puts
// the file in the field. True on a double click on a file: the dialog's OK.
static bool folderBrowser(UiContext& c, const char* popup, bool keepName) {
    UiState& ui = c.ui;
    if (ImGui::IsWindowAppearing()) {
        ui.browsed = readFolder(folderOf(ui.pathField));
        const char* home = std::getenv("HOME");
        ui.places = placesToBrowse(ui.recent.paths(), ui.scenesDir, home ? home : "", ".");
    }
    std::string go;
    if (button(popup, "Up")) go = parentFolder(ui.browsed.folder);
    ImGui::SameLine();
    ImGui::TextUnformatted(ui.browsed.folder.c_str());
    std::string place = placesList(ui);
    ImGui::SameLine();
    bool chosen = false;
    ImGui::BeginChild("entries", ImVec2(420, 240), true);
    if (!ui.browsed.error.empty()) fieldErrorLine(ui.browsed.error);
    for (const FolderEntry& e : ui.browsed.entries) {
        const std::string path = entryPath(ui.browsed.folder, e.name);
        const std::string label = e.folder ? e.name + "/" : e.name;
        if (ImGui::Selectable(label.c_str(), path == ui.pathField,
                              ImGuiSelectableFlags_AllowDoubleClick)) {
            if (e.folder) go = path;
            else ui.pathField = path, chosen = ImGui::IsMouseDoubleClicked(0);
        }
        markItem(std::string(popup) + "/" + label);
    }
    ImGui::EndChild();
    if (!place.empty()) go = place;
    if (!go.empty()) browseTo(ui, go, keepName);
    return chosen;
}

static void openDialog(UiContext& c) {
    if (!beginModal(kOpenPopup)) return;
    bool go = folderBrowser(c, kOpenPopup, false);
    go |= pathField(kOpenPopup, &c.ui.pathField);
    go |= button(kOpenPopup, "Open");
    ImGui::SameLine();
    bool cancel = button(kOpenPopup, "Cancel") || escaped(c);
    go = go && !cancel && !intoFolder(c.ui, go);
    if (go || cancel) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    if (go) openFile(c, c.ui.pathField);  // may raise the unsaved prompt: after EndPopup
}

static void finishSaveAs(UiContext& c, bool saved) {
    bool leave = c.ui.saveThenLeave;
    c.ui.saveThenLeave = false;
    if (!leave) return;
    if (saved) c.editor.confirmLeave();
    else c.editor.cancelLeave();
}

// Saving over another existing file takes a second Save: the first one only warns.
static bool confirmedTarget(UiContext& c, bool go) {
    std::error_code ec;
    const std::string& path = c.ui.pathField;
    bool same = sameFile(path, c.editor.document().path());
    // Only a file is replaced; a folder or device is refused by the save, which says so.
    bool other = !same && std::filesystem::is_regular_file(path, ec);
    if (other && go && c.ui.replacePath != path) {
        c.ui.replacePath = path;
        emitEvent("confirm replace " + path);
        return false;
    }
    if (other && c.ui.replacePath == path)
        ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "%s exists: Save again to replace it.",
                           path.c_str());
    return go;
}

static void saveAsDialog(UiContext& c) {
    if (!beginModal(kSaveAsPopup)) return;
    bool go = folderBrowser(c, kSaveAsPopup, true);
    bool enter = pathField(kSaveAsPopup, &c.ui.pathField, c.ui.refocusPath);
    go |= enter;
    go |= button(kSaveAsPopup, "Save");
    ImGui::SameLine();
    bool cancel = button(kSaveAsPopup, "Cancel") || escaped(c);
    go = confirmedTarget(c, go) && !cancel;
    messageLine(c, Place::SaveAs);
    std::string* why = c.ui.messages.at(Place::SaveAs);
    bool saved = go && c.editor.saveAs(c.ui.pathField, why);
    if (saved) why->clear();
    // A failed save keeps the keys in the field, so the path can be fixed at once. Not after
    // the replace warning: a held Return would repeat into the Save that replaces the file.
    c.ui.refocusPath = enter && go && !saved;
    if (saved || cancel) {
        c.ui.replacePath.clear();
        ImGui::CloseCurrentPopup();
        finishSaveAs(c, saved);
    }
    ImGui::EndPopup();
}

// What leaving would lose. Edits of the run made at t > 0 are not in the start Save writes:
// Keep makes the scene shown the start (only a scene at t > 0 can be kept), then saves.
static void unsavedQuestion(const Document& d) {
    const std::string& path = d.path();
    const std::string file = path.empty() ? "the new scene" : path;
    if (!d.runEdits()) {
        ImGui::Text("Save the changes to %s first?", file.c_str());
        return;
    }
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "%s",
                       "The run holds edits made at t > 0, which Save does not write.");
    if (d.time() > 0)
        ImGui::Text("Keep the scene shown at %s as the start, and save it to %s?",
                    timeLabel(d.time()).c_str(), file.c_str());
    else
        ImGui::TextUnformatted(
            "To keep them: Cancel, scrub to them, Simulation > Keep simulated poses.");
    if (d.dirty()) ImGui::Text("Leaving them also leaves the changes to %s unsaved.", file.c_str());
}

static void unsavedPrompt(UiContext& c) {
    if (!beginModal(kUnsavedPopup)) return;
    const Document& d = c.editor.document();
    unsavedQuestion(d);
    const bool run = d.runEdits();
    bool save = false;
    if (!run || d.time() > 0) {
        save = button(kUnsavedPopup, run ? "Keep and save" : "Save");
        ImGui::SameLine();
    }
    bool discard = button(kUnsavedPopup, run ? "Leave them" : "Don't save");
    ImGui::SameLine();
    bool cancel = button(kUnsavedPopup, "Cancel") || escaped(c);
    if (save || discard || cancel) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    if (cancel) c.editor.cancelLeave();
    if (discard) c.editor.confirmLeave();
    if (save && run) c.editor.keepPoses();
    if (save && !d.path().empty() && c.editor.save(c.ui.messages.at(Place::SaveAs)))
        c.editor.confirmLeave();
    else if (save && c.editor.diskChanged())  // that question first; then leave again
        c.editor.cancelLeave();
    else if (save) {  // no file yet, or it could not be written: ask where
        c.ui.saveThenLeave = true;
        c.ui.wantSaveAs = true;
    }
}

static void errorsPopup(UiContext& c) {
    if (!beginModal(kErrorsPopup)) return;
    ImGui::TextUnformatted(c.ui.errorsHeader.c_str());
    // The errors scroll in a list of at most half the window, so OK stays on screen however
    // many there are (up to 100).
    const ImVec2 screen = ImGui::GetIO().DisplaySize;
    float width = 0.0f;
    for (const std::string& e : c.ui.openErrors)
        width = std::max(width, ImGui::CalcTextSize(e.c_str()).x);
    const float height = ImGui::GetTextLineHeightWithSpacing() * float(c.ui.openErrors.size());
    const float bar = ImGui::GetStyle().ScrollbarSize;
    ImGui::BeginChild("errors", ImVec2(std::min(width + bar, screen.x * 0.9f),
                                       std::min(height, screen.y * 0.5f)));
    for (const std::string& e : c.ui.openErrors) fieldErrorLine(e);
    ImGui::EndChild();
    if (button(kErrorsPopup, "OK") || returnPressed() || escaped(c)) {
        c.ui.openErrors.clear();
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

// The file changed on disk while this scene has edits it lacks: one of them goes.
static void diskPrompt(UiContext& c) {
    if (!beginModal(kDiskPopup)) return;
    const Document& d = c.editor.document();
    ImGui::PushTextWrapPos(std::min(480.0f, ImGui::GetIO().DisplaySize.x * 0.9f));
    ImGui::Text("%s changed on disk since it was opened or saved here.", d.name().c_str());
    ImGui::TextUnformatted(d.dirty() || d.runEdits()
                               ? "Load theirs to see it (Undo brings your edits back), or keep "
                                 "yours (Save then writes them over it)."
                               : "Load theirs to see it, or keep yours (Save then writes it).");
    ImGui::PopTextWrapPos();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", d.path().c_str());
    const bool load = button(kDiskPopup, "Load theirs");
    ImGui::SameLine();
    const bool keep = button(kDiskPopup, "Keep mine") || escaped(c);
    if (load || keep) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    if (keep && !c.editor.keepMine(c.ui.messages.at(Place::SaveAs))) c.ui.wantSaveAs = true;
    if (load && !c.editor.loadTheirs(&c.ui.openErrors))
        c.ui.errorsHeader = d.name() + " does not load; the open scene is unchanged.";
}

// Popups open here, at the top of ImGui's id stack, whichever menu or key asked for them.
void drawDialogs(UiContext& c) {
    UiState& ui = c.ui;
    if (ui.wantOpen || ui.wantSaveAs) {
        ImGui::OpenPopup(ui.wantOpen ? kOpenPopup : kSaveAsPopup);
        ui.pathField = ui.wantOpen
                           ? c.editor.document().path()
                           : proposeSavePath(c.editor.document().path(), c.editor.lastFile());
    }
    if (c.editor.pendingLeave() != Leave::None && !ui.saveThenLeave)
        ImGui::OpenPopup(kUnsavedPopup);
    if (!ui.openErrors.empty()) ImGui::OpenPopup(kErrorsPopup);
    if (c.editor.diskChanged()) ImGui::OpenPopup(kDiskPopup);
    ui.wantOpen = ui.wantSaveAs = false;
    openDialog(c);
    saveAsDialog(c);
    unsavedPrompt(c);
    diskPrompt(c);
    errorsPopup(c);
    ui.escape = false;  // no dialog took it
}

}  // namespace mb
