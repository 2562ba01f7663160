// marchbox/editor/scene_tree.h — the scene's objects and groups as a tree, and the edits that
// change the tree while the Scene stays in tree order (scene.h): each group's objects one run of
// `objects`, groups stored in preorder, and every `first`, `parent` and object `group` in step.
//
// [SECTION] Places: an item's parent and its place among that parent's children
// [SECTION] Reading the tree
// [SECTION] Frames: where an item stands in the world, and putting it there
// [SECTION] Edits: insert, erase, move, duplicate, group and ungroup
//
// Rules: items are objects and groups (Item, kind Object or Group); a parent is a group's index,
// -1 for the top level. An item that changes parent keeps its place in the world: its pos and
// turn are converted to the new parent's frame. Members have no motion of their own: an item
// that becomes a member drops its motion keys (mass, vel, spin, static, friction, restitution);
// one that comes out to the top level takes those of the top-level group it left. Every edit
// leaves the scene in tree order, or refuses with *why and leaves it as it was, and says how
// the old indices map to the new (Renumbering) so that a selection can follow its items.
#pragma once

#include "marchbox/editor/scene_edit.h"
#include "marchbox/scene/scene.h"

#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace mb {

//-----------------------------------------------------------------------------
// [SECTION] Places
//-----------------------------------------------------------------------------
// A place in the tree: among group `parent`'s children (-1: the top level), before child `at`
// as the children stand now (their count, or -1: after the last).
struct TreeSpot {
    int parent = -1;
    int at = -1;
    bool operator==(const TreeSpot&) const = default;
};

// Old index to new, for objects and groups; -1 where the item went.
struct Renumbering {
    std::vector<int> objects, groups;
    Item operator()(Item it) const;  // materials and lights unchanged; {kind, -1} for one gone
};

//-----------------------------------------------------------------------------
// [SECTION] Reading the tree
//-----------------------------------------------------------------------------
bool validItem(const Scene& s, Item it);                 // an object or group that exists
std::vector<Item> children(const Scene& s, int parent);  // in chain order
int parentOf(const Scene& s, Item it);                   // its group, -1 at the top level
TreeSpot spotOf(const Scene& s, Item it);                // its parent and its place there
bool within(const Scene& s, Item it, int group);         // it is that group or lies inside it
// The items none of whose groups is among them, each once, in tree order: what a command on a
// selection acts on (a member moves with its group, not a second time).
std::vector<Item> roots(const Scene& s, const std::vector<Item>& items);
// Every object and group in tree order, each with how many groups hold it: the Objects panel's
// rows, a group's members after it.
struct TreeRow {
    Item item;
    int depth = 0;
};
std::vector<TreeRow> treeRows(const Scene& s);
// How many levels of groups g holds, itself included: 1 for a group without groups in it.
int groupHeight(const Scene& s, int g);
// Whether the tree order holds (scene.h); *why names the first thing out of step.
bool treeInOrder(const Scene& s, std::string* why);

//-----------------------------------------------------------------------------
// [SECTION] Frames
//-----------------------------------------------------------------------------
Placement compose(const Placement& frame, const Placement& local);   // local within frame
Placement relative(const Placement& frame, const Placement& world);  // world seen from frame
Placement itemPose(const Scene& s, Item it);  // where the item stands in the world
// Sets the item's own pos and turn so that it stands at `world`. A turn that changes is shown
// in `rot` and kept exactly in `orient` where the item has one, moves, or stands where Euler
// angles lose the turn; one that does not change is left as it was.
void setItemPose(Scene& s, Item it, const Placement& world);

//-----------------------------------------------------------------------------
// [SECTION] Edits
//-----------------------------------------------------------------------------
// Puts `o`, its pos and turn in the spot's parent's frame, at `spot`; returns its index, or -1
// with *why when the scene is full.
int insertObject(Scene& s, Object o, TreeSpot spot, Renumbering* r, std::string* why);
// Removes the items, each group with everything inside it.
Renumbering eraseItems(Scene& s, const std::vector<Item>& items);
// Moves `it` to `spot`, keeping its place in the world. Refused for a group put inside
// itself, or where groups would nest deeper than kMaxGroupDepth.
bool moveItem(Scene& s, Item it, TreeSpot spot, Renumbering* r, std::string* why);
// Moves `it` by `by` places among its siblings (-1: earlier in its chain), the ones it passes
// one place the other way. False with *why past either end.
bool shiftItem(Scene& s, Item it, int by, Renumbering* r, std::string* why);
// A copy of each of the roots of `items` (a group with everything in it, named anew), last
// among its original's siblings and moved by `aside` in the world. *copies gets their new
// indices, in the order of roots(). Refused when the scene has no room.
bool duplicateItems(Scene& s, const std::vector<Item>& items, glm::vec3 aside,
                    std::vector<Item>* copies, Renumbering* r, std::string* why);
// A new group holding the roots of `items`, put where the first of them stood, with its
// origin at their centre and no turn of its own in its parent's frame. It is static (tick it
// dynamic to make it one body), with the mass of the dynamic bodies it took, or 1 kg. Returns
// its index, or -1 with *why (nothing to group, too many groups, nesting too deep).
int groupItems(Scene& s, const std::vector<Item>& items, Renumbering* r, std::string* why);
// Dissolves group g: its children take its place in its parent, where they stand in the
// world (its mirror and repeat go with it). Members coming out to the top level take g's
// motion keys.
bool ungroup(Scene& s, int g, Renumbering* r, std::string* why);
// A group name not yet used: `base`, else base2, base3, ...
std::string freeGroupName(const Scene& s, const std::string& base);

}  // namespace mb
