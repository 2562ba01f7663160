// marchbox/editor/fields.h — every editable number of a scene, with the range SCENE_FORMAT.md
// allows and a narrower range that is comfortable to drag through.
//
// The editor never stores a value validateField() refuses, so a scene built in the editor
// always saves to a file that loads.
#pragma once

#include <glm/vec3.hpp>
#include <string>

namespace mb {

enum class Field : int {
    // camera, world, render
    Fov, Gravity, Restitution, Friction, Rolling, Floor,
    Steps, Epsilon, Shadows, Reflections, Fog, Aa,
    // material
    ColorChannel, Ka, Kd, Ks, Shininess, Reflectivity,
    // light
    LightColor, Intensity, LightPosition, LightDirection,
    // object
    Position, Radius, HalfExtent, Minor, Height, Rotation, Mass, Velocity, Spin, Blend,
    Count
};

struct FieldSpec {
    const char* name;          // the key in the file: "fov", "restitution", ...
    double min, max;           // allowed range; ±infinity where the format sets no bound
    bool minExclusive;         // "> 0" rather than ">= 0"
    float dragMin, dragMax;    // a sensible range for sliders; typing may go beyond it
    bool integer;              // steps, shadows, reflections, aa
    const char* format;        // printf format for widgets
};

const FieldSpec& fieldSpec(Field f);

// True when v may be stored: finite, in range, whole for integer fields. Otherwise *why holds
// one line such as "restitution must be between 0 and 1".
bool validateField(Field f, double v, std::string* why);

// Each component through validateField; a direction must not be zero.
bool validateVec(Field f, glm::vec3 v, std::string* why);

// A material name: one or more of A-Z a-z 0-9 _ . -
bool validateName(const std::string& name, std::string* why);

}  // namespace mb
