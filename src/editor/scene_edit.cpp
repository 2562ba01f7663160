// scene_edit.cpp — add, duplicate, delete and clear for objects, materials and lights.
#include "marchbox/editor/scene_edit.h"

#include "marchbox/scene/sdf.h"

#include <algorithm>
#include <random>

namespace mb {

const char* itemKindName(ItemKind k) {
    static const char* names[] = {"object", "material", "light"};
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

Object retyped(Object o, ShapeType t) {
    const float lowest = o.pos.y - depthBelowCentre(o);
    o.type = t;
    o.pos.y = lowest + depthBelowCentre(o);
    return o;
}

// Names like the loader's: "materialN" for the N-th material, so names stay distinct.
static Material numberedMaterial(const Scene& s) {
    Material m = defaultMaterial();
    m.name = "material" + std::to_string(s.materials.size());
    return m;
}

static bool hasRoom(const Scene& s, ItemKind k, int extra, std::string* why) {
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
    }
    return itemCount(s, k) - 1;
}

int duplicateItem(Scene& s, ItemKind k, int index, std::string* why) {
    if (!inRange(s, k, index, why) || !hasRoom(s, k, 1, why)) return -1;
    const glm::vec3 aside(1.0f, 0.0f, 0.0f);
    switch (k) {
        case ItemKind::Object: {
            Object o = s.objects[size_t(index)];
            o.pos += aside;
            o.comment.clear();
            s.objects.push_back(o);
            break;
        }
        case ItemKind::Material: {
            Material m = s.materials[size_t(index)];
            m.name += "-copy";
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
            s.objects.erase(s.objects.begin() + index);
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
    const int to = index + by;
    if (to < 0 || to >= int(s.objects.size())) {
        *why = "object " + std::to_string(index) + " is already " + (by < 0 ? "first" : "last");
        return -1;
    }
    // The ones between shift one place towards where it was: a drag from 0 onto 3 gives 1 2 3 0.
    auto at = [&](int i) { return s.objects.begin() + i; };
    if (by < 0) std::rotate(at(to), at(index), at(index + 1));
    else std::rotate(at(index), at(index + 1), at(to + 1));
    return to;
}

void clearItems(Scene& s, ItemKind k) {
    switch (k) {
        case ItemKind::Object:
            s.objects.clear();
            break;
        case ItemKind::Light:
            s.lights.clear();
            break;
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
    return n;
}

}  // namespace mb
