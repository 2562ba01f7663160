// scene_tree.cpp — edits of the object tree. Each reads the scene into a list of children per
// parent, changes the lists, and writes the scene back in their order (flatten), as the loader
// does: the tree order then holds by construction, whatever the edit.
#include "marchbox/editor/scene_tree.h"

#include "marchbox/scene/sdf.h"

#include <algorithm>
#include <glm/gtc/quaternion.hpp>

namespace mb {

Item Renumbering::operator()(Item it) const {
    const std::vector<int>* map = it.kind == ItemKind::Object  ? &objects
                                  : it.kind == ItemKind::Group ? &groups
                                                               : nullptr;
    if (!map) return it;
    const bool known = it.index >= 0 && it.index < int(map->size());
    return {it.kind, known ? (*map)[size_t(it.index)] : -1};
}

namespace {

constexpr Item object(int i) { return {ItemKind::Object, i}; }
constexpr Item group(int g) { return {ItemKind::Group, g}; }

// Each parent's children in chain order: kids[parent + 1].
struct Tree {
    std::vector<std::vector<Item>> kids;
    std::vector<Item>& of(int parent) { return kids[size_t(parent + 1)]; }
    int add() {  // a list for a group just appended to the scene
        kids.emplace_back();
        return int(kids.size()) - 2;
    }
};

// A group stands just before objects[first] in its parent's chain; groups sharing a `first`
// stand in their stored (pre)order.
Tree treeOf(const Scene& s) {
    Tree t;
    t.kids.resize(s.groups.size() + 1);
    size_t g = 0;
    for (size_t i = 0; i <= s.objects.size(); ++i) {
        for (; g < s.groups.size() && s.groups[g].first <= int(i); ++g)
            t.of(s.groups[g].parent).push_back(group(int(g)));
        if (i < s.objects.size()) t.of(s.objects[i].group).push_back(object(int(i)));
    }
    return t;
}

// Writes the scene back in the tree's order: each group followed at once by its members.
class Flatten {
public:
    Flatten(Scene& s, Tree& t) : s_(s), t_(t) {
        r_.objects.assign(s.objects.size(), -1);
        r_.groups.assign(s.groups.size(), -1);
    }
    Renumbering run() {
        emit(-1, -1);
        s_.objects = std::move(objects_);
        s_.groups = std::move(groups_);
        return std::move(r_);
    }

private:
    void emit(int parent, int newParent) {
        for (Item it : t_.of(parent)) {
            if (it.kind == ItemKind::Object) {
                r_.objects[size_t(it.index)] = int(objects_.size());
                objects_.push_back(std::move(s_.objects[size_t(it.index)]));
                objects_.back().group = newParent;
                continue;
            }
            const int g = int(groups_.size());
            r_.groups[size_t(it.index)] = g;
            groups_.push_back(std::move(s_.groups[size_t(it.index)]));
            groups_.back().parent = newParent;
            groups_.back().first = int(objects_.size());
            emit(it.index, g);
        }
    }

