// marchbox/editor/history.h — undo and redo as a stack of whole-scene snapshots.
//
// Each step keeps the scene before and after one edit. Snapshots make every command trivially
// reversible (an edit may touch any field; a simulation run touches every dynamic body) and a
// scene of 4096 objects is only about 400 KiB, so the stack is simply bounded by its length.
#pragma once

#include "marchbox/scene/scene.h"

#include <cstdint>
#include <deque>
#include <string>

namespace mb {

struct HistoryStep {
    std::string label;  // "Delete object", "Simulation run", ...
    Scene before, after;
    uint64_t id = 0;        // names the state `after`; see History::state()
    uint64_t mergeKey = 0;  // nonzero: later pushes with the same key fold into this step
};

class History {
public:
    explicit History(size_t maxSteps = 200) : maxSteps_(maxSteps < 1 ? 1 : maxSteps) {}

    // Records one edit and drops everything that could be redone. A push whose scenes are equal
    // records nothing. With a nonzero mergeKey equal to the top step's, and no seal() since,
    // the top step's `after` is replaced instead: one slider drag is one undo step.
    void push(const std::string& label, const Scene& before, const Scene& after,
              uint64_t mergeKey = 0);
    // Records even when the scenes are equal: a step that changes what the document means by
    // its scene (the time shown, the start) without moving anything.
    void pushEvenIfSame(const std::string& label, const Scene& before, const Scene& after,
                        uint64_t mergeKey = 0);
    void seal() { sealed_ = true; }  // the next push starts a new step whatever its key

    const HistoryStep* undo();  // the step undone (restore its `before`), or null
    const HistoryStep* redo();  // the step redone (restore its `after`), or null
    bool canUndo() const { return cursor_ > 0; }
    bool canRedo() const { return cursor_ < steps_.size(); }
    std::string undoLabel() const { return canUndo() ? steps_[cursor_ - 1].label : ""; }
    std::string redoLabel() const { return canRedo() ? steps_[cursor_].label : ""; }

    // Names the current state. Two moments with the same name have the same scene, so a
    // document is clean while state() equals the name it had when saved.
    uint64_t state() const { return cursor_ > 0 ? steps_[cursor_ - 1].id : baseId_; }
    void clear();  // forgets every step; state() gets a fresh name
    size_t size() const { return steps_.size(); }

private:
    void record(const std::string& label, const Scene& before, const Scene& after,
                uint64_t mergeKey);

    std::deque<HistoryStep> steps_;
    size_t cursor_ = 0;  // steps_[0, cursor_) are done, the rest can be redone
    size_t maxSteps_;
    uint64_t baseId_ = 0;  // the state before steps_.front()
    uint64_t nextId_ = 1;
    bool sealed_ = true;
};

}  // namespace mb
