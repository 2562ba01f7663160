// marchbox/editor/scene_edit.h — the edit commands of the Edit menu, as plain functions on a Scene.
//
// Each keeps the scene valid by SCENE_FORMAT.md: lists stay within their limits and every
// object's material index exists. A command that cannot keep that promise refuses, saying why,
// and leaves the scene as it was.
#pragma once

#include "marchbox/scene/scene.h"

#include <cstdint>
#include <string>

namespace mb {

enum class ItemKind : int { Object = 0, Material = 1, Light = 2 };
constexpr int kItemKindCount = 3;

const char* itemKindName(ItemKind k);  // "object", "material", "light"
int itemCount(const Scene& s, ItemKind k);
int itemLimit(ItemKind k);  // kMaxObjects, kMaxMaterials, kMaxLights

Object defaultObject();      // a dynamic sphere of radius 0.5, 2 m above the origin
Material defaultMaterial();  // light grey, the format's default coefficients
Light defaultLight();        // a white point light above and behind the origin

// The object as type t, resting where it stood: moved up or down so that the new shape's lowest
// point, turned as the object is, is where the old one's was (depthBelowCentre).
Object retyped(Object o, ShapeType t);

// Appends a default item; returns its index, or -1 with *why when the list is full. A new
// object needs a material: in a scene without one, a default material is added first.
int addItem(Scene& s, ItemKind k, std::string* why);

// Appends a copy of item `index` (objects and point lights moved 1 m along +x so both show),
// without the original's comment lines, which stay with the original; returns the copy's
// index, or -1 with *why.
int duplicateItem(Scene& s, ItemKind k, int index, std::string* why);

// Removes item `index`, and the comment lines above it in the file. Deleting a material renumbers
// the objects' indices; objects that used it take material 0. The last material cannot go while
// objects remain.
bool deleteItem(Scene& s, ItemKind k, int index, std::string* why);

// Moves object `index` by `by` places in the list (−1: up, earlier in the CSG chain; +1: down;
// more for a drag in the Objects list), its comment lines with it, the objects it passes one
// place the other way. Returns its new index, or -1 with *why past either end.
int reorderObject(Scene& s, int index, int by, std::string* why);

// Empties a list. Clearing materials leaves one default material when objects remain.
void clearItems(Scene& s, ItemKind k);

// A fresh scene for File > New: ground, one light, one material, one sphere.
Scene newScene();

// A scene with nothing in it yet: the ground, the camera and one light. `marchbox NEW.txt`
// opens it for a file that does not exist, to be saved there.
Scene emptyScene();

// J in the editor: a random velocity for every dynamic body, mostly sideways and a little up.
// Returns how many bodies it touched.
int randomizeVelocities(Scene& s, uint32_t seed);

}  // namespace mb
