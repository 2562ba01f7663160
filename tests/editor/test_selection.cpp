// test_selection.cpp — one active item and more beside it: Shift, boxes, renumbering, the
// event log's words, and what a click or a Ctrl drag takes in a tree of groups.
#include "marchbox/editor/selection.h"
#include "marchbox/scene/scene_io.h"

#include <gtest/gtest.h>

using namespace mb;

namespace {

Item object(int i) { return {ItemKind::Object, i}; }
Item group(int g) { return {ItemKind::Group, g}; }

// objects a(0) b(1) c(2); group outer(0) holds b and group inner(1), which holds c.
Scene nested() {
    Scene s;
    std::vector<SceneError> errors;
    EXPECT_TRUE(
        parseScene("scene version:3\nmaterial r:1 g:1 b:1\n"
                   "object type:sphere pos:0,1,0 name:a\n"
                   "group name:outer\n"
                   "object in:outer type:sphere pos:1,1,0 name:b\n"
                   "group name:inner in:outer\n"
                   "object in:inner type:sphere pos:2,1,0 name:c\n",
                   &s, &errors));
    return s;
}

}  // namespace

TEST(Selection, ShiftAddsAndRemovesTheLastLeftActive) {
    Selection sel;
    selectOnly(sel, object(2));
    toggleSelected(sel, object(0));
    toggleSelected(sel, group(1));
    EXPECT_TRUE(sel.is(ItemKind::Group, 1));
    EXPECT_EQ(treeItems(sel), (std::vector<Item>{object(0), object(2), group(1)}));
    toggleSelected(sel, group(1));  // the active one leaves: the last left takes over
    EXPECT_TRUE(sel.is(ItemKind::Object, 2));
    toggleSelected(sel, object(0));
    EXPECT_TRUE(sel.has(ItemKind::Object, 2));
    EXPECT_FALSE(sel.has(ItemKind::Object, 0));
    toggleSelected(sel, {ItemKind::Light, 1});  // a light stands alone
    EXPECT_TRUE(sel.is(ItemKind::Light, 1));
    EXPECT_TRUE(treeItems(sel).empty());
    EXPECT_EQ(describe(sel), "light 1");
}

TEST(Selection, ABoxReplacesOrExtendsKeepingTheActiveItem) {
    Selection sel;
    selectOnly(sel, object(1));
    selectItems(sel, {object(3), object(2)}, true);
    EXPECT_TRUE(sel.is(ItemKind::Object, 1));
    EXPECT_EQ(describe(sel), "3 items: object 1, object 2, object 3");
    selectItems(sel, {object(3), object(2)}, false);  // the active one left: the first came
    EXPECT_TRUE(sel.is(ItemKind::Object, 3));
    selectItems(sel, {}, false);
    EXPECT_TRUE(sel.empty());
    EXPECT_EQ(describe(sel), "none");
}

TEST(Selection, FollowsItsItemsThroughATreeEdit) {
    Selection sel;
    selectItems(sel, {object(0), object(2), group(1)}, false);
    Renumbering r{{-1, 0, 1}, {1, -1}};  // object 0 and group 1 gone, the rest moved down
    selectionRenumber(sel, r);
    EXPECT_EQ(treeItems(sel), (std::vector<Item>{object(1)}));
    EXPECT_TRUE(sel.is(ItemKind::Object, 1));
}

TEST(Selection, AClickClimbsFromTheObjectThroughItsGroups) {
    const Scene s = nested();
    Selection sel;
    EXPECT_EQ(clickTarget(s, sel, 2), object(2));
    selectOnly(sel, object(2));
    EXPECT_EQ(clickTarget(s, sel, 2), group(1));
    selectOnly(sel, group(1));
    EXPECT_EQ(clickTarget(s, sel, 2), group(0));
    selectOnly(sel, group(0));
    EXPECT_EQ(clickTarget(s, sel, 2), object(2));  // from the top, back to the object
    EXPECT_EQ(clickTarget(s, sel, 0), object(0));  // a click elsewhere takes what it hits
    selectOnly(sel, object(0));
    EXPECT_EQ(clickTarget(s, sel, 0), object(0));  // no group above it: it stays
    EXPECT_EQ(clickTarget(s, sel, -1), object(-1));
}

TEST(Selection, ACtrlDragMovesTheOutermostSelectedGroupHoldingTheObject) {
    const Scene s = nested();
    Selection sel;
    EXPECT_EQ(dragTarget(s, sel, 2), object(2));
    selectItems(sel, {group(1), object(0)}, false);
    EXPECT_EQ(dragTarget(s, sel, 2), group(1));
    toggleSelected(sel, group(0));
    EXPECT_EQ(dragTarget(s, sel, 2), group(0));
    EXPECT_EQ(dragTarget(s, sel, 0), object(0));
    EXPECT_EQ(everyTopItem(s), (std::vector<Item>{object(0), group(0)}));
}
