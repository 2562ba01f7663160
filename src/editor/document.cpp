// document.cpp — edits, live changes and undo over one scene.
#include "marchbox/editor/document.h"

#include "marchbox/scene/scene_io.h"

#include <cstdio>
#include <filesystem>

namespace mb {

bool sameCamera(const Camera& a, const Camera& b) {
    return a.pos == b.pos && a.target == b.target && a.fov == b.fov;
}

std::string timeLabel(double seconds) {
    char text[48];
    std::snprintf(text, sizeof text, "t = %.2f s", seconds);
    return text;
}

std::string Document::name() const {
    return path_.empty() ? "untitled" : std::filesystem::path(path_).filename().string();
}

void Document::replace(const Scene& scene, const std::string& path) {
    scene_ = scene;
    path_ = path;
    history_.clear();
    saved_ = scene;
    fileCamera_ = scene.camera;
    time_ = 0;
    start_.reset();
    run_.reset();
    moments_.clear();
    ++version_;
    ++opened_;
}

void Document::markSaved(const std::string& path) {
    path_ = path;
    saved_ = start();
    fileCamera_ = saved_.camera;
    ++version_;
    history_.seal();  // a later drag must not fold into the step that was saved
}

void Document::reload(const Scene& disk) {
    const uint64_t was = history_.state();
    const bool ran = start_ || run_;  // going back to t = 0 is a step even if nothing else is
    Scene before = scene_;
    scene_ = disk;
    if (sameCamera(disk.camera, fileCamera_)) scene_.camera = before.camera;
    saved_ = disk;
    fileCamera_ = disk.camera;
    start_.reset();
    run_.reset();
    time_ = 0;
    ++version_;
    if (ran) history_.pushEvenIfSame("Reload from disk", before, scene_);
    else history_.push("Reload from disk", before, scene_);
    history_.seal();
    pushed(was);
}

// Compared once per version: while the simulator runs that is once a frame, about 0.2 ms for
// 4096 objects.
bool Document::dirty() const {
    if (checkedVersion_ != version_) {
        const Scene& first = start_ ? *start_ : scene_;
        saved_.camera = first.camera;
        dirty_ = !(saved_ == first);
        checkedVersion_ = version_;
    }
    return dirty_;
}

Scene Document::start() const {
    Scene s = start_ ? *start_ : scene_;
    s.camera = scene_.camera;
    return s;
}

// The objects and the groups they make: an edit of either is an event of the run.
static bool sameObjects(const Scene& a, const Scene& b) {
    Scene probe = a;
    probe.objects = b.objects;
    probe.groups = b.groups;
    return probe == a;
}

// What the simulator reads of `s`: its objects and groups, wearing the looks of `looks`'s
// (copyLooks), and its world where asked for.
static Scene motionOf(const Scene& s, const Scene& looks, bool world) {
    Scene m;
    m.objects = s.objects, m.groups = s.groups;
    copyLooks(looks.objects, m.objects);
    copyLooks(looks.groups, m.groups);
    if (world) m.world = s.world;
    return m;
}

// The same bodies, whatever their names and materials.
static bool sameBodies(const Scene& a, const Scene& b) {
    return motionOf(a, a, false) == motionOf(b, a, false);
}

// What the simulator reads: the rest (camera, looks, keys) leaves the run as it was.
static bool sameMotion(const Scene& a, const Scene& b) {
    return motionOf(a, a, true) == motionOf(b, a, true);
}

// The start holds the scene's objects and groups, one for one: no edit at t > 0 added or
// removed any, so a change of their looks made now can be made to it too.
static bool oneForOne(const Scene& start, const Scene& now) {
    return start.objects.size() == now.objects.size() && start.groups.size() == now.groups.size();
}

void Document::apply(const std::string& label, const SceneChange& change, uint64_t mergeKey) {
    const uint64_t was = history_.state();
    Scene before = scene_;
    change(scene_);
    // A change of the world, the camera, materials or lights, or of what objects are called
    // and look like, is the start's too: it keeps the run, which it cannot have changed.
    if (start_ && (sameObjects(scene_, before) ||
                   (sameBodies(scene_, before) && oneForOne(*start_, scene_)))) {
        Scene s = *start_;
        change(s);
        start_ = std::make_shared<const Scene>(std::move(s));
    } else if (start_ && time_ == 0) {  // scrubbed back to the start: an edit of it
        scene_ = start();               // the change's camera, the start's bodies
        start_.reset();
        change(scene_);
    }
    if (!sameMotion(scene_, before)) edited(time_, !sameObjects(scene_, before));
    ++version_;
    history_.push(label, before, scene_, mergeKey);
    pushed(was);
}

void Document::edited(double t, bool objects) {
    if (t <= 0) {  // an edit of the start: nothing has run from it yet
        run_.reset();
        return;
    }
    const std::shared_ptr<const RunPiece>& at = pieceAt(run_, t);
    // Edits at one time (each frame of a drag) make one piece: the last replaces the others,
    // and holds whatever edit of the objects they made.
    const bool replaces = at && at->from == t;
    std::shared_ptr<const RunPiece> before = replaces ? at->before : at;
    auto now = std::make_shared<const std::vector<Object>>(scene_.objects);
    auto groups = std::make_shared<const std::vector<Group>>(scene_.groups);
    objects = objects || (replaces && at->objectsEdited);
    run_ = std::make_shared<const RunPiece>(
        RunPiece{t, std::move(now), std::move(before), objects, std::move(groups)});
}

// A world edit at t > 0 is made to the start too (apply): only the objects' edits are lost.
bool Document::runEdits() const {
    for (const RunPiece* p = run_.get(); p; p = p->before.get())
        if (p->objectsEdited) return true;
    return false;
}

void Document::commit(const std::string& label, const Scene& before) {
    const uint64_t was = history_.state();
    Scene from = before;
    from.camera = scene_.camera;  // the view moving meanwhile is not part of the step
    history_.push(label, from, scene_);
    pushed(was);
}

Scene& Document::moving(double seconds) {
    if (!start_) start_ = std::make_shared<const Scene>(scene_);
    if (!run_) run_ = std::make_shared<const RunPiece>();  // from 0, with the start's objects
    run_ = pieceAt(run_, time_);  // an edit after now is no part of what follows
    time_ += seconds;
    return live();
}

// The run stays: it is still the run from this start, to scrub forward again.
bool Document::rewind(const std::string& label) { return start_ && restart(label, start()); }

bool Document::keep(const std::string& label) {
    if (!start_) return false;
    run_.reset();  // a new start: nothing has run from it
    return restart(label, scene_);
}

bool Document::restart(const std::string& label, const Scene& first) {
    const uint64_t was = history_.state();
    Scene before = scene_;
    scene_ = first;
    start_.reset();
    time_ = 0;
    ++version_;
    history_.pushEvenIfSame(label, before, scene_);
    pushed(was);
    return true;
}

void Document::show(const BakedFrame* frame) {
    if (!start_ && frame) start_ = std::make_shared<const Scene>(scene_);
    scene_ = start();
    if (frame) applyFrame(*frame, scene_);
    time_ = frame ? frame->t : 0;
    ++version_;
}

bool Document::seek(const std::string& label, const BakedFrame* frame, uint64_t mergeKey) {
    if (!run_) return false;
    const uint64_t was = history_.state();
    Scene before = scene_;
    show(frame);
    history_.pushEvenIfSame(label, before, scene_, mergeKey);
    pushed(was);
    return true;
}

void Document::pushed(uint64_t was) {
    const uint64_t now = history_.state();
    if (now == was) return;  // nothing was recorded
    if (start_ || run_) moments_[now] = {time_, start_, run_};
}

void Document::recall() {
    auto m = moments_.find(history_.state());
    time_ = m == moments_.end() ? 0 : m->second.time;
    start_ = m == moments_.end() ? nullptr : m->second.start;
    run_ = m == moments_.end() ? nullptr : m->second.run;
}

void Document::restore(const Scene& target, bool stepMovedCamera) {
    Camera view = scene_.camera;
    scene_ = target;
    if (!stepMovedCamera) scene_.camera = view;
    ++version_;
}

bool Document::undo(std::string* label) {
    const HistoryStep* s = history_.undo();
    if (!s) return false;
    restore(s->before, !sameCamera(s->before.camera, s->after.camera));
    recall();
    if (label) *label = s->label;
    return true;
}

bool Document::redo(std::string* label) {
    const HistoryStep* s = history_.redo();
    if (!s) return false;
    restore(s->after, !sameCamera(s->before.camera, s->after.camera));
    recall();
    if (label) *label = s->label;
    return true;
}

}  // namespace mb
