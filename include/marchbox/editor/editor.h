// marchbox/editor/editor.h — the editor without its window: the document, the selection and the
// simulation, and the rules that tie them together.
//
// [SECTION] File: new, open, save; leaving unsaved work always asks first
// [SECTION] Edits: every change to the scene, undo and redo
// [SECTION] Selection and the viewport's object commands
// [SECTION] Simulation
//
// The window's panels and input call these; nothing here knows about GL, GLFW or ImGui.
#pragma once

#include "marchbox/editor/camera_control.h"
#include "marchbox/editor/disk_file.h"
#include "marchbox/editor/document.h"
#include "marchbox/editor/gizmo.h"
#include "marchbox/editor/scene_edit.h"
#include "marchbox/editor/scene_tree.h"
#include "marchbox/editor/selection.h"
#include "marchbox/editor/simulation.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace mb {

enum class Leave : int { None, NewScene, Open, Exit };

// Where Duplicate puts a copy, in the world, from its original: beside it, 1 m along x.
inline const glm::vec3 kCopyAside(1.0f, 0.0f, 0.0f);

class Editor {
public:
    //-------------------------------------------------------------------------
    // [SECTION] File
    //-------------------------------------------------------------------------
    // New, Open and Exit leave the current scene. With unsaved changes, or edits of the run
    // that the start lacks (Document::runEdits), they wait (pendingLeave) until confirmLeave()
    // (after the user saved, kept or chose to discard) or cancelLeave().
    // An Open reads its file first: one that does not load asks nothing. Returns false only
    // when that read failed; *errors then has FILE:LINE lines and the open scene is untouched.
    bool request(Leave what, const std::string& path, std::vector<std::string>* errors);
    Leave pendingLeave() const { return pending_; }
    void confirmLeave();  // carries out the pending leave; an Open's file was read already
    void cancelLeave();
    bool quitRequested() const { return quit_; }

    // The scene the editor starts on (startingScene()); `file` is where Save writes, "" for an
    // untitled scene, which Save asks a name for.
    void start(const Scene& scene, const std::string& file);

    // Both write the start (t = 0), never the poses the simulation got to: see keepPoses().
    bool save(std::string* error);  // to document().path(); fails when the scene has none
    bool saveAs(const std::string& path, std::string* error);  // "" is refused: asks for a name
    // The file last opened or saved, kept through New: where Save As starts a new scene.
    const std::string& lastFile() const { return lastFile_; }

    // The file on disk. watchFile(), each frame: a change made elsewhere reloads the scene, as
    // one undo step, when nothing here is unsaved; otherwise diskChanged() waits for keepMine()
    // or loadTheirs(). A change whose file does not load leaves the scene alone, *errors saying
    // why. Save never writes over a change it was not told of: it refuses, and asks the same.
    void watchFile(std::vector<std::string>* errors);
    bool diskChanged() const { return diskChanged_; }
    // Ours stays, and the next Save writes over theirs; straight away if a Save was refused.
    bool keepMine(std::string* error);
    bool loadTheirs(std::vector<std::string>* errors);  // false, the scene kept, if it fails

    //-------------------------------------------------------------------------
    // [SECTION] Edits
    //-------------------------------------------------------------------------
    // A running simulation's progress is recorded first, so the edit is its own undo step.
    void edit(const std::string& label, const SceneChange& change, uint64_t mergeKey = 0);
    void endEdit();  // a widget or drag was released: the next change is a new step
    bool undo();
    bool redo();

    // Selects the new item; an object of type `shape`, put where placeNewObject() says for the
    // part of the view no panel covers.
    bool add(ItemKind k, std::string* why, ShapeType shape = ShapeType::Sphere,
             const ViewWindow& view = {});
    bool duplicate(ItemKind k, int index, std::string* why);  // selects the copy
    bool remove(ItemKind k, int index, std::string* why);
    bool reorder(int object, int by, std::string* why);  // reorderObject(); the selection follows
    bool reorder(Item it, int by, std::string* why);     // shiftItem(): among its siblings
    // The Objects panel's drag: `it` to `spot` (scene_tree.h), where it stands in the world.
    bool moveTo(Item it, TreeSpot spot, std::string* why);
    void clear(ItemKind k);
    int kick();  // J: random velocities for the dynamic bodies; returns how many

    // Ctrl+G: a group of the selected objects and groups (groupItems()), selected; one step.
    bool groupSelected(std::string* why);
    // Ungroup: dissolves each selected group, its children selected in its place; one step.
    bool ungroupSelected(std::string* why);
    // A field of the active object or group edited while more are selected: the active one
    // becomes `after`; each other selected item of its kind takes the fields that changed from
    // `before` to `after` (applyObjectEdit()), one undo step per mergeKey.
    void editObjects(const Object& before, const Object& after, uint64_t mergeKey);
    void editGroups(const Group& before, const Group& after, uint64_t mergeKey);

