// fields.cpp — every field's range, unit and meaning, once, for every widget, check and tooltip.
#include "marchbox/editor/fields.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>

#include "marchbox/scene/scene_io.h"

namespace mb {

// Lengths and positions stop at 10 km, speeds at the simulator's guard (PhysicsSettings'
// maxSpeed); the rest at values no scene needs.
static constexpr double kFar = 1e4;

// Rows in the order of enum Field:
// name, min, max, minExclusive, dragMin, dragMax, integer, slider, format, unit, meaning.
static const FieldSpec kSpecs[] = {
    {"pos", -kFar, kFar, false, -20, 20, false, false, "%.3f", "m",
     "Where the camera is. Saved with the scene; moving it never marks the scene unsaved."},
    {"target", -kFar, kFar, false, -20, 20, false, false, "%.3f", "m",
     "The point the camera looks at and orbits about. Saved with the scene."},
    {"fov", 1, 179, false, 10, 120, false, true, "%.1f", "degrees", "Vertical field of view."},
    {"gravity", 0, 1000, false, 0, 30, false, false, "%.2f", "m/s\xC2\xB2",
     "Acceleration along -y."},
    {"restitution", 0, 1, false, 0, 1, false, true, "%.2f", "",
     "Bounciness: 0 stops, 1 keeps every bounce."},
    {"friction", 0, 100, false, 0, 2, false, false, "%.2f", "",
     "Coulomb coefficient, sphere on sphere and on statics."},
    {"rolling", 0, 100, false, 0, 0.2f, false, false, "%.3f", "",
     "Rolling resistance: torque rolling x radius x normal force."},
    {"floor", -kFar, kFar, false, -10, 10, false, false, "%.2f", "m",
     "Height of the ground plane."},
    {"steps", 1, 4096, false, 16, 1024, true, true, "%.0f", "", "Most march steps per ray."},
    {"epsilon", 0, 1, true, 1e-5f, 0.01f, false, false, "%.5f", "m",
     "Distance that counts as a hit."},
    {"shadows", 0, 2, false, 0, 2, true, true, "%.0f", "", "0 none, 1 hard, 2 soft."},
    {"reflections", 0, 8, false, 0, 8, true, true, "%.0f", "", "Most mirror bounces."},
    {"fog", 0, 10, false, 0, 0.2f, false, false, "%.3f", "1/m",
     "Density of exp\xC2\xB2 fog; 0 is none."},
    {"aa", 1, 4, false, 1, 4, true, true, "%.0f", "", "Samples per pixel along each axis."},
    {"color", 0, 100, false, 0, 1, false, false, "%.3f", "",
     "Red, green, blue; above 1 is brighter than white."},
    {"Ka", 0, 100, false, 0, 1, false, false, "%.2f", "", "Ambient coefficient."},
    {"Kd", 0, 100, false, 0, 1, false, false, "%.2f", "", "Diffuse coefficient."},
    {"Ks", 0, 100, false, 0, 1, false, false, "%.2f", "", "Specular coefficient."},
    {"C", 0, 10000, true, 1, 256, false, false, "%.1f", "", "Shininess: the specular exponent."},
    {"Kr", 0, 1, false, 0, 1, false, true, "%.2f", "", "Mirror reflectivity."},
    {"color", 0, 100, false, 0, 1, false, false, "%.3f", "",
     "Red, green, blue; above 1 is brighter than white."},
    {"intensity", 0, 10000, false, 0, 5, false, false, "%.2f", "", "Brightness, times the colour."},
    {"pos", -kFar, kFar, false, -20, 20, false, false, "%.3f", "m", "Where the point light is."},
    {"dir", -kFar, kFar, false, -1, 1, false, false, "%.3f", "",
     "The way the light shines; its length does not matter."},
    {"pos", -kFar, kFar, false, -20, 20, false, false, "%.3f", "m", "Centre."},
    {"radius", 0, kFar, true, 0.01f, 5, false, false, "%.3f", "m",
     "Radius of a sphere, torus ring, capsule or cylinder, or a cone's base."},
    {"size", 0, kFar, true, 0.01f, 5, false, false, "%.3f", "m",
     "Half the box's extent, or the ellipsoid's semi-axis, along each local axis."},
    {"minor", 0, kFar, true, 0.01f, 2, false, false, "%.3f", "m", "Radius of the torus tube."},
    {"height", 0, kFar, true, 0.01f, 10, false, false, "%.3f", "m",
     "Length along local y of a capsule's segment, a cylinder or a cone."},
    {"rot", -360, 360, false, -180, 180, false, false, "%.1f", "degrees",
     "Turns about x, then y, then z."},
    {"mass", 0, 1e6, false, 0, 20, false, false, "%.2f", "kg", "0 keeps a sphere still."},
    {"vel", -kFar, kFar, false, -20, 20, false, false, "%.2f", "m/s",
     "Velocity of a dynamic body."},
    {"spin", -kFar, kFar, false, -20, 20, false, false, "%.2f", "rad/s",
     "Angular velocity of a dynamic body."},
    {"blend", 0, kFar, false, 0, 1, false, false, "%.3f", "m",
     "Smooth-blend radius with the objects before; 0 is sharp."},
    {"top", 0, kFar, false, 0, 5, false, false, "%.3f", "m",
     "A cone's top radius: 0 for a point; kept below its base radius."},
    {"round", 0, kFar, false, 0, 1, false, false, "%.3f", "m",
     "Edge radius of a box, cylinder or cone; its faces keep their place."},
    {"shell", 0, kFar, false, 0, 1, false, false, "%.3f", "m",
     "Wall thickness: 0 for a solid, else hollow inside the surface."},
    {"repeat", 1, 64, false, 1, 16, true, false, "%.0f", "",
     "Copies of the group along x, y and z; at most 4096 in all."},
    {"spacing", 0, kFar, true, 0.01f, 10, false, false, "%.3f", "m",
     "Between the group's copies, along x, y and z."},
};
static_assert(sizeof kSpecs / sizeof kSpecs[0] == size_t(Field::Count), "one row per Field");

const FieldSpec& fieldSpec(Field f) { return kSpecs[int(f)]; }

// Floats as the file writes them; a double past float range as a double.
static std::string num(double v) {
    if (std::isnan(v) || std::abs(v) <= double(std::numeric_limits<float>::max()))
        return formatFloat(float(v));
    char buf[32];
    auto res = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, res.ptr);
}

