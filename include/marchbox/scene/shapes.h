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
    const char* name;       // the file's word and the editor's: "cone"
    const char* label;      // the Add menu's: "Cone"
    int since = 1;          // the first format version that has it
    unsigned keys = 0;      // SizeKey bits
    bool exact = true;      // its SDF is the true distance; otherwise a bound, exact on the surface
    bool edges = false;     // `round` rounds its edges (the others have none)
    bool revolved = false;  // a solid of revolution about local y: its x and z moments are equal
    bool centred = true;    // its centre of mass is its origin (else on its y axis)
    // What testing a ray against its exact hit costs, a sphere's being 1 (shader_source.cpp's
    // choice of the grid). Measured straight-line on llvmpipe, 4 and 16 turned objects of a type
    // at 480x270: a torus's quartic 4.3 times a sphere's, the other types 0.6 to 1.5 times.
    float hitCost = 1.5f;
    const char* sdf = nullptr;
    const char* rounded = nullptr;  // the SDF with rounded edges ($o.detail.y), where it has edges
    const char* hit = nullptr;      // the exact ray hit (< 0: a miss), or none where it is marched
};

inline constexpr ShapeRow kShapes[] = {
    {.type = ShapeType::Sphere,
     .name = "sphere",
     .label = "Sphere",
     .keys = kRadiusKey,
     .revolved = true,
     .hitCost = 1.0f,
     .sdf = "sdSphere($q, $o.shape.x)",
     .hit = "hitSphere($r, $d, $o.shape.x)"},
    {.type = ShapeType::Box,
     .name = "box",
     .label = "Box",
     .keys = kSizeKey,
     .edges = true,
     .sdf = "sdBox($q, $o.sizeMinor.xyz)",
     .rounded = "sdRoundedBox($q, $o.sizeMinor.xyz, $o.detail.y)",
     .hit = "hitBox($r, $d, $o.sizeMinor.xyz)"},
    {.type = ShapeType::Torus,
     .name = "torus",
     .label = "Torus",
     .keys = kRadiusKey | kMinorKey,
     .revolved = true,
     .hitCost = 4.0f,
     .sdf = "sdTorus($q, $o.shape.x, $o.sizeMinor.w)",
     .hit = "hitTorus($r, $d, $o.shape.x, $o.sizeMinor.w)"},
    {.type = ShapeType::Capsule,
     .name = "capsule",
     .label = "Capsule",
     .keys = kRadiusKey | kHeightKey,
     .revolved = true,
     .sdf = "sdCapsule($q, $o.shape.y, $o.shape.x)",
     .hit = "hitCapsule($r, $d, $o.shape.y, $o.shape.x)"},
    {.type = ShapeType::Cylinder,
     .name = "cylinder",
     .label = "Cylinder",
     .keys = kRadiusKey | kHeightKey,
     .edges = true,
     .revolved = true,
     .sdf = "sdCylinder($q, $o.shape.y, $o.shape.x)",
     .rounded = "sdRoundedCylinder($q, $o.shape.y, $o.shape.x, $o.detail.y)",
     .hit = "hitCylinder($r, $d, $o.shape.y, $o.shape.x)"},
    {.type = ShapeType::Cone,
     .name = "cone",
     .label = "Cone",
     .since = 3,
     .keys = kRadiusKey | kHeightKey | kTopKey,
     .edges = true,
     .revolved = true,
     .centred = false,
     .sdf = "sdCone($q, $o.shape.y, $o.shape.x, $o.detail.x)",
     .rounded = "sdRoundedCone($q, $o.shape.y, $o.shape.x, $o.detail.x, $o.detail.y)",
     .hit = "hitCone($r, $d, $o.shape.y, $o.shape.x, $o.detail.x)"},
    {.type = ShapeType::Ellipsoid,
     .name = "ellipsoid",
     .label = "Ellipsoid",
     .since = 3,
     .keys = kSizeKey,
     .exact = false,
     .sdf = "sdEllipsoid($q, $o.sizeMinor.xyz)",
     .hit = "hitEllipsoid($r, $d, $o.sizeMinor.xyz)"},
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