    //-------------------------------------------------------------------------
    // [SECTION] Selection
    //-------------------------------------------------------------------------
    // Each change of the selection is told to the event log as "select " + describe().
    const Selection& selection() const { return sel_; }
    void select(ItemKind k, int index);                             // that item alone (-1: nothing)
    void toggle(Item it);                                           // Shift+click: toggleSelected()
    void selectItems(const std::vector<Item>& items, bool extend);  // a box
    void selectAll();     // Ctrl+A: every top-level object and group
    bool selectParent();  // [: the group that holds the active item; false at the top level
    // A click in the view: Replace selects the object there, or nothing; Climb does too, but
    // a click on the active object, or inside the active group, goes up to its group
    // (clickTarget()); Toggle (Shift) adds or removes it. Returns the object hit, or -1.
    enum class Pick { Replace, Climb, Toggle };
    int pick(glm::vec2 pixel, glm::vec2 viewSize, Pick how = Pick::Replace);
    bool removeSelected(std::string* why);     // everything selected, one step
    // The Objects list's eye and lock, for this session (Object::hidden, locked): one undo step
    // each, never unsaved. A hidden or locked object leaves the selection.
    void setHidden(int object, bool hidden);
    void setLocked(int object, bool locked);
    // Ctrl+C: the selected objects and groups as scene text (copyText); "" for none.
    std::string copySelection() const;
    // Ctrl+V: scene text's objects and groups added (pasteText) as one step, and selected.
    bool paste(const std::string& text, std::string* why);
    bool duplicateSelected(std::string* why);  // selects the copies
    // A Ctrl drag over the ground: the item's centre to `pos` in the world, one undo step.
    void placeItem(Item it, glm::vec3 pos, uint64_t mergeKey);
    void moveObject(int index, glm::vec3 pos, uint64_t mergeKey);  // placeItem() of an object
    // A gizmo's drag: object `index` becomes `o` ("Rotate object", ...), one undo step per key.
    void setObject(int index, const Object& o, const std::string& label, uint64_t mergeKey);
    // A gizmo's drag of the selection held at its press (applyGizmo()), one undo step per key.
    void dragSelection(const GizmoHold& hold, const GizmoDelta& d, const std::string& label,
                       uint64_t mergeKey);
    void moveLight(int index, glm::vec3 pos, uint64_t mergeKey);  // a point light's marker

    //-------------------------------------------------------------------------
    // [SECTION] Simulation
    //-------------------------------------------------------------------------
    void togglePlay();
    void setLoop(bool on);  // see Simulation: playing goes back to t = 0 at the loop's end
    void step();
    void resetSimulation();  // back to t = 0
    bool keepPoses();        // the simulated poses become the start; false at t = 0
    // To the cached frame at or before t (Home: t = 0), pausing; an undo step, one per drag
    // of the timeline (one mergeKey). False when nothing has run from this start.
    bool seek(double t, uint64_t mergeKey = 0);
    // To camera key `index`'s time as seek() does; false without that key.
    bool seekKey(int index, uint64_t mergeKey = 0);
    void frame(double seconds);  // the simulator's share of one frame
    const Simulation& simulation() const { return sim_; }

    // The camera moves as a view, not an edit: no undo step, no unsaved change.
    Camera& view() { return doc_.live().camera; }
    // Numpad . and Home: the camera looks at the selection (its objects and groups, or a point
    // light), or at every object, as they stand now, from where it looks, as close as lets them
    // fit the part of the view no panel covers (ViewWindow). False, the camera unmoved, when
    // there is nothing to frame.
    bool frameSelected(const ViewWindow& view);
    bool frameAll(const ViewWindow& view);
    // What the view shows: while playing a scene with keyframes, their path at the simulated
    // time; otherwise (at rest, paused, editing) the camera record.
    Camera shownCamera() const;
    bool followsPath() const;
    void addCameraKey();     // a key at the simulated time from the camera record
    bool deleteCameraKey();  // the key nearest the simulated time; false without keys
    // A key dragged along the timeline: one undo step a drag (one mergeKey). Returns the key's
    // new index, or -1 where moveCameraKey() refuses (the key stays).
    int moveCameraKey(int index, float t, uint64_t mergeKey);

    const Document& document() const { return doc_; }
    const Scene& scene() const { return doc_.scene(); }

private:
    void leaveNow(Leave what, const std::string& path);
    void setViewFlag(int object, bool Object::*flag, bool on, const char* label);
    void replace(const Scene& scene, const std::string& path);  // New or Open
    void reload(const Scene& disk);                              // the file changed on disk
    void edited();  // after any change of the scene outside the simulator
    void told(const Selection& before);  // the event log hears of a changed selection
    // A change of the object tree as one undo step; the selection follows its items.
    template <typename Command>
    bool treeEdit(const std::string& label, Command command);

    Document doc_;
    Selection sel_;
    Simulation sim_;
    Leave pending_ = Leave::None;
    std::string pendingPath_;
    Scene opening_;  // an Open's scene, read before anything was asked
    std::string lastFile_;
    DiskFile disk_;
    bool diskChanged_ = false;  // a change on disk waits for keepMine() or loadTheirs()
    bool saveOnKeep_ = false;   // a Save was refused for it
    bool quit_ = false;
    uint32_t kicks_ = 0;      // seeds J: different each press, the same in every run
    uint64_t loggedKey_ = 0;  // the merge key of the edit last told to the event log
};

}  // namespace mb
