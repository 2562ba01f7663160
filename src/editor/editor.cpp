// editor.cpp — the rules between document, selection and simulation.
#include "marchbox/editor/editor.h"

#include "marchbox/editor/camera_control.h"
#include "marchbox/editor/camera_keys.h"
#include "marchbox/editor/events.h"
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
    if (!saveScene(path, doc_.start(), error)) {
        emitEvent("save-failed " + *error);
        return false;
    }
    doc_.markSaved(path);
    lastFile_ = path;
    emitEvent("save " + path);
    return true;
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
    const bool objectsKept = probe == e.scene();
    e.edit(
        label,
        [&](Scene& s) {
            std::vector<Object> own = std::move(s.objects);
            s = trial;
            if (objectsKept) s.objects = std::move(own);
        },
        mergeKey);
    return true;
}

bool Editor::add(ItemKind k, std::string* why, ShapeType shape) {
    const bool object = k == ItemKind::Object;
    int index = -1;
    const std::string label = object ? shapeTypeName(shape) : itemKindName(k);
    bool ok = tryEdit(*this, "Add " + label, [&](Scene& s) {
        Object o = defaultObject();
        o.type = shape;
        o.pos = object ? placeNewObject(s, o) : o.pos;  // clear of the others, not of itself
        if ((index = addItem(s, k, why)) < 0) return false;
        if (object) s.objects[size_t(index)] = o;
        return true;
    });
    if (ok) select(k, index);
    return ok;
}

bool Editor::duplicate(ItemKind k, int index, std::string* why) {
    int copy = -1;
    bool ok = tryEdit(*this, std::string("Duplicate ") + itemKindName(k),
                      [&](Scene& s) { return (copy = duplicateItem(s, k, index, why)) >= 0; });
    if (ok) select(k, copy);
    return ok;
}

bool Editor::remove(ItemKind k, int index, std::string* why) {
    // The selection moves before the edit, whose clamp would otherwise drop it.
    return tryEdit(*this, std::string("Delete ") + itemKindName(k), [&](Scene& s) {
        if (!deleteItem(s, k, index, why)) return false;
        selectionAfterDelete(sel_, k, index);
        return true;
    });
}

bool Editor::reorder(int object, int by, std::string* why) {
    int to = -1;
    bool ok = tryEdit(*this, by < 0 ? "Move object up" : "Move object down",
                      [&](Scene& s) { return (to = reorderObject(s, object, by, why)) >= 0; });
    if (ok) select(ItemKind::Object, to);
    return ok;
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
void Editor::select(ItemKind k, int index) {
    if (index >= itemCount(doc_.scene(), k)) index = -1;
    if (sel_.kind == k && sel_.index == index) return;
    sel_.kind = k;
    sel_.index = index;
    if (index < 0) emitEvent("select none");
    else emitEvent(std::string("select ") + itemKindName(k) + " " + std::to_string(index));
}

int Editor::pick(glm::vec2 pixel, glm::vec2 viewSize) {
    int hit = pickObject(doc_.scene(), pixel, viewSize);
    select(ItemKind::Object, hit);
    return hit;
}

bool Editor::removeSelected(std::string* why) {
    if (sel_.empty()) return false;
    return remove(sel_.kind, sel_.index, why);
}

void Editor::moveObject(int index, glm::vec3 pos, uint64_t mergeKey) {
    if (index < 0 || index >= int(doc_.scene().objects.size())) return;
    edit(
        "Move object", [&](Scene& s) { s.objects[size_t(index)].pos = pos; }, mergeKey);
}

void Editor::setObject(int index, const Object& o, const std::string& label, uint64_t mergeKey) {
    if (index < 0 || index >= int(doc_.scene().objects.size())) return;
    edit(
        label, [&](Scene& s) { s.objects[size_t(index)] = o; }, mergeKey);
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

static Ball objectBall(const Object& o) { return {o.pos, boundingRadius(o)}; }

bool Editor::frameSelected(float aspect) {
    std::vector<Ball> balls;
    const Scene& s = scene();
    if (sel_.kind == ItemKind::Object && sel_.index >= 0)
        balls.push_back(objectBall(s.objects[size_t(sel_.index)]));
    const bool pointLight = sel_.kind == ItemKind::Light && sel_.index >= 0 &&
                            !s.lights[size_t(sel_.index)].directional;
    if (pointLight) balls.push_back({s.lights[size_t(sel_.index)].vec, kLightFrameRadius});
    frameBalls(view(), balls, aspect);
    return !balls.empty();
}

bool Editor::frameAll(float aspect) {
    std::vector<Ball> balls;
    for (const Object& o : scene().objects) balls.push_back(objectBall(o));
    frameBalls(view(), balls, aspect);
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

void Editor::frame(double seconds) { sim_.advance(doc_, seconds); }

}  // namespace mb
