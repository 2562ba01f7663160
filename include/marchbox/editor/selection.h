// marchbox/editor/selection.h — what the panels and the viewport act on: one active item, whose
// fields show, and, among objects and groups, any number more beside it (as in Blender).
#pragma once

#include "marchbox/editor/scene_edit.h"
#include "marchbox/editor/scene_tree.h"

#include <string>
#include <vector>

namespace mb {

struct Selection {
    ItemKind kind = ItemKind::Object;  // the active item's
    int index = -1;                    // the active item; -1: none
    std::vector<Item> items{};         // objects and groups selected (the active one too), sorted

    bool empty() const { return index < 0 && items.empty(); }
    bool is(ItemKind k, int i) const { return kind == k && index == i && i >= 0; }  // active
    bool has(ItemKind k, int i) const;                                    // selected, active or not
    int object() const { return kind == ItemKind::Object ? index : -1; }  // for the highlight
    void clear() {
        index = -1;
        items.clear();
    }
};

// The objects and groups selected, the active one included, sorted.
std::vector<Item> treeItems(const Selection& sel);

// A click: that item alone, active (index -1: nothing).
void selectOnly(Selection& sel, Item it);
// Shift+click: an object or group not selected joins the selection as the active item; one
// selected leaves it (the last one left becomes active). A material or light: selectOnly.
void toggleSelected(Selection& sel, Item it);
// A box, or Ctrl+A: `items` replace the selection, or join it (extend). The active item stays
// where it is still selected, else the first of them is.
void selectItems(Selection& sel, const std::vector<Item>& items, bool extend);
// Ctrl+A's items: every top-level object and group, so each is acted on once, with its members.
std::vector<Item> everyTopItem(const Scene& s);

// What a click on `object` in the view selects, as the selection stands: the object; clicked
// again while it is the active item, its group; again, that group's parent, up to the top
// level; once more, the object again.
Item clickTarget(const Scene& s, const Selection& sel, int object);

// What a Ctrl drag on `object` moves: the outermost selected group that holds it, else the
// object itself.
Item dragTarget(const Scene& s, const Selection& sel, int object);

// One line for the event log: "none", "object 3", or "3 items: object 0, object 2, group 0".
std::string describe(const Selection& sel);

// After item `deleted` of `kind` went: the selection follows its own item down the list, or
// empties when it was the one deleted.
void selectionAfterDelete(Selection& sel, ItemKind kind, int deleted);

// After an edit of the tree: each object and group follows its new index, and those gone leave.
void selectionRenumber(Selection& sel, const Renumbering& r);

// After undo, redo or a new file: items past the end of their lists leave the selection.
void selectionClamp(Selection& sel, const Scene& scene);

}  // namespace mb
