// scene_edit.cpp — add, duplicate, delete and clear for objects, groups, materials and lights.
#include "marchbox/editor/scene_edit.h"

#include "marchbox/editor/scene_tree.h"
#include "marchbox/scene/sdf.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace mb {

const char* itemKindName(ItemKind k) {
    static const char* names[kItemKindCount] = {"object", "material", "light", "group"};
    return names[int(k)];
}

int itemCount(const Scene& s, ItemKind k) {
    switch (k) {
        case ItemKind::Object:
            return int(s.objects.size());
        case ItemKind::Material:
            return int(s.materials.size());
        case ItemKind::Light:
            return int(s.lights.size());
        case ItemKind::Group:
            return int(s.groups.size());
    }
    return 0;
}

int itemLimit(ItemKind k) {
    switch (k) {
        case ItemKind::Object:
            return kMaxObjects;
        case ItemKind::Material:
            return kMaxMaterials;
        case ItemKind::Light:
            return kMaxLights;
        case ItemKind::Group:
            return kMaxGroups;
    }
    return 0;
}

Object defaultObject() {
    Object o;
    o.pos = {0.0f, 2.0f, 0.0f};
    return o;
}

Material defaultMaterial() {
    Material m;
    m.name = "material";
    m.color = glm::vec3(0.8f);
    return m;
}

Light defaultLight() {
    Light l;
    l.vec = {3.0f, 6.0f, -4.0f};
    return l;
}

// The largest float below v: "less than" in the file's rules.
static float justBelow(float v) { return std::nextafter(v, 0.0f); }

void fitShape(Object& o) {
    const bool edged = hasEdges(o.type);
    if (!edged) o.round = 0.0f;
    const float limit = halfThinnest(o);
    if (o.round >= limit) o.round = justBelow(limit);
    if (o.shell >= limit) o.shell = justBelow(limit);
    if (o.top >= o.radius) o.top = justBelow(o.radius);
}

Object retyped(Object o, ShapeType t) {
    const float lowest = o.pos.y - depthBelowCentre(o);
    o.type = t;
    fitShape(o);
    o.pos.y = lowest + depthBelowCentre(o);
    return o;
}

Object retypedIn(const Scene& s, int index, ShapeType t) {
    const Object& o = s.objects[size_t(index)];
    if (o.group < 0) return retyped(o, t);
    // Its lowest point in the world: the object as the world sees it, retyped, moved back.
    const Placement frame = groupPose(s, o.group), world = worldPose(s, o);
    Object seen = o;
    seen.pos = world.pos;
    seen.orient = world.turn;
    const glm::vec3 rise = retyped(seen, t).pos - seen.pos;
    Object out = retyped(o, t);
    out.pos = o.pos + glm::inverse(frame.turn) * rise;
    return out;
}

// Names like the loader's: "materialN" for the N-th material, so names stay distinct.
static Material numberedMaterial(const Scene& s) {
    Material m = defaultMaterial();
    m.name = "material" + std::to_string(s.materials.size());
    return m;
}

bool hasRoom(const Scene& s, ItemKind k, int extra, std::string* why) {
    if (itemCount(s, k) + extra <= itemLimit(k)) return true;
    *why = "a scene holds at most " + std::to_string(itemLimit(k)) + " " + itemKindName(k) + "s";
    return false;
}

static bool inRange(const Scene& s, ItemKind k, int index, std::string* why) {
    if (index >= 0 && index < itemCount(s, k)) return true;
    *why = std::string("no ") + itemKindName(k) + " " + std::to_string(index);
    return false;
}

int addItem(Scene& s, ItemKind k, std::string* why) {
    if (k == ItemKind::Group) {
        *why = "a group is made of objects: select them and use Group";
        return -1;
    }
    bool needMaterial = k == ItemKind::Object && s.materials.empty();
    if (!hasRoom(s, k, 1, why)) return -1;
    if (needMaterial) s.materials.push_back(numberedMaterial(s));
    switch (k) {
        case ItemKind::Object:
            s.objects.push_back(defaultObject());
            break;
        case ItemKind::Material:
            s.materials.push_back(numberedMaterial(s));
            break;
        case ItemKind::Light:
            s.lights.push_back(defaultLight());
            break;
        case ItemKind::Group:
            break;
    }
    return itemCount(s, k) - 1;
}

