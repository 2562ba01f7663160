// fields.cpp — the ranges of SCENE_FORMAT.md, once, for every widget and check.
#include "marchbox/editor/fields.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "marchbox/scene_io.h"

namespace mb {

static constexpr double kInf = std::numeric_limits<double>::infinity();

// Rows in the order of enum Field.
static const FieldSpec kSpecs[] = {
    {"fov", 1, 179, false, 10, 120, false, "%.1f"},
    {"gravity", 0, kInf, false, 0, 30, false, "%.2f"},
    {"restitution", 0, 1, false, 0, 1, false, "%.2f"},
    {"friction", 0, kInf, false, 0, 2, false, "%.2f"},
    {"rolling", 0, kInf, false, 0, 0.2f, false, "%.3f"},
    {"floor", -kInf, kInf, false, -10, 10, false, "%.2f"},
    {"steps", 1, 4096, false, 16, 1024, true, "%.0f"},
    {"epsilon", 0, kInf, true, 1e-5f, 0.01f, false, "%.5f"},
    {"shadows", 0, 2, false, 0, 2, true, "%.0f"},
    {"reflections", 0, 8, false, 0, 8, true, "%.0f"},
    {"fog", 0, kInf, false, 0, 0.2f, false, "%.3f"},
    {"aa", 1, 4, false, 1, 4, true, "%.0f"},
    {"color", 0, kInf, false, 0, 1, false, "%.3f"},
    {"Ka", 0, kInf, false, 0, 1, false, "%.2f"},
    {"Kd", 0, kInf, false, 0, 1, false, "%.2f"},
    {"Ks", 0, kInf, false, 0, 1, false, "%.2f"},
    {"C", 0, kInf, true, 1, 256, false, "%.1f"},
    {"Kr", 0, 1, false, 0, 1, false, "%.2f"},
    {"color", 0, kInf, false, 0, 1, false, "%.3f"},
    {"intensity", 0, kInf, false, 0, 5, false, "%.2f"},
    {"pos", -kInf, kInf, false, -20, 20, false, "%.3f"},
    {"dir", -kInf, kInf, false, -1, 1, false, "%.3f"},
    {"pos", -kInf, kInf, false, -20, 20, false, "%.3f"},
    {"radius", 0, kInf, true, 0.01f, 5, false, "%.3f"},
    {"size", 0, kInf, true, 0.01f, 5, false, "%.3f"},
    {"minor", 0, kInf, true, 0.01f, 2, false, "%.3f"},
    {"height", 0, kInf, true, 0.01f, 10, false, "%.3f"},
    {"rot", -kInf, kInf, false, -180, 180, false, "%.1f"},
    {"mass", 0, kInf, false, 0, 20, false, "%.2f"},
    {"vel", -kInf, kInf, false, -20, 20, false, "%.2f"},
    {"spin", -kInf, kInf, false, -20, 20, false, "%.2f"},
    {"blend", 0, kInf, false, 0, 1, false, "%.3f"},
};
static_assert(sizeof kSpecs / sizeof kSpecs[0] == size_t(Field::Count), "one row per Field");

const FieldSpec& fieldSpec(Field f) { return kSpecs[int(f)]; }

static std::string num(double v) { return formatFloat(float(v)); }

static std::string rangeText(const FieldSpec& s) {
    std::string name = s.name;
    if (std::isinf(s.max)) return name + (s.minExclusive ? " must be > " : " must be >= ") + num(s.min);
    return name + " must be between " + num(s.min) + " and " + num(s.max);
}

bool validateField(Field f, double v, std::string* why) {
    const FieldSpec& s = fieldSpec(f);
    if (!std::isfinite(v)) {
        *why = std::string(s.name) + " must be a finite number";
        return false;
    }
    bool ok = (s.minExclusive ? v > s.min : v >= s.min) && v <= s.max;
    if (ok && s.integer && v != std::floor(v)) {
        *why = std::string(s.name) + " must be a whole number";
        return false;
    }
    // Past float range is not finite once stored.
    if (ok && std::abs(v) > double(std::numeric_limits<float>::max())) ok = false;
    if (!ok) *why = std::isinf(s.min) && std::isinf(s.max) ? std::string(s.name) + " is too large"
                                                            : rangeText(s);
    return ok;
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

bool validateName(const std::string& name, std::string* why) {
    auto allowed = [](unsigned char c) { return std::isalnum(c) || c == '_' || c == '.' || c == '-'; };
    if (!name.empty() && std::all_of(name.begin(), name.end(), allowed)) return true;
    *why = "a name is letters, digits, '_', '.' or '-', at least one";
    return false;
}

}  // namespace mb
