// marchbox/editor/selection.h — the one item the panels and the viewport act on.
#pragma once

#include "marchbox/editor/scene_edit.h"

namespace mb {

struct Selection {
    ItemKind kind = ItemKind::Object;
    int index = -1;  // -1: nothing selected

    bool empty() const { return index < 0; }
    bool is(ItemKind k, int i) const { return kind == k && index == i && i >= 0; }
    int object() const { return kind == ItemKind::Object ? index : -1; }  // for the highlight
    void clear() { index = -1; }
};

// After item `deleted` of `kind` went: the selection follows its own item down the list, or
// empties when it was the one deleted.
void selectionAfterDelete(Selection& sel, ItemKind kind, int deleted);

// After undo, redo or a new file: a selection past the end of its list empties.
void selectionClamp(Selection& sel, const Scene& scene);

}  // namespace mb
