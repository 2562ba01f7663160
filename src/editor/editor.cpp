// editor.cpp — the rules between document, selection and simulation.
#include "marchbox/editor/editor.h"

#include "marchbox/editor/camera_control.h"
#include "marchbox/editor/camera_keys.h"
#include "marchbox/editor/clipboard.h"
#include "marchbox/editor/events.h"
#include "marchbox/editor/files.h"
#include "marchbox/editor/picking.h"
#include "marchbox/scene/camera_path.h"
#include "marchbox/scene/scene_io.h"
#include "marchbox/scene/sdf.h"

#include <cmath>
#include <cstdio>

namespace mb {

static const char* leaveName(Leave what) {
    static const char* names[] = {"none", "new", "open", "exit"};
    return names[int(what)];
}

//-----------------------------------------------------------------------------
// [SECTION] File
//-----------------------------------------------------------------------------
bool Editor::request(Leave what, const std::string& path, std::vector<std::string>* errors) {
    if (what == Leave::None) return true;
    if (what == Leave::Open && !loadScene(path, &opening_, errors)) {
        emitEvent("open-failed " + path);
        return false;
    }
    if (!doc_.dirty() && !doc_.runEdits()) {
        leaveNow(what, path);
        return true;
    }
    pending_ = what;
    pendingPath_ = path;
    emitEvent(std::string("ask ") + leaveName(what));
    return true;
}

void Editor::confirmLeave() {
    Leave what = pending_;
    pending_ = Leave::None;
    leaveNow(what, pendingPath_);
}

void Editor::cancelLeave() {
    pending_ = Leave::None;
    opening_ = Scene{};
}

void Editor::leaveNow(Leave what, const std::string& path) {
    switch (what) {
        case Leave::None:
            return;
        case Leave::NewScene:
            replace(newScene(), "");
            emitEvent("new");
            return;
        case Leave::Open:
            // The scene read when Open was asked for: what was checked is what opens.
            replace(opening_, path);
            opening_ = Scene{};
            lastFile_ = path;
            emitEvent("open " + path);
            return;
        case Leave::Exit:
            quit_ = true;
            emitEvent("quit");
            return;
    }
}

void Editor::replace(const Scene& scene, const std::string& path) {
    sim_.pause(doc_);  // before the history goes, so the run is not recorded into the new one
    doc_.replace(scene, path);
    sim_.sceneChanged(doc_);
    sel_.clear();
    disk_.track(path);
    diskChanged_ = saveOnKeep_ = false;
}

void Editor::start(const Scene& scene, const std::string& file) {
    replace(scene, file);
    lastFile_ = file;
    emitEvent(file.empty() ? "new" : "open " + file);
}

bool Editor::save(std::string* error) {
    if (doc_.path().empty()) {
        *error = "the scene has no file yet: use Save As";
        return false;
    }
    return saveAs(doc_.path(), error);
}

bool Editor::saveAs(const std::string& path, std::string* error) {
    if (path.empty()) {  // not a file that cannot be written: nothing to write to
        *error = "type a file name to save the scene to";
        emitEvent("refuse " + *error);
        return false;
    }
    // The start is what gets saved, whatever time the view shows; a running simulation is
    // recorded first so that the save names the state it was made in.
    sim_.commitRun(doc_);
    if (sameFile(path, disk_.path()) && disk_.differs()) {
        *error = doc_.name() + " changed on disk since it was opened or saved: keep yours, or "
                 "load theirs";
        diskChanged_ = saveOnKeep_ = true;
        emitEvent("ask disk " + path);
        return false;
    }
    if (!saveScene(path, doc_.start(), error)) {
        emitEvent("save-failed " + *error);
        return false;
    }
    doc_.markSaved(path);
    lastFile_ = path;
    disk_.track(path);
    emitEvent("save " + path);
    return true;
}

//-----------------------------------------------------------------------------
// [SECTION] The file on disk
//-----------------------------------------------------------------------------
void Editor::watchFile(std::vector<std::string>* errors) {
    if (diskChanged_ || !disk_.changedElsewhere()) return;
    Scene theirs;
    if (!loadScene(disk_.path(), &theirs, errors)) {
        emitEvent("disk-unloadable " + disk_.path());
        return;
    }
    if (doc_.dirty() || doc_.runEdits()) {
        diskChanged_ = true;
        emitEvent("ask disk " + disk_.path());
        return;
    }
    reload(theirs);
}

bool Editor::keepMine(std::string* error) {
    disk_.accept();
    diskChanged_ = false;
    const bool save = saveOnKeep_;
    saveOnKeep_ = false;
    emitEvent("keep-mine " + disk_.path());
    return !save || this->save(error);
}

bool Editor::loadTheirs(std::vector<std::string>* errors) {
    Scene theirs;
    disk_.differs();  // what is read next is what is accepted
    if (!loadScene(disk_.path(), &theirs, errors)) return false;
    diskChanged_ = saveOnKeep_ = false;
    reload(theirs);
    return true;
}

void Editor::reload(const Scene& disk) {
    sim_.pause(doc_);
    doc_.reload(disk);
    disk_.accept();
    sim_.sceneChanged(doc_);
    selectionClamp(sel_, doc_.scene());
    emitEvent("reload " + disk_.path());
}

//-----------------------------------------------------------------------------
// [SECTION] Edits
//-----------------------------------------------------------------------------
void Editor::edit(const std::string& label, const SceneChange& change, uint64_t mergeKey) {
    sim_.commitRun(doc_);
    doc_.apply(label, change, mergeKey);
    edited();
    // A drag sends an edit every frame: it is told once, when it starts.
    if (mergeKey == 0 || mergeKey != loggedKey_) emitEvent("edit " + label);
    loggedKey_ = mergeKey;
}

void Editor::endEdit() {
    doc_.seal();
    loggedKey_ = 0;
}

void Editor::edited() {
    sim_.sceneChanged(doc_);
    selectionClamp(sel_, doc_.scene());
}

bool Editor::undo() {
    sim_.pause(doc_);
    std::string label;
    if (!doc_.undo(&label)) return false;
    edited();
    emitEvent("undo " + label);
    return true;
}

bool Editor::redo() {
    sim_.pause(doc_);
    std::string label;
    if (!doc_.redo(&label)) return false;
    edited();
    emitEvent("redo " + label);
    return true;
}

// Runs a scene_edit command inside an undo step, keeping the scene untouched if it refuses.
// At t > 0 an edit that leaves the objects alone is made to the start too (Document::apply):
// there the start keeps its own bodies, not the poses shown.
template <typename Command>
static bool tryEdit(Editor& e, const std::string& label, Command command, uint64_t mergeKey = 0) {
    Scene trial = e.scene();  // made at the time shown, as every edit is
    if (!command(trial)) return false;
    Scene probe = e.scene();  // the scene shown with the trial's objects: unchanged if they are
    probe.objects = trial.objects;
    probe.groups = trial.groups;
    const bool objectsKept = probe == e.scene();
    e.edit(
        label,
        [&](Scene& s) {
            std::vector<Object> own = std::move(s.objects);
            std::vector<Group> groups = std::move(s.groups);
            s = trial;
            if (!objectsKept) return;
            s.objects = std::move(own);
            s.groups = std::move(groups);
        },
        mergeKey);
    return true;
}

// An edit of the tree: `command` changes a trial scene and says how items moved (Renumbering),
// or refuses. The selection follows its items before the edit is made, whose clamp would
// otherwise drop them.
template <typename Command>
bool Editor::treeEdit(const std::string& label, Command command) {
    const Selection before = sel_;
    const bool ok = tryEdit(*this, label, [&](Scene& s) {
        Renumbering r;
        if (!command(s, &r)) return false;
        selectionRenumber(sel_, r);
        return true;
    });
    told(before);
    return ok;
}

static std::string itemsLabel(const std::string& verb, const std::vector<Item>& items) {
    if (items.size() == 1) return verb + " " + itemKindName(items[0].kind);
    return verb + " " + std::to_string(items.size()) + " items";
}

bool Editor::add(ItemKind k, std::string* why, ShapeType shape, const ViewWindow& view) {
    const bool object = k == ItemKind::Object;
    int index = -1;
    const std::string label = object ? shapeTypeName(shape) : itemKindName(k);
    bool ok = tryEdit(*this, "Add " + label, [&](Scene& s) {
        Object o = defaultObject();
        o.type = shape;
        o.pos = object ? placeNewObject(s, o, view) : o.pos;  // clear of the others, not itself
        if ((index = addItem(s, k, why)) < 0) return false;
        if (object) s.objects[size_t(index)] = o;
        return true;
    });
    if (ok) select(k, index);
    return ok;
}

bool Editor::duplicate(ItemKind k, int index, std::string* why) {
    if (k == ItemKind::Object || k == ItemKind::Group) {
        const Selection was = sel_;
        selectOnly(sel_, {k, index});
        const bool ok = duplicateSelected(why);
        if (!ok) sel_ = was;
        return ok;
    }
    int copy = -1;
    bool ok = tryEdit(*this, std::string("Duplicate ") + itemKindName(k),
                      [&](Scene& s) { return (copy = duplicateItem(s, k, index, why)) >= 0; });
    if (ok) select(k, copy);
    return ok;
}

bool Editor::remove(ItemKind k, int index, std::string* why) {
    if (k == ItemKind::Object || k == ItemKind::Group) {
        if (!validItem(scene(), {k, index}))
            return *why = std::string("no ") + itemKindName(k) + " " + std::to_string(index), false;
        return treeEdit(std::string("Delete ") + itemKindName(k), [&](Scene& s, Renumbering* r) {
            *r = eraseItems(s, {{k, index}});
            return true;
        });
    }
    // The selection moves before the edit, whose clamp would otherwise drop it.
    return tryEdit(*this, std::string("Delete ") + itemKindName(k), [&](Scene& s) {
        if (!deleteItem(s, k, index, why)) return false;
        selectionAfterDelete(sel_, k, index);
        return true;
    });
}

bool Editor::reorder(int object, int by, std::string* why) {
    return reorder(Item{ItemKind::Object, object}, by, why);
}

bool Editor::reorder(Item it, int by, std::string* why) {
    const std::string label =
        std::string("Move ") + itemKindName(it.kind) + (by < 0 ? " up" : " down");
    Item to;
    const bool ok = treeEdit(label, [&](Scene& s, Renumbering* r) {
        if (!shiftItem(s, it, by, r, why)) return false;
        to = (*r)(it);
        return true;
    });
    if (ok) select(to.kind, to.index);
    return ok;
}

// Within its parent a move is a reorder, as the arrows make; else into or out of a group.
static std::string moveLabel(const Scene& s, Item it, TreeSpot spot) {
    const std::string what = std::string("Move ") + itemKindName(it.kind);
    const TreeSpot from = spotOf(s, it);
    if (from.parent == spot.parent)
        return what + (spot.at >= 0 && spot.at <= from.at ? " up" : " down");
    return what + (spot.parent >= 0 ? " into group" : " out of group");
}

bool Editor::moveTo(Item it, TreeSpot spot, std::string* why) {
    if (!validItem(scene(), it)) return *why = "nothing to move", false;
    Item to;
    const bool ok = treeEdit(moveLabel(scene(), it, spot), [&](Scene& s, Renumbering* r) {
        if (!moveItem(s, it, spot, r, why)) return false;
        to = (*r)(it);
        return true;
    });
    if (ok) select(to.kind, to.index);
    return ok;
}

bool Editor::groupSelected(std::string* why) {
    int g = -1;
    const bool ok = treeEdit("Group", [&](Scene& s, Renumbering* r) {
        return (g = groupItems(s, treeItems(sel_), r, why)) >= 0;
    });
    if (ok) select(ItemKind::Group, g);
    return ok;
}

// `then` after `first`: where each item of the scene before both ends up.
static Renumbering chain(const Renumbering& first, const Renumbering& then) {
    Renumbering r = first;
    for (int& o : r.objects) o = o < 0 ? -1 : then.objects[size_t(o)];
    for (int& g : r.groups) g = g < 0 ? -1 : then.groups[size_t(g)];
    return r;
}

static Renumbering unchanged(const Scene& s) {
    Renumbering r;
    for (size_t i = 0; i < s.objects.size(); ++i) r.objects.push_back(int(i));
    for (size_t g = 0; g < s.groups.size(); ++g) r.groups.push_back(int(g));
    return r;
}

bool Editor::ungroupSelected(std::string* why) {
    std::vector<int> groups;  // the last first: those before keep their index as it goes
    for (Item it : treeItems(sel_))
        if (it.kind == ItemKind::Group) groups.insert(groups.begin(), it.index);
    if (groups.empty()) return *why = "select a group to ungroup", false;
    std::vector<Item> freed;  // the groups' children, as each ungroup renumbers them
    const bool ok = treeEdit("Ungroup", [&](Scene& s, Renumbering* r) {
        *r = unchanged(s);
        for (int g : groups) {
            const std::vector<Item> kids = children(s, g);
            freed.insert(freed.end(), kids.begin(), kids.end());
            Renumbering step;
            if (!ungroup(s, g, &step, why)) return false;
            for (Item& it : freed) it = step(it);
            *r = chain(*r, step);
        }
        return true;
    });
    if (ok) selectItems(freed, false);
    return ok;
}

// Each selected item, the active one too, takes only the fields that changed: the same change
// is made to the start where it leaves the motion alone (a name, a material at t > 0), and a
// whole record would carry the pose shown into it.
void Editor::editObjects(const Object& before, const Object& after, uint64_t mergeKey) {
    if (sel_.object() < 0) return;
    std::vector<int> targets;
    for (Item it : treeItems(sel_))
        if (it.kind == ItemKind::Object) targets.push_back(it.index);
    edit(
        "Edit object",
        [targets, before, after](Scene& s) { applyObjectEdit(s, targets, before, after); },
        mergeKey);
}

void Editor::editGroups(const Group& before, const Group& after, uint64_t mergeKey) {
    const int active = sel_.kind == ItemKind::Group ? sel_.index : -1;
    if (active < 0 || active >= int(scene().groups.size())) return;
    std::vector<int> targets;
    for (Item it : treeItems(sel_))
        if (it.kind == ItemKind::Group) targets.push_back(it.index);
    edit(
        "Edit group",
        [active, targets, before, after](Scene& s) {
            s.groups[size_t(active)].name = after.name;  // unique: the active group's alone
            applyGroupEdit(s, targets, before, after);
        },
        mergeKey);
}

void Editor::clear(ItemKind k) {
    edit(std::string("Clear ") + itemKindName(k) + "s", [&](Scene& s) { clearItems(s, k); });
    selectionClamp(sel_, doc_.scene());
}

int Editor::kick() {
    int n = 0;
    uint32_t seed = ++kicks_;
    edit("Random velocities", [&](Scene& s) { n = randomizeVelocities(s, seed); });
    return n;
}

//-----------------------------------------------------------------------------
// [SECTION] Selection
//-----------------------------------------------------------------------------
void Editor::told(const Selection& before) {
    if (before.kind == sel_.kind && before.index == sel_.index && before.items == sel_.items)
        return;
    emitEvent("select " + describe(sel_));
}

void Editor::select(ItemKind k, int index) {
    if (index >= itemCount(doc_.scene(), k)) index = -1;
    const Selection before = sel_;
    selectOnly(sel_, {k, index});
    told(before);
}

void Editor::toggle(Item it) {
    if (!validItem(scene(), it)) return;
    const Selection before = sel_;
    toggleSelected(sel_, it);
    told(before);
}

void Editor::selectItems(const std::vector<Item>& items, bool extend) {
    std::vector<Item> valid;
    for (Item it : items)
        if (validItem(scene(), it)) valid.push_back(it);
    const Selection before = sel_;
    mb::selectItems(sel_, valid, extend);
    told(before);
}

void Editor::selectAll() { selectItems(everyTopItem(scene()), false); }

bool Editor::selectParent() {
    const Item active{sel_.kind, sel_.index};
    if (!validItem(scene(), active) || parentOf(scene(), active) < 0) return false;
    select(ItemKind::Group, parentOf(scene(), active));
    return true;
}

int Editor::pick(glm::vec2 pixel, glm::vec2 viewSize, Pick how) {
    const int hit = pickObject(doc_.scene(), pixel, viewSize);
    if (how == Pick::Toggle) {
        if (hit >= 0) toggle({ItemKind::Object, hit});
        return hit;
    }
    const Item target =
        how == Pick::Climb ? clickTarget(scene(), sel_, hit) : Item{ItemKind::Object, hit};
    select(target.kind, target.index);
    return hit;
}

bool Editor::removeSelected(std::string* why) {
    if (sel_.empty()) return false;
    const std::vector<Item> items = roots(scene(), treeItems(sel_));
    if (items.empty()) return remove(sel_.kind, sel_.index, why);
    return treeEdit(itemsLabel("Delete", items), [&](Scene& s, Renumbering* r) {
        *r = eraseItems(s, items);
        return true;
    });
}

// Hidden or locked, an object can no longer be clicked: it leaves the selection, as in Blender.
void Editor::setViewFlag(int object, bool Object::*flag, bool on, const char* label) {
    if (object < 0 || object >= int(scene().objects.size())) return;
    edit(label, [&](Scene& s) { s.objects[size_t(object)].*flag = on; });
    if (on && sel_.has(ItemKind::Object, object)) toggle({ItemKind::Object, object});
}

void Editor::setHidden(int object, bool hidden) {
    setViewFlag(object, &Object::hidden, hidden, hidden ? "Hide object" : "Show object");
}

void Editor::setLocked(int object, bool locked) {
    setViewFlag(object, &Object::locked, locked, locked ? "Lock object" : "Unlock object");
}

std::string Editor::copySelection() const {
    std::string text = copyText(scene(), treeItems(sel_));
    if (!text.empty()) emitEvent("copy " + describe(sel_));
    return text;
}

bool Editor::paste(const std::string& text, std::string* why) {
    std::vector<Item> pasted;
    if (!tryEdit(*this, "Paste", [&](Scene& s) { return pasteText(s, text, &pasted, why); })) {
        emitEvent("refuse " + *why);
        return false;
    }
    selectItems(pasted, false);
    return true;
}

bool Editor::duplicateSelected(std::string* why) {
    const std::vector<Item> items = roots(scene(), treeItems(sel_));
    if (items.empty()) return sel_.index >= 0 && duplicate(sel_.kind, sel_.index, why);
    std::vector<Item> copies;
    const bool ok = treeEdit(itemsLabel("Duplicate", items), [&](Scene& s, Renumbering* r) {
        return duplicateItems(s, items, kCopyAside, &copies, r, why);
    });
    if (ok) selectItems(copies, false);
    return ok;
}

void Editor::placeItem(Item it, glm::vec3 pos, uint64_t mergeKey) {
    if (!validItem(scene(), it)) return;
    const std::string label = std::string("Move ") + itemKindName(it.kind);
    edit(
        label,
        [&](Scene& s) {
            const Placement frame = groupPose(s, parentOf(s, it));
            const glm::vec3 local = glm::inverse(frame.turn) * (pos - frame.pos);
            if (it.kind == ItemKind::Object) s.objects[size_t(it.index)].pos = local;
            else s.groups[size_t(it.index)].pos = local;
        },
        mergeKey);
}

void Editor::moveObject(int index, glm::vec3 pos, uint64_t mergeKey) {
    placeItem({ItemKind::Object, index}, pos, mergeKey);
}

void Editor::setObject(int index, const Object& o, const std::string& label, uint64_t mergeKey) {
    if (index < 0 || index >= int(doc_.scene().objects.size())) return;
    edit(
        label, [&](Scene& s) { s.objects[size_t(index)] = o; }, mergeKey);
}

void Editor::dragSelection(const GizmoHold& hold, const GizmoDelta& d, const std::string& label,
                           uint64_t mergeKey) {
    edit(
        label, [&](Scene& s) { applyGizmo(s, hold, d); }, mergeKey);
}

void Editor::moveLight(int index, glm::vec3 pos, uint64_t mergeKey) {
    if (index < 0 || index >= int(doc_.scene().lights.size())) return;
    edit(
        "Move light", [&](Scene& s) { s.lights[size_t(index)].vec = pos; }, mergeKey);
}

//-----------------------------------------------------------------------------
// [SECTION] Simulation
//-----------------------------------------------------------------------------
void Editor::togglePlay() {
    if (sim_.playing()) {
        sim_.pause(doc_);
        emitEvent("pause");
    } else {
        sim_.play(doc_);
        emitEvent("play");
    }
}

void Editor::setLoop(bool on) {
    if (on == sim_.loop()) return;
    sim_.setLoop(on);
    emitEvent(on ? "loop on" : "loop off");
}

void Editor::step() {
    sim_.step(doc_);
    emitEvent("step");
}

void Editor::resetSimulation() {
    sim_.reset(doc_);
    selectionClamp(sel_, doc_.scene());
    emitEvent("reset");
}

bool Editor::keepPoses() {
    sim_.pause(doc_);
    if (!doc_.keep("Keep simulated poses")) return false;
    sim_.sceneChanged(doc_);  // nothing has run from the new start
    emitEvent("keep");
    return true;
}

bool Editor::followsPath() const {
    return sim_.playing() && doc_.time() > 0 && !scene().keyframes.empty();
}

// A point light's ball: big enough that framing it alone shows a little of around it.
static constexpr float kLightFrameRadius = 0.5f;

// Each item's ball in the world: an object's about its centre, a group's about its origin,
// holding every copy of its members.
static std::vector<Ball> itemBalls(const Scene& s, const std::vector<Item>& items) {
    const SceneSdf sdf = makeSceneSdf(s);
    std::vector<Ball> balls;
    for (Item it : items) {
        if (it.kind == ItemKind::Object) {
            const SdfObject& o = sdf.objects[size_t(it.index)];
            balls.push_back({o.pos, o.bound});
        } else {
            const SdfGroup& g = sdf.groups[size_t(it.index)];
            balls.push_back({g.pos, g.bound});
        }
    }
    return balls;
}

bool Editor::frameSelected(const ViewWindow& view) {
    const Scene& s = scene();
    std::vector<Ball> balls = itemBalls(s, roots(s, treeItems(sel_)));
    const bool pointLight = sel_.kind == ItemKind::Light && sel_.index >= 0 &&
                            !s.lights[size_t(sel_.index)].directional;
    if (pointLight) balls.push_back({s.lights[size_t(sel_.index)].vec, kLightFrameRadius});
    frameBalls(this->view(), balls, view);
    return !balls.empty();
}

bool Editor::frameAll(const ViewWindow& view) {
    std::vector<Item> all;
    for (size_t i = 0; i < scene().objects.size(); ++i) all.push_back({ItemKind::Object, int(i)});
    const std::vector<Ball> balls = itemBalls(scene(), all);
    frameBalls(this->view(), balls, view);
    return !balls.empty();
}

Camera Editor::shownCamera() const {
    return followsPath() ? cameraAt(scene().keyframes, scene().camera, doc_.time())
                         : scene().camera;
}

int Editor::moveCameraKey(int index, float t, uint64_t mergeKey) {
    int to = -1;
    tryEdit(
        *this, "Move camera key",
        [&](Scene& s) { return (to = mb::moveCameraKey(s, index, t)) >= 0; }, mergeKey);
    return to;
}

void Editor::addCameraKey() {
    const float t = float(doc_.time());
    // The view as shown: at t > 0 the edit is made to the start too, whose camera is older.
    const Camera view = scene().camera;
    edit("Add camera key", [&](Scene& s) { setCameraKey(s, t, view); });
}

bool Editor::deleteCameraKey() {
    const int k = nearestCameraKey(scene(), doc_.time());
    if (k < 0) return false;
    edit("Delete camera key", [&](Scene& s) { s.keyframes.erase(s.keyframes.begin() + k); });
    return true;
}

bool Editor::seek(double t, uint64_t mergeKey) {
    sim_.pause(doc_);
    // Frame times are sums of steps: one a rounding error past t still counts as at t.
    if (!doc_.seek("Scrub", sim_.cache().at(t + 1e-9), mergeKey)) return false;
    sim_.sceneChanged(doc_);
    const double to = doc_.time();
    if (mergeKey == 0 || mergeKey != loggedKey_) {
        char exact[32];  // to name the frame's step: `simulate --seconds` reads it back
        std::snprintf(exact, sizeof exact, " (%.9g)", to);
        emitEvent("seek " + timeLabel(to) + exact);
    }
    loggedKey_ = mergeKey;
    return true;
}

bool Editor::seekKey(int index, uint64_t mergeKey) {
    if (index < 0 || index >= int(scene().keyframes.size())) return false;
    // A key's time is the float nearest the frame it was added at, which may be a rounding
    // below that frame's time: the next float up is at or past it.
    const float t = scene().keyframes[size_t(index)].t;
    return seek(std::nextafter(t, INFINITY), mergeKey);
}

void Editor::frame(double seconds) {
    const bool playing = sim_.playing();
    sim_.advance(doc_, seconds);
    if (playing && !sim_.playing()) emitEvent("pause at rest " + timeLabel(sim_.restedAt()));
}

}  // namespace mb