    Scene& s_;
    Tree& t_;
    std::vector<Object> objects_;
    std::vector<Group> groups_;
    Renumbering r_;
};

Renumbering flatten(Scene& s, Tree& t) { return Flatten(s, t).run(); }

std::vector<Item> preorder(const Scene& s) {
    std::vector<Item> out;
    for (const TreeRow& row : treeRows(s)) out.push_back(row.item);
    return out;
}

int position(const std::vector<Item>& list, Item it) {
    return int(std::find(list.begin(), list.end(), it) - list.begin());
}

// Whether two turns are one, to within float noise (q and -q are the same turn).
bool sameTurn(glm::quat a, glm::quat b) {
    float same = 0.0f, flipped = 0.0f;
    for (int i = 0; i < 4; ++i) {
        same = std::max(same, std::abs(a[i] - b[i]));
        flipped = std::max(flipped, std::abs(a[i] + b[i]));
    }
    return std::min(same, flipped) < 1e-6f;
}

// A turn is kept exactly in `orient` where the record has one or moves, as the gizmo keeps it,
// and where Euler angles cannot hold it (near y = ±90 degrees they lose the turn about x and
// z); `rot` shows it either way.
template <class R>
void setTurn(R& r, glm::quat q, bool dynamic) {
    if (sameTurn(q, r.orientation())) return;
    q = glm::normalize(q);
    r.rot = eulerFromRotation(glm::mat3_cast(q));
    const bool held = sameTurn(glm::quat_cast(rotationFromEuler(r.rot)), q);
    if (r.orient || dynamic || !held) r.orient = q;
}

glm::vec3& posOf(Scene& s, Item it) {
    return it.kind == ItemKind::Object ? s.objects[size_t(it.index)].pos
                                       : s.groups[size_t(it.index)].pos;
}

Placement ownPose(const Scene& s, Item it) {
    if (it.kind == ItemKind::Object) {
        const Object& o = s.objects[size_t(it.index)];
        return {o.pos, o.orientation()};
    }
    const Group& g = s.groups[size_t(it.index)];
    return {g.pos, g.orientation()};
}

// Item `it`, whose own pos and turn were in frame `from`, into the frame of its parent now.
// Frames that share a turn (most often none) only shift it, so nothing but the move rounds.
void reframe(Scene& s, Item it, const Placement& from) {
    const Placement to = groupPose(s, parentOf(s, it));
    if (to.turn == from.turn) {
        posOf(s, it) += glm::inverse(to.turn) * (from.pos - to.pos);
        return;
    }
    setItemPose(s, it, compose(from, ownPose(s, it)));
}

// The motion keys: mass, vel, spin, static, friction and restitution.
template <class R, class From>
void takeMotion(R& r, const From& from) {
    r.mass = from.mass;
    r.vel = from.vel;
    r.spin = from.spin;
    r.isStatic = from.isStatic;
    r.friction = from.friction;
    r.restitution = from.restitution;
}

// A member has no motion: its keys go back to their defaults, as a file would load it.
template <class R>
void dropMotion(R& r) {
    takeMotion(r, R{});
}

// After `it` changed parent from `oldParent`: joining a group drops its motion; leaving for the
// top level takes that of `top`, the top-level group it left.
void changedLevel(Scene& s, Item it, int oldParent, const Group& top) {
    const int parent = parentOf(s, it);
    const bool joined = oldParent < 0 && parent >= 0, left = oldParent >= 0 && parent < 0;
    if (it.kind == ItemKind::Object) {
        Object& o = s.objects[size_t(it.index)];
        if (joined) dropMotion(o);
        if (left) takeMotion(o, top);
        return;
    }
    Group& g = s.groups[size_t(it.index)];
    if (joined) dropMotion(g);
    if (left) takeMotion(g, top);
}

int topGroup(const Scene& s, Item it) {
    int g = it.kind == ItemKind::Group ? it.index : -1;
    for (int p = parentOf(s, it); p >= 0; p = s.groups[size_t(p)].parent) g = p;
    return g;
}

Group topRecord(const Scene& s, Item it) {
    const int g = topGroup(s, it);
    return g >= 0 ? s.groups[size_t(g)] : Group{};
}

int depthOf(const Scene& s, int parent) { return parent < 0 ? 0 : groupDepth(s, parent); }

bool tooDeep(const Scene& s, int parent, int levels, std::string* why) {
    if (depthOf(s, parent) + levels <= kMaxGroupDepth) return false;
    *why = "groups nest at most " + std::to_string(kMaxGroupDepth) + " deep";
    return true;
}

}  // namespace

//-----------------------------------------------------------------------------
// [SECTION] Reading the tree
//-----------------------------------------------------------------------------
bool validItem(const Scene& s, Item it) {
    if (it.kind == ItemKind::Object) return it.index >= 0 && it.index < int(s.objects.size());
    if (it.kind == ItemKind::Group) return it.index >= 0 && it.index < int(s.groups.size());
    return false;
}

std::vector<Item> children(const Scene& s, int parent) { return treeOf(s).of(parent); }

int parentOf(const Scene& s, Item it) {
    return it.kind == ItemKind::Object ? s.objects[size_t(it.index)].group
                                       : s.groups[size_t(it.index)].parent;
}

TreeSpot spotOf(const Scene& s, Item it) {
    const int parent = parentOf(s, it);
    return {parent, position(children(s, parent), it)};
}

bool within(const Scene& s, Item it, int g) {
    if (!validItem(s, it)) return false;
    for (int p = it.kind == ItemKind::Group ? it.index : parentOf(s, it); p >= 0;
         p = s.groups[size_t(p)].parent)
        if (p == g) return true;
    return false;
}

std::vector<Item> roots(const Scene& s, const std::vector<Item>& items) {
    std::vector<bool> object(s.objects.size()), grouped(s.groups.size());
    for (Item it : items) {
        if (!validItem(s, it)) continue;
        (it.kind == ItemKind::Object ? object : grouped)[size_t(it.index)] = true;
    }
    auto held = [&](Item it) {
        return it.kind == ItemKind::Object ? object[size_t(it.index)] : grouped[size_t(it.index)];
    };
    auto inHeldGroup = [&](Item it) {
        for (int p = parentOf(s, it); p >= 0; p = s.groups[size_t(p)].parent)
            if (grouped[size_t(p)]) return true;
        return false;
    };
    std::vector<Item> out;
    for (Item it : preorder(s))
        if (held(it) && !inHeldGroup(it)) out.push_back(it);
    return out;
}

std::vector<TreeRow> treeRows(const Scene& s) {
    Tree t = treeOf(s);
    std::vector<TreeRow> out;
    auto walk = [&](auto&& self, int parent, int depth) -> void {
        for (Item it : t.of(parent)) {
            out.push_back({it, depth});
            if (it.kind == ItemKind::Group) self(self, it.index, depth + 1);
        }
    };
    walk(walk, -1, 0);
    return out;
}

int groupHeight(const Scene& s, int g) {
    int height = 1;
    for (size_t h = size_t(g) + 1; h < s.groups.size(); ++h)
        if (within(s, group(int(h)), g))
            height = std::max(height, 1 + groupDepth(s, int(h)) - groupDepth(s, g));
    return height;
}

bool treeInOrder(const Scene& s, std::string* why) {
    const int objects = int(s.objects.size()), groups = int(s.groups.size());
    for (int i = 0; i < objects; ++i)
        if (s.objects[size_t(i)].group < -1 || s.objects[size_t(i)].group >= groups)
            return *why = "object " + std::to_string(i) + " names no group", false;
    for (int g = 0; g < groups; ++g) {
        const Group& r = s.groups[size_t(g)];
        if (r.parent < -1 || r.parent >= g)
            return *why = "group " + std::to_string(g) + " does not follow its parent", false;
        if (r.first < 0 || r.first > objects)
            return *why = "group " + std::to_string(g) + " stands outside the objects", false;
    }
    Scene copy = s;
    Tree t = treeOf(copy);
    const Renumbering r = flatten(copy, t);
    for (int i = 0; i < objects; ++i)
        if (r.objects[size_t(i)] != i)
            return *why = "object " + std::to_string(i) + " is out of tree order", false;
    for (int g = 0; g < groups; ++g)
        if (r.groups[size_t(g)] != g || copy.groups[size_t(g)].first != s.groups[size_t(g)].first)
            return *why = "group " + std::to_string(g) + " is out of tree order", false;
    return true;
}

//-----------------------------------------------------------------------------
// [SECTION] Frames
//-----------------------------------------------------------------------------
Placement compose(const Placement& frame, const Placement& local) {
    return {frame.pos + frame.turn * local.pos, frame.turn * local.turn};
}

Placement relative(const Placement& frame, const Placement& world) {
    const glm::quat back = glm::inverse(frame.turn);
    return {back * (world.pos - frame.pos), back * world.turn};
}

Placement itemPose(const Scene& s, Item it) {
    return it.kind == ItemKind::Object ? worldPose(s, s.objects[size_t(it.index)])
                                       : groupPose(s, it.index);
}

void setItemPose(Scene& s, Item it, const Placement& world) {
    const Placement local = relative(groupPose(s, parentOf(s, it)), world);
    if (it.kind == ItemKind::Object) {
        Object& o = s.objects[size_t(it.index)];
        o.pos = local.pos;
        setTurn(o, local.turn, o.dynamic());
        return;
    }
    Group& g = s.groups[size_t(it.index)];
    g.pos = local.pos;
    setTurn(g, local.turn, g.dynamic());
}

//-----------------------------------------------------------------------------
// [SECTION] Edits
//-----------------------------------------------------------------------------
static bool room(const Scene& s, int objects, int groups, std::string* why) {
    if (int(s.objects.size()) + objects > kMaxObjects)
        return *why = "a scene holds at most " + std::to_string(kMaxObjects) + " objects", false;
    if (int(s.groups.size()) + groups > kMaxGroups)
        return *why = "a scene holds at most " + std::to_string(kMaxGroups) + " groups", false;
    return true;
}

static void insertAt(std::vector<Item>& list, int at, Item it) {
    const int n = int(list.size());
    list.insert(list.begin() + (at < 0 || at > n ? n : at), it);
}

int insertObject(Scene& s, Object o, TreeSpot spot, Renumbering* r, std::string* why) {
    if (!room(s, 1, 0, why)) return -1;
    if (spot.parent >= int(s.groups.size())) spot.parent = -1;
    if (spot.parent >= 0) dropMotion(o);
    Tree t = treeOf(s);
    s.objects.push_back(std::move(o));
    insertAt(t.of(spot.parent), spot.at, object(int(s.objects.size()) - 1));
    *r = flatten(s, t);
    return r->objects.back();
}

Renumbering eraseItems(Scene& s, const std::vector<Item>& items) {
    Tree t = treeOf(s);
    for (Item it : roots(s, items)) {
        std::vector<Item>& list = t.of(parentOf(s, it));
        list.erase(list.begin() + position(list, it));
    }
    return flatten(s, t);  // what the erased groups held is reached no more
}

bool moveItem(Scene& s, Item it, TreeSpot spot, Renumbering* r, std::string* why) {
    if (!validItem(s, it)) return *why = "nothing to move", false;
    if (spot.parent < -1 || spot.parent >= int(s.groups.size()))
        return *why = "no group " + std::to_string(spot.parent), false;
    if (it.kind == ItemKind::Group && spot.parent >= 0 && within(s, group(spot.parent), it.index))
        return *why = "a group cannot go inside itself", false;
    if (it.kind == ItemKind::Group && tooDeep(s, spot.parent, groupHeight(s, it.index), why))
        return false;
    const int oldParent = parentOf(s, it);
    const Placement from = groupPose(s, oldParent);
    const Group top = topRecord(s, it);
    Tree t = treeOf(s);
    std::vector<Item>& list = t.of(oldParent);
    const int was = position(list, it);
    list.erase(list.begin() + was);
    int at = spot.at < 0 ? int(t.of(spot.parent).size()) : spot.at;
    if (spot.parent == oldParent && was < at) --at;
    insertAt(t.of(spot.parent), at, it);
    *r = flatten(s, t);
    const Item moved = (*r)(it);
    reframe(s, moved, from);
    changedLevel(s, moved, oldParent, top);
    return true;
}

bool shiftItem(Scene& s, Item it, int by, Renumbering* r, std::string* why) {
    if (!validItem(s, it))
        return *why = std::string("no ") + itemKindName(it.kind) + " " + std::to_string(it.index),
               false;
    const TreeSpot spot = spotOf(s, it);
    const int to = spot.at + by;
    if (to < 0 || to >= int(children(s, spot.parent).size())) {
        *why = std::string(itemKindName(it.kind)) + " " + std::to_string(it.index) +
               " is already " + (by < 0 ? "first" : "last");
        return false;
    }
    return moveItem(s, it, {spot.parent, by > 0 ? to + 1 : to}, r, why);
}

std::string freeGroupName(const Scene& s, const std::string& base) {
    auto used = [&](const std::string& name) {
        return std::any_of(s.groups.begin(), s.groups.end(),
                           [&](const Group& g) { return g.name == name; });
    };
    if (!used(base)) return base;
    for (int n = 2;; ++n)
        if (!used(base + std::to_string(n))) return base + std::to_string(n);
}

namespace {

// Appends a copy of `it` and of everything in it to the scene and the tree; returns the copy.
Item copyInto(Scene& s, Tree& t, Item it) {
    if (it.kind == ItemKind::Object) {
        Object o = s.objects[size_t(it.index)];
        o.comment.clear();  // the file's notes stay with the original
        o.name = copyName(o.name, [&](const std::string& n) {
            return nameUsed(s, ItemKind::Object, n);
        });
        s.objects.push_back(std::move(o));
        return object(int(s.objects.size()) - 1);
    }
    Group g = s.groups[size_t(it.index)];
    g.comment.clear();
    g.name = copyName(g.name, [&](const std::string& n) {
        return nameUsed(s, ItemKind::Group, n);
    });
    s.groups.push_back(std::move(g));
    const int copy = t.add();
    const std::vector<Item> kids = t.of(it.index);  // t grows while the kids are copied
    for (Item kid : kids) {
        const Item c = copyInto(s, t, kid);
        t.of(copy).push_back(c);
    }
    return group(copy);
}

void countItems(const Scene& s, Item it, int* objects, int* groups) {
    if (it.kind == ItemKind::Object) {
        ++*objects;
        return;
    }
    ++*groups;
    *objects += groupEnd(s, it.index) - s.groups[size_t(it.index)].first;
    for (size_t h = size_t(it.index) + 1; h < s.groups.size(); ++h)
        if (within(s, group(int(h)), it.index)) ++*groups;
}

}  // namespace

bool duplicateItems(Scene& s, const std::vector<Item>& items, glm::vec3 aside,
                    std::vector<Item>* copies, Renumbering* r, std::string* why) {
    const std::vector<Item> from = roots(s, items);
    if (from.empty()) return *why = "nothing to duplicate", false;
    int objects = 0, groups = 0;
    for (Item it : from) countItems(s, it, &objects, &groups);
    if (!room(s, objects, groups, why)) return false;
    Tree t = treeOf(s);
    std::vector<Item> made;
    for (Item it : from) {
        made.push_back(copyInto(s, t, it));
        t.of(parentOf(s, it)).push_back(made.back());
    }
    *r = flatten(s, t);
    copies->clear();
    for (Item it : made) {
        const Item copy = (*r)(it);
        const Placement frame = groupPose(s, parentOf(s, copy));
        posOf(s, copy) += glm::inverse(frame.turn) * aside;
        copies->push_back(copy);
    }
    return true;
}

// Mass of the dynamic bodies among `items`: what a group made of them weighs.
static float bodiesMass(const Scene& s, const std::vector<Item>& items) {
    float mass = 0.0f;
    for (Item it : items) {
        if (it.kind == ItemKind::Object && s.objects[size_t(it.index)].dynamic())
            mass += s.objects[size_t(it.index)].mass;
        if (it.kind == ItemKind::Group && s.groups[size_t(it.index)].dynamic())
            mass += s.groups[size_t(it.index)].mass;
    }
    return mass > 0.0f ? mass : 1.0f;
}

// The new group's record: at the centre of `items`, unturned in its parent's frame.
static Group newGroup(const Scene& s, const std::vector<Item>& items, int parent) {
    glm::vec3 centre(0.0f);
    for (Item it : items) centre += itemPose(s, it).pos;
    centre /= float(items.size());
    Group g;
    g.name = freeGroupName(s, "group");
    g.parent = parent;
    g.pos = relative(groupPose(s, parent), {centre, glm::quat(1, 0, 0, 0)}).pos;
    if (parent < 0) {
        g.isStatic = true;
        g.mass = bodiesMass(s, items);
    }
    return g;
}

int groupItems(Scene& s, const std::vector<Item>& items, Renumbering* r, std::string* why) {
    const std::vector<Item> from = roots(s, items);
    if (from.empty()) return *why = "select objects or groups to group", -1;
    if (!room(s, 0, 1, why)) return -1;
    const int parent = parentOf(s, from.front());
    int height = 0;
    for (Item it : from)
        if (it.kind == ItemKind::Group) height = std::max(height, groupHeight(s, it.index));
    if (tooDeep(s, parent, 1 + height, why)) return -1;
    std::vector<Placement> frames;
    std::vector<int> parents;
    for (Item it : from) {
        parents.push_back(parentOf(s, it));
        frames.push_back(groupPose(s, parents.back()));
    }
    Tree t = treeOf(s);
    const int at = position(t.of(parent), from.front());
    s.groups.push_back(newGroup(s, from, parent));
    const int g = t.add();
    for (Item it : from) {
        std::vector<Item>& list = t.of(parentOf(s, it));
        list.erase(list.begin() + position(list, it));
        t.of(g).push_back(it);
    }
    insertAt(t.of(parent), at, group(g));
    *r = flatten(s, t);
    for (size_t i = 0; i < from.size(); ++i) {
        const Item moved = (*r)(from[i]);
        reframe(s, moved, frames[i]);
        changedLevel(s, moved, parents[i], Group{});
    }
    return r->groups[size_t(g)];
}

bool ungroup(Scene& s, int g, Renumbering* r, std::string* why) {
    if (!validItem(s, group(g))) return *why = "select a group to ungroup", false;
    const Group old = s.groups[size_t(g)];
    const Placement from = groupPose(s, g);
    Tree t = treeOf(s);
    const std::vector<Item> kids = t.of(g);
    std::vector<Item>& list = t.of(old.parent);
    const int at = position(list, group(g));
    list.erase(list.begin() + at);
    list.insert(list.begin() + at, kids.begin(), kids.end());
    *r = flatten(s, t);
    for (Item kid : kids) {
        const Item moved = (*r)(kid);
        reframe(s, moved, from);
        if (old.parent < 0) changedLevel(s, moved, g, old);
    }
    return true;
}

}  // namespace mb
