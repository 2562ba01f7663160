// shapes.h — the table of shapes: one row per ShapeType with what the file, the editor and the
// shaders know of it. The shader's type switches, its HAS_ macros, the parser's list of names,
// the editor's size fields and its Add menu are all made from these rows; the maths each layer
// does per shape (SDF, bounds, mass, probes) stays in that layer, in one switch a concern.
// docs/architecture.md ("Adding a shape") lists every place a new shape goes.
#pragma once

#include "marchbox/scene/scene.h"

#include <array>
#include <iterator>

namespace mb {

// The size keys of an object record a shape reads (and a save writes).
enum SizeKey : unsigned {
    kRadiusKey = 1u << 0,  // radius
    kSizeKey = 1u << 1,    // size: half-extents or semi-axes
    kMinorKey = 1u << 2,   // minor: a torus's tube
    kHeightKey = 1u << 3,  // height along local y
    kTopKey = 1u << 4,     // top: a cone's top radius
};

// GLSL calls are templates over shaders/sdf.glsl and intersect.glsl: `$q` is the point and `$r`,
// `$d` the ray in the object's frame, `$o` its record (scene_data.glsl's Object: shape.x radius,
// shape.y height, sizeMinor.xyz size, sizeMinor.w minor, detail.x top, detail.y round).
struct ShapeRow {
    ShapeType type;
    const char* name;   // the file's word and the editor's: "cone"
    const char* label;  // the Add menu's: "Cone"
    int since;          // the first format version that has it
    unsigned keys;      // SizeKey bits
    bool exact;         // its SDF is the true distance; otherwise a bound, exact on the surface
    bool edges;         // `round` rounds its edges (the others have none)
    const char* sdf;
    const char* rounded;  // the SDF with rounded edges ($o.detail.y), where it has edges
    const char* hit;      // the exact ray hit (< 0: a miss), or none where it is marched
};

inline constexpr ShapeRow kShapes[] = {
    {ShapeType::Sphere, "sphere", "Sphere", 1, kRadiusKey, true, false,  //
     "sdSphere($q, $o.shape.x)", nullptr, "hitSphere($r, $d, $o.shape.x)"},
    {ShapeType::Box, "box", "Box", 1, kSizeKey, true, true,  //
     "sdBox($q, $o.sizeMinor.xyz)", "sdRoundedBox($q, $o.sizeMinor.xyz, $o.detail.y)",
     "hitBox($r, $d, $o.sizeMinor.xyz)"},
    {ShapeType::Torus, "torus", "Torus", 1, kRadiusKey | kMinorKey, true, false,  //
     "sdTorus($q, $o.shape.x, $o.sizeMinor.w)", nullptr,
     "hitTorus($r, $d, $o.shape.x, $o.sizeMinor.w)"},
    {ShapeType::Capsule, "capsule", "Capsule", 1, kRadiusKey | kHeightKey, true, false,  //
     "sdCapsule($q, $o.shape.y, $o.shape.x)", nullptr,
     "hitCapsule($r, $d, $o.shape.y, $o.shape.x)"},
    {ShapeType::Cylinder, "cylinder", "Cylinder", 1, kRadiusKey | kHeightKey, true, true,  //
     "sdCylinder($q, $o.shape.y, $o.shape.x)",
     "sdRoundedCylinder($q, $o.shape.y, $o.shape.x, $o.detail.y)",
     "hitCylinder($r, $d, $o.shape.y, $o.shape.x)"},
    {ShapeType::Cone, "cone", "Cone", 3, kRadiusKey | kHeightKey | kTopKey, true, true,  //
     "sdCone($q, $o.shape.y, $o.shape.x, $o.detail.x)",
     "sdRoundedCone($q, $o.shape.y, $o.shape.x, $o.detail.x, $o.detail.y)",
     "hitCone($r, $d, $o.shape.y, $o.shape.x, $o.detail.x)"},
    {ShapeType::Ellipsoid, "ellipsoid", "Ellipsoid", 3, kSizeKey, false, false,  //
     "sdEllipsoid($q, $o.sizeMinor.xyz)", nullptr, "hitEllipsoid($r, $d, $o.sizeMinor.xyz)"},
};
static_assert(std::size(kShapes) == kShapeTypeCount, "a row for every ShapeType");

constexpr bool rowsInTypeOrder() {
    for (int t = 0; t < kShapeTypeCount; ++t)
        if (kShapes[t].type != ShapeType(t)) return false;
    return true;
}
static_assert(rowsInTypeOrder(), "row t describes ShapeType t");

constexpr const ShapeRow& shapeRow(ShapeType t) { return kShapes[int(t)]; }
constexpr bool reads(ShapeType t, SizeKey key) { return (shapeRow(t).keys & key) != 0u; }

// One column of the table, for a list a combo box or a menu shows.
template <const char* ShapeRow::*Column>
constexpr std::array<const char*, kShapeTypeCount> shapeColumn() {
    std::array<const char*, kShapeTypeCount> column{};
    for (int t = 0; t < kShapeTypeCount; ++t) column[size_t(t)] = kShapes[t].*Column;
    return column;
}

}  // namespace mb
