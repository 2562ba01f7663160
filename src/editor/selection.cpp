// selection.cpp — keeping the selection on its items while lists change, and the rules of
// clicks, boxes and Shift.
#include "marchbox/editor/selection.h"

#include <algorithm>

namespace mb {

static bool inTree(ItemKind k) { return k == ItemKind::Object || k == ItemKind::Group; }

bool Selection::has(ItemKind k, int i) const {
    return is(k, i) || std::binary_search(items.begin(), items.end(), Item{k, i});
}

static void tidy(std::vector<Item>& items) {
    std::sort(items.begin(), items.end());
    items.erase(std::unique(items.begin(), items.end()), items.end());
    items.erase(std::remove_if(items.begin(), items.end(), [](Item it) { return it.index < 0; }),
                items.end());
}

std::vector<Item> treeItems(const Selection& sel) {
    std::vector<Item> out = sel.items;
    if (inTree(sel.kind) && sel.index >= 0) out.push_back({sel.kind, sel.index});
    tidy(out);
    return out;
}

static void activate(Selection& sel, Item it) {
    sel.kind = it.kind;
    sel.index = it.index;
}

void selectOnly(Selection& sel, Item it) {
    sel.clear();
    activate(sel, it);
    if (inTree(it.kind) && it.index >= 0) sel.items = {it};
}

void toggleSelected(Selection& sel, Item it) {
    if (!inTree(it.kind) || it.index < 0) return selectOnly(sel, it);
    std::vector<Item> items = treeItems(sel);
    auto found = std::find(items.begin(), items.end(), it);
    if (found == items.end()) {
        items.push_back(it);
        activate(sel, it);
    } else {
        items.erase(found);
        if (sel.is(it.kind, it.index)) activate(sel, items.empty() ? Item{} : items.back());
    }
    sel.items = std::move(items);
    tidy(sel.items);
}

void selectItems(Selection& sel, const std::vector<Item>& items, bool extend) {
    std::vector<Item> all = extend ? treeItems(sel) : std::vector<Item>{};
    all.insert(all.end(), items.begin(), items.end());
    tidy(all);
    const bool stays = std::binary_search(all.begin(), all.end(), Item{sel.kind, sel.index});
    sel.items = std::move(all);
    if (stays) return;
    activate(sel, sel.items.empty() ? Item{} : items.empty() ? sel.items.front() : items.front());
}

std::vector<Item> everyTopItem(const Scene& s) { return children(s, -1); }

Item clickTarget(const Scene& s, const Selection& sel, int object) {
    const Item hit{ItemKind::Object, object};
    if (!validItem(s, hit)) return {ItemKind::Object, -1};
    if (sel.is(ItemKind::Object, object)) {
        const int g = s.objects[size_t(object)].group;
        return g >= 0 ? Item{ItemKind::Group, g} : hit;
    }
    if (sel.kind == ItemKind::Group && within(s, hit, sel.index)) {
        const int parent = s.groups[size_t(sel.index)].parent;
        return parent >= 0 ? Item{ItemKind::Group, parent} : hit;
    }
    return hit;
}

Item dragTarget(const Scene& s, const Selection& sel, int object) {
    Item target{ItemKind::Object, object};
    if (!validItem(s, target)) return target;
    for (int g = s.objects[size_t(object)].group; g >= 0; g = s.groups[size_t(g)].parent)
        if (sel.has(ItemKind::Group, g)) target = {ItemKind::Group, g};
    return target;
}

static std::string name(Item it) {
    return itemKindName(it.kind) + (" " + std::to_string(it.index));
}

std::string describe(const Selection& sel) {
    const std::vector<Item> items = treeItems(sel);
    if (items.size() <= 1) return sel.index < 0 ? "none" : name({sel.kind, sel.index});
    std::string out = std::to_string(items.size()) + " items:";
    for (size_t i = 0; i < items.size(); ++i) out += (i ? ", " : " ") + name(items[i]);
    return out;
}

void selectionAfterDelete(Selection& sel, ItemKind kind, int deleted) {
    auto follow = [&](Item it) -> Item {
        if (it.kind != kind || it.index < deleted) return it;
        return {it.kind, it.index == deleted ? -1 : it.index - 1};
    };
    sel.index = follow({sel.kind, sel.index}).index;
    for (Item& it : sel.items) it = follow(it);
    tidy(sel.items);
    if (sel.index < 0 && !sel.items.empty()) activate(sel, sel.items.back());
}

void selectionRenumber(Selection& sel, const Renumbering& r) {
    if (inTree(sel.kind)) sel.index = r({sel.kind, sel.index}).index;
    for (Item& it : sel.items) it = r(it);
    tidy(sel.items);
    if (sel.index < 0 && inTree(sel.kind) && !sel.items.empty()) activate(sel, sel.items.back());
}

void selectionClamp(Selection& sel, const Scene& scene) {
    if (sel.index >= itemCount(scene, sel.kind)) sel.index = -1;
    sel.items.erase(std::remove_if(sel.items.begin(), sel.items.end(),
                                   [&](Item it) { return it.index >= itemCount(scene, it.kind); }),
                    sel.items.end());
    if (sel.index < 0 && !sel.items.empty()) activate(sel, sel.items.back());
}

}  // namespace mb