std::string copyName(const std::string& name,
                     const std::function<bool(const std::string&)>& used) {
    if (name.empty()) return name;
    // "box.001" counts on from "box": the stem is the name without a dot and 3+ digits.
    const size_t dot = name.find_last_of('.');
    const bool numbered = dot != std::string::npos && name.size() - dot >= 4 &&
                          name.find_first_not_of("0123456789", dot + 1) == std::string::npos;
    const std::string stem = numbered ? name.substr(0, dot) : name;
    char suffix[16];
    for (int n = 1;; ++n) {
        std::snprintf(suffix, sizeof suffix, ".%03d", n);
        if (!used(stem + suffix)) return stem + suffix;
    }
}

bool nameUsed(const Scene& s, ItemKind k, const std::string& name) {
    auto in = [&](const auto& list) {
        return std::any_of(list.begin(), list.end(), [&](const auto& r) { return r.name == name; });
    };
    switch (k) {
        case ItemKind::Object: return in(s.objects);
        case ItemKind::Group: return in(s.groups);
        case ItemKind::Material: return in(s.materials);
        case ItemKind::Light: return false;
    }
    return false;
}

std::string unusedName(const Scene& s, ItemKind k, const std::string& name) {
    auto used = [&](const std::string& n) { return nameUsed(s, k, n); };
    return used(name) ? copyName(name, used) : name;
}

int duplicateItem(Scene& s, ItemKind k, int index, std::string* why) {
    if (!inRange(s, k, index, why) || !hasRoom(s, k, 1, why)) return -1;
    const glm::vec3 aside(1.0f, 0.0f, 0.0f);
    switch (k) {
        case ItemKind::Object:
        case ItemKind::Group: {
            std::vector<Item> copies;
            Renumbering r;
            if (!duplicateItems(s, {{k, index}}, aside, &copies, &r, why)) return -1;
            return copies.front().index;
        }
        case ItemKind::Material: {
            Material m = s.materials[size_t(index)];
            m.name = copyName(m.name, [&](const std::string& n) {
                return nameUsed(s, ItemKind::Material, n);
            });
            m.comment.clear();
            s.materials.push_back(m);
            break;
        }
        case ItemKind::Light: {
            Light l = s.lights[size_t(index)];
            if (!l.directional) l.vec += aside;
            l.comment.clear();
            s.lights.push_back(l);
            break;
        }
    }
    return itemCount(s, k) - 1;
}

static bool deleteMaterial(Scene& s, int index, std::string* why) {
    if (s.materials.size() == 1 && !s.objects.empty()) {
        *why = "the objects need at least one material";
        return false;
    }
    s.materials.erase(s.materials.begin() + index);
    for (Object& o : s.objects) {
        if (o.material == index) o.material = 0;
        else if (o.material > index) --o.material;
    }
    return true;
}

bool deleteItem(Scene& s, ItemKind k, int index, std::string* why) {
    if (!inRange(s, k, index, why)) return false;
    switch (k) {
        case ItemKind::Object:
        case ItemKind::Group:
            eraseItems(s, {{k, index}});
            return true;
        case ItemKind::Material:
            return deleteMaterial(s, index, why);
        case ItemKind::Light:
            s.lights.erase(s.lights.begin() + index);
            return true;
    }
    return false;
}

int reorderObject(Scene& s, int index, int by, std::string* why) {
    if (!inRange(s, ItemKind::Object, index, why)) return -1;
    Renumbering r;
    if (!shiftItem(s, {ItemKind::Object, index}, by, &r, why)) return -1;
    return r.objects[size_t(index)];
}