std::string fieldRangeText(Field f) {
    const FieldSpec& s = fieldSpec(f);
    std::string unit = *s.unit ? std::string(" ") + s.unit : "";
    std::string whole = s.integer ? "a whole number " : "";
    if (s.minExclusive) return whole + "above " + num(s.min) + " and at most " + num(s.max) + unit;
    return whole + "between " + num(s.min) + " and " + num(s.max) + unit;
}

std::string fieldTooltip(Field f) {
    const FieldSpec& s = fieldSpec(f);
    std::string unit = *s.unit ? std::string("Unit: ") + s.unit + ". " : "No unit. ";
    return std::string(s.meaning) + "\n" + unit + "Range: " + fieldRangeText(f) + ".\n" +
           "Click to type a value, or drag.";
}

// The check behind validateField, its message naming `label` ("pos.y", "radius").
static bool check(Field f, double v, const std::string& label, std::string* why) {
    const FieldSpec& s = fieldSpec(f);
    if (std::isnan(v)) {
        *why = label + " must be a number";
        return false;
    }
    bool ok = (s.minExclusive ? v > s.min : v >= s.min) && v <= s.max;
    if (ok && s.integer && v != std::floor(v)) ok = false;
    if (!ok) *why = label + " must be " + fieldRangeText(f);
    return ok;
}

bool validateField(Field f, double v, std::string* why) {
    return check(f, v, fieldSpec(f).name, why);
}

bool validateVec(Field f, glm::vec3 v, std::string* why) {
    for (int i = 0; i < 3; ++i)
        if (!validateField(f, v[i], why)) return false;
    if (f == Field::LightDirection && v == glm::vec3(0.0f)) {
        *why = "a light direction must not be zero";
        return false;
    }
    return true;
}

static void refused(std::string* why, double typed, double kept) {
    *why += ": " + num(typed) + " refused, " + num(kept) + " kept";
}

bool acceptField(Field f, double typed, double kept, std::string* why) {
    if (validateField(f, typed, why)) return true;
    refused(why, typed, kept);
    return false;
}

bool acceptVec(Field f, glm::vec3 typed, glm::vec3 kept, std::string* why) {
    const bool colour = f == Field::ColorChannel || f == Field::LightColor;
    for (int i = 0; i < 3; ++i) {
        std::string label = std::string(fieldSpec(f).name) + "." + (colour ? "rgb" : "xyz")[i];
        if (typed[i] == kept[i] || check(f, typed[i], label, why)) continue;
        refused(why, typed[i], kept[i]);
        return false;
    }
    if (f == Field::LightDirection && typed == glm::vec3(0.0f)) {
        *why = "a light direction must not be zero: 0,0,0 refused, " + num(kept.x) + "," +
               num(kept.y) + "," + num(kept.z) + " kept";
        return false;
    }
    return true;
}

// A file's lines end at kMaxLineBytes: a longer name would save a material line that no longer
// loads. kMaxNameBytes leaves the line room for every other key, and for duplicates' "-copy"s.
bool validateName(const std::string& name, std::string* why) {
    auto allowed = [](unsigned char c) {
        return std::isalnum(c) || c == '_' || c == '.' || c == '-';
    };
    if (!name.empty() && name.size() <= kMaxNameBytes &&
        std::all_of(name.begin(), name.end(), allowed))
        return true;
    *why = "a name is letters, digits, '_', '.' or '-', 1 to " + std::to_string(kMaxNameBytes);
    return false;
}

}  // namespace mb
