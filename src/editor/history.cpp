// history.cpp — the snapshot undo stack.
#include "marchbox/editor/history.h"

#include "marchbox/scene/scene_io.h"

namespace mb {

// Hidden and locked are no part of Scene equality (the file's), but hiding is an edit to undo.
static bool sameViewFlags(const Scene& a, const Scene& b) {
    if (a.objects.size() != b.objects.size()) return false;
    for (size_t i = 0; i < a.objects.size(); ++i)
        if (a.objects[i].hidden != b.objects[i].hidden || a.objects[i].locked != b.objects[i].locked)
            return false;
    return true;
}

void History::push(const std::string& label, const Scene& before, const Scene& after,
                   uint64_t mergeKey) {
    if (before == after && sameViewFlags(before, after)) return;
    record(label, before, after, mergeKey);
}

void History::pushEvenIfSame(const std::string& label, const Scene& before, const Scene& after,
                             uint64_t mergeKey) {
    record(label, before, after, mergeKey);
}

void History::record(const std::string& label, const Scene& before, const Scene& after,
                     uint64_t mergeKey) {
    bool merge = mergeKey != 0 && !sealed_ && cursor_ == steps_.size() && cursor_ > 0 &&
                 steps_.back().mergeKey == mergeKey;
    sealed_ = false;
    if (merge) {
        // A fresh id even so: the merged state differs from any state saved in between.
        steps_.back().after = after;
        steps_.back().id = nextId_++;
        return;
    }
    steps_.erase(steps_.begin() + long(cursor_), steps_.end());
    steps_.push_back({label, before, after, nextId_++, mergeKey});
    if (steps_.size() > maxSteps_) {
        baseId_ = steps_.front().id;  // the oldest step's `after` becomes the starting state
        steps_.pop_front();
    }
    cursor_ = steps_.size();
}

const HistoryStep* History::undo() {
    if (!canUndo()) return nullptr;
    sealed_ = true;
    return &steps_[--cursor_];
}

const HistoryStep* History::redo() {
    if (!canRedo()) return nullptr;
    sealed_ = true;
    return &steps_[cursor_++];
}

void History::clear() {
    steps_.clear();
    cursor_ = 0;
    baseId_ = nextId_++;
    sealed_ = true;
}

}  // namespace mb