namespace {

template <class T>
void take(const T& before, const T& after, T& target) {
    if (!(before == after)) target = after;
}

template <class V>
void takeParts(const V& before, const V& after, V& target) {
    for (int i = 0; i < 3; ++i)
        if (before[i] != after[i]) target[i] = after[i];
}

// A turn typed into `rot` replaces the exact one; the gizmo's turns come another way.
template <class R>
void takeTurn(const R& before, const R& after, R& target) {
    if (before.rot == after.rot) return;
    takeParts(before.rot, after.rot, target.rot);
    target.orient.reset();
}

template <class R>
void takeMotion(const R& before, const R& after, R& target) {
    take(before.mass, after.mass, target.mass);
    takeParts(before.vel, after.vel, target.vel);
    takeParts(before.spin, after.spin, target.spin);
    take(before.isStatic, after.isStatic, target.isStatic);
    take(before.friction, after.friction, target.friction);
    take(before.restitution, after.restitution, target.restitution);
}

void takeShape(const Object& before, const Object& after, Object& t) {
    take(before.radius, after.radius, t.radius);
    takeParts(before.size, after.size, t.size);
    take(before.minor, after.minor, t.minor);
    take(before.height, after.height, t.height);
    take(before.top, after.top, t.top);
    take(before.round, after.round, t.round);
    take(before.shell, after.shell, t.shell);
}

}  // namespace

void applyObjectEdit(Scene& s, const std::vector<int>& targets, const Object& before,
                     const Object& after) {
    for (int i : targets) {
        if (i < 0 || i >= int(s.objects.size())) continue;
        if (before.type != after.type) s.objects[size_t(i)] = retypedIn(s, i, after.type);
        Object& t = s.objects[size_t(i)];
        take(before.name, after.name, t.name);
        takeParts(before.pos, after.pos, t.pos);
        take(before.material, after.material, t.material);
        takeShape(before, after, t);
        takeTurn(before, after, t);
        take(before.op, after.op, t.op);
        take(before.blend, after.blend, t.blend);
        if (t.group < 0) takeMotion(before, after, t);
        fitShape(t);
    }
}

void applyGroupEdit(Scene& s, const std::vector<int>& targets, const Group& before,
                    const Group& after) {
    for (int g : targets) {
        if (g < 0 || g >= int(s.groups.size())) continue;
        Group& t = s.groups[size_t(g)];
        takeParts(before.pos, after.pos, t.pos);
        takeTurn(before, after, t);
        takeParts(before.mirror, after.mirror, t.mirror);
        takeParts(before.repeat, after.repeat, t.repeat);
        takeParts(before.spacing, after.spacing, t.spacing);
        take(before.op, after.op, t.op);
        take(before.blend, after.blend, t.blend);
        if (t.parent < 0) takeMotion(before, after, t);
    }
}

void clearItems(Scene& s, ItemKind k) {
    switch (k) {
        case ItemKind::Object:
            s.objects.clear();
            s.groups.clear();
            break;
        case ItemKind::Light:
            s.lights.clear();
            break;
        case ItemKind::Group: {  // the objects stay, where they stand
            Renumbering r;
            std::string unused;
            while (!s.groups.empty()) ungroup(s, 0, &r, &unused);
            break;
        }
        case ItemKind::Material:
            s.materials.clear();
            if (s.objects.empty()) break;
            s.materials.push_back(numberedMaterial(s));
            for (Object& o : s.objects) o.material = 0;
            break;
    }
}

Scene emptyScene() {
    Scene s;
    s.lights.push_back(defaultLight());
    return s;
}

Scene newScene() {
    Scene s = emptyScene();
    std::string unused;
    addItem(s, ItemKind::Object, &unused);  // brings its material
    s.materials[0].color = {0.9f, 0.3f, 0.2f};
    return s;
}

int randomizeVelocities(Scene& s, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> side(-4.0f, 4.0f), up(1.0f, 5.0f);
    int n = 0;
    for (Object& o : s.objects) {
        if (!o.dynamic()) continue;
        o.vel = {side(rng), up(rng), side(rng)};
        ++n;
    }
    for (Group& g : s.groups) {
        if (!g.dynamic()) continue;
        g.vel = {side(rng), up(rng), side(rng)};
        ++n;
    }
    return n;
}

}  // namespace mb
