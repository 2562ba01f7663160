// marchbox/editor/fields.h — every editable number of a scene: its unit, the range the editor
// accepts, and a narrower range that is comfortable to drag through.
//
// The accepted range lies inside the one SCENE_FORMAT.md allows, so a scene built in the editor
// always saves to a file that loads. Where the format sets no bound the editor sets a generous
// one (10 km, 10000 m/s, ...): a value past it is a typing slip, not a scene. Every field
// refuses the same way: the value is not stored, the old one stays, and the message says both.
#pragma once

#include <glm/vec3.hpp>
#include <string>

namespace mb {

enum class Field : int {
    // camera, world, render
    CameraPosition,
    CameraTarget,
    Fov,
    Gravity,
    Restitution,
    Friction,
    Rolling,
    Floor,
    Steps,
    Epsilon,
    Shadows,
    Reflections,
    Fog,
    Aa,
    // material
    ColorChannel,
    Ka,
    Kd,
    Ks,
    Shininess,
    Reflectivity,
    // light
    LightColor,
    Intensity,
    LightPosition,
    LightDirection,
    // object
    Position,
    Radius,
    HalfExtent,
    Minor,
    Height,
    Rotation,
    Mass,
    Velocity,
    Spin,
    Blend,
    Top,
    Round,
    Shell,
    // group
    Repeat,
    Spacing,
    Count
};

struct FieldSpec {
    const char* name;        // the key in the file: "fov", "restitution", ...
    double min, max;         // the range the editor accepts, inside the format's
    bool minExclusive;       // "> 0" rather than ">= 0"
    float dragMin, dragMax;  // a sensible range for sliders; typing may go beyond it
    bool integer;            // steps, shadows, reflections, aa
    bool slider;             // a slider over dragMin..dragMax; otherwise a drag field
    const char* format;      // printf format for widgets
    const char* unit;        // "m", "m/s", "degrees", ...; "" for a pure number
    const char* meaning;     // one line for the tooltip
};

const FieldSpec& fieldSpec(Field f);

// The range in words, e.g. "above 0 and at most 10000 m", "between 0 and 1".
std::string fieldRangeText(Field f);

// The tooltip: meaning, unit and range, e.g. "Sphere, torus ring, capsule or cylinder radius.
// Metres (m), above 0 and at most 10000; click to type a value, or drag."
std::string fieldTooltip(Field f);

// True when v may be stored: a number, in range, whole for integer fields. Otherwise *why holds
// one line such as "restitution must be between 0 and 1".
bool validateField(Field f, double v, std::string* why);

// Each component through validateField; a direction must not be zero.
bool validateVec(Field f, glm::vec3 v, std::string* why);

// A value typed or dragged into a field whose stored value is `kept`. True when it may be
// stored; otherwise *why says what was refused and what stays, e.g. "radius must be above 0 and
// at most 10000 m: 1e+09 refused, 0.5 kept". A vector is checked where it differs from `kept`:
// a component loaded from a file beyond the editor's range stays editable beside it.
bool acceptField(Field f, double typed, double kept, std::string* why);
bool acceptVec(Field f, glm::vec3 typed, glm::vec3 kept, std::string* why);

// A material name: 1 to kMaxNameBytes of A-Z a-z 0-9 _ . -
constexpr size_t kMaxNameBytes = 256;
bool validateName(const std::string& name, std::string* why);

}  // namespace mb
