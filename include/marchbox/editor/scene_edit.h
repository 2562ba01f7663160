// marchbox/editor/scene_edit.h — the edit commands of the Edit menu, as plain functions on a Scene.
//
// Each keeps the scene valid by SCENE_FORMAT.md: lists stay within their limits and every
// object's material index exists. A command that cannot keep that promise refuses, saying why,
// and leaves the scene as it was.
#pragma once

#include "marchbox/scene/scene.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace mb {

enum class ItemKind : int { Object = 0, Material = 1, Light = 2, Group = 3 };
constexpr int kItemKindCount = 4;

// One item of a list: object 3, group 0, light 1. Objects and groups are the scene tree's items
// (scene_tree.h); materials and lights stand alone.
struct Item {
    ItemKind kind = ItemKind::Object;
    int index = -1;
    bool operator==(const Item&) const = default;
    auto operator<=>(const Item&) const = default;
};

const char* itemKindName(ItemKind k);  // "object", "material", "light", "group"
int itemCount(const Scene& s, ItemKind k);
int itemLimit(ItemKind k);  // kMaxObjects, kMaxMaterials, kMaxLights, kMaxGroups
// Whether `extra` more items of kind k fit; otherwise *why says the limit.
bool hasRoom(const Scene& s, ItemKind k, int extra, std::string* why);

Object defaultObject();      // a dynamic sphere of radius 0.5, 2 m above the origin
Material defaultMaterial();  // light grey, the format's default coefficients
Light defaultLight();        // a white point light above and behind the origin

// The object as type t, resting where it stood: moved up or down so that the new shape's lowest
// point, turned as the object is, is where the old one's was (depthBelowCentre).
Object retyped(Object o, ShapeType t);
// Object `index` of the scene retyped so: a member's lowest point stays where the world sees
// it, whatever its groups' turns.
Object retypedIn(const Scene& s, int index, ShapeType t);

// Keeps the version 3 shape keys within what the file allows after a change of type or size:
// `round` only on a box, cylinder or cone, `round` and `shell` under half the thinnest extent,
// a cone's `top` under its `radius`.
void fitShape(Object& o);

// Appends a default item; returns its index, or -1 with *why when the list is full. A new
// object needs a material: in a scene without one, a default material is added first.
int addItem(Scene& s, ItemKind k, std::string* why);

// Appends a copy of item `index` (objects, groups and point lights moved 1 m along +x so both
// show), without the original's comment lines, which stay with the original; returns the
// copy's index, or -1 with *why. An object's or group's copy goes last among its original's
// siblings (scene_tree.h), a group's with everything in it.
int duplicateItem(Scene& s, ItemKind k, int index, std::string* why);
// A copy's name, as Blender names it: "box" gives "box.001", "box.001" the next number that no
// name in use has ("box.002"). `used` says whether a name is taken; an empty name stays empty.
std::string copyName(const std::string& name, const std::function<bool(const std::string&)>& used);
// Whether an object, a group or a material (by kind) already has that name.
bool nameUsed(const Scene& s, ItemKind k, const std::string& name);
// `name` where no item of kind k has it, else copyName's next free one.
std::string unusedName(const Scene& s, ItemKind k, const std::string& name);

// Removes item `index`, and the comment lines above it in the file; a group with everything in
// it. Deleting a material renumbers the objects' indices; objects that used it take material 0.
// The last material cannot go while objects remain.
bool deleteItem(Scene& s, ItemKind k, int index, std::string* why);

// Moves object `index` by `by` places among its siblings (−1: up, earlier in the CSG chain; +1:
// down; more for a drag in the Objects list), its comment lines with it, the items it passes
// one place the other way. Returns its new index, or -1 with *why past either end.
int reorderObject(Scene& s, int index, int by, std::string* why);

// A field of one object edited while more are selected: each of `targets` takes the fields
// that differ between `before` and `after`, a vector's parts one by one (typing pos.x sets x
// alone). A change of type retypes each where it stands (retypedIn); motion keys go only to
// top-level objects, the ones that have them. The same for groups.
void applyObjectEdit(Scene& s, const std::vector<int>& targets, const Object& before,
                     const Object& after);
void applyGroupEdit(Scene& s, const std::vector<int>& targets, const Group& before,
                    const Group& after);

// Empties a list. Clearing objects clears the groups too; clearing groups leaves their objects
// where they stand. Clearing materials leaves one default material when objects remain.
void clearItems(Scene& s, ItemKind k);

// A fresh scene for File > New: ground, one light, one material, one sphere.
Scene newScene();

// A scene with nothing in it yet: the ground, the camera and one light. `marchbox NEW.txt`
// opens it for a file that does not exist, to be saved there.
Scene emptyScene();

// J in the editor: a random velocity for every dynamic body (objects, then groups), mostly
// sideways and a little up.
// Returns how many bodies it touched.
int randomizeVelocities(Scene& s, uint32_t seed);

}  // namespace mb
