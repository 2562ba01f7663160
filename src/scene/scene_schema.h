// scene_schema.h — the keys of each scene-file record, one row per key (private to core).
//
// One table drives the reader, the writer and operator==, so a key added here is read, written
// and compared without touching any of them. Rows are in the order the saver writes them.
//
//     key(name, field, rule = {}, need = {});
//
// `field` is a member pointer or a generic lambda returning a reference (std::invoke takes
// both); the C++ type of the field decides the value syntax (float: Number, glm::vec3: Vector,
// glm::quat: Quaternion, int: whole Number, bool: Flag, std::string: Name, ShapeType / CsgOp:
// their names; std::optional of any: the key may be absent, and is then not written).
#pragma once

#include "marchbox/scene/scene.h"
#include "marchbox/scene/shapes.h"

#include <limits>
#include <string>
#include <string_view>

namespace mb {

// Range of a number, or of each component of a vector.
struct Rule {
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    bool above = false;    // lo is exclusive: the value must be > lo
    bool nonZero = false;  // a vector must not be 0,0,0 (it is a direction)
};
constexpr Rule atLeast(double lo) { return {lo, std::numeric_limits<double>::infinity()}; }
constexpr Rule above(double lo) { return {lo, std::numeric_limits<double>::infinity(), true}; }
constexpr Rule between(double lo, double hi) { return {lo, hi}; }
constexpr Rule kNonZero{-std::numeric_limits<double>::infinity(),
                        std::numeric_limits<double>::infinity(), false, true};

// Whether a key must be present. `pick` marks alternative spellings of one field: exactly one
// of a record's picking keys must be present, reading it sets rec.*pick = when, and the writer
// writes the one whose `when` matches.
template <class R>
struct Need {
    bool required = false;
    bool R::*pick = nullptr;
    bool when = false;
    int since = 1;                        // the version that added it: an error in older files
    bool (*written)(const R&) = nullptr;  // where set, the writer writes the key only if true
};

// The `scene` record: it has no counterpart in Scene, only a version to check. Files without
// one are version 1; saves write version 3.
struct SceneHeader {
    int version = 1;
};
constexpr int kSceneVersion = 3;

// A dynamic object saves its exact turn, `orient`, in place of `rot`; so does any object or
// group that has one, so that it reads back the same.
template <class R>
bool writesOrient(const R& o) {
    return o.orient.has_value();
}
template <class R>
bool writesRot(const R& o) {
    return !o.orient.has_value();
}
template <class R>
bool hasFriction(const R& o) {
    return o.friction.has_value();
}
template <class R>
bool hasRestitution(const R& o) {
    return o.restitution.has_value();
}
inline bool hasName(const Object& o) { return !o.name.empty(); }
// The motion keys belong to top-level objects and groups: a member moves with its group.
inline bool movesAlone(const Object& o) { return o.group < 0; }
inline bool movesAlone(const Group& g) { return g.parent < 0; }
// Each type writes the size keys it uses.
inline bool usesRadius(const Object& o) { return reads(o.type, kRadiusKey); }
inline bool usesSize(const Object& o) { return reads(o.type, kSizeKey); }
inline bool usesMinor(const Object& o) { return reads(o.type, kMinorKey); }
inline bool usesHeight(const Object& o) { return reads(o.type, kHeightKey); }
inline bool usesTop(const Object& o) { return reads(o.type, kTopKey) && o.top != 0.0f; }
inline bool isRounded(const Object& o) { return o.round != 0.0f; }
inline bool isShelled(const Object& o) { return o.shell != 0.0f; }
inline bool isMirrored(const Group& g) { return glm::any(g.mirror); }
inline bool isRepeated(const Group& g) { return g.repeat != glm::ivec3(1); }
inline bool hasSpacing(const Group& g) { return g.spacing != glm::vec3(1.0f); }
inline bool isBlended(const Group& g) { return g.blend != 0.0f; }
inline bool isCarving(const Group& g) { return g.op != CsgOp::Union; }
inline bool isTurned(const Group& g) { return !g.orient && g.rot != glm::vec3(0.0f); }

template <class R>
struct Schema;

template <>
struct Schema<SceneHeader> {
    static constexpr const char* kind = "scene";
    template <class K>
    static void keys(K& key) {
        key("version", &SceneHeader::version, between(1, kSceneVersion));
    }
};

template <>
struct Schema<Camera> {
    static constexpr const char* kind = "camera";
    template <class K>
    static void keys(K& key) {
        key("pos", &Camera::pos);
        key("target", &Camera::target);
        key("fov", &Camera::fov, between(1, 179));
    }
};

template <>
struct Schema<Keyframe> {
    static constexpr const char* kind = "keyframe";
    template <class K>
    static void keys(K& key) {
        key("t", &Keyframe::t, atLeast(0), Need<Keyframe>{true});
        key("pos", &Keyframe::pos);
        key("target", &Keyframe::target);
        key("fov", &Keyframe::fov, between(1, 179));
    }
};

template <>
struct Schema<World> {
    static constexpr const char* kind = "world";
    template <class K>
    static void keys(K& key) {
        key("gravity", &World::gravity, atLeast(0));
        key("restitution", &World::restitution, between(0, 1));
        key("friction", &World::friction, atLeast(0));
        key("rolling", &World::rolling, atLeast(0));
        key("floor", &World::floor);
        key("ground", &World::ground);
    }
};

template <>
struct Schema<RenderSettings> {
    static constexpr const char* kind = "render";
    template <class K>
    static void keys(K& key) {
        key("steps", &RenderSettings::steps, between(1, 4096));
        key("epsilon", &RenderSettings::epsilon, above(0));
        key("shadows", &RenderSettings::shadows, between(0, 2));
        key("reflections", &RenderSettings::reflections, between(0, 8));
        key("fog", &RenderSettings::fog, atLeast(0));
        key("ao", &RenderSettings::ao);
        key("aa", &RenderSettings::aa, between(1, 4));
    }
};

template <>
struct Schema<Material> {
    static constexpr const char* kind = "material";
    template <class K>
    static void keys(K& key) {
        const Need<Material> required{true};
        key("name", &Material::name);
        key(
            "r", [](auto& m) -> auto& { return m.color.r; }, atLeast(0), required);
        key(
            "g", [](auto& m) -> auto& { return m.color.g; }, atLeast(0), required);
        key(
            "b", [](auto& m) -> auto& { return m.color.b; }, atLeast(0), required);
        key("Ka", &Material::Ka, atLeast(0));
        key("Kd", &Material::Kd, atLeast(0));
        key("Ks", &Material::Ks, atLeast(0));
        key("C", &Material::C, above(0));
        key("Kr", &Material::Kr, between(0, 1));
    }
};

template <>
struct Schema<Light> {
    static constexpr const char* kind = "light";
    template <class K>
    static void keys(K& key) {
        key("pos", &Light::vec, Rule{}, Need<Light>{false, &Light::directional, false});
        key("dir", &Light::vec, kNonZero, Need<Light>{false, &Light::directional, true});
        key("color", &Light::color, atLeast(0));
        key("intensity", &Light::intensity, atLeast(0));
    }
};

template <>
struct Schema<Object> {
    static constexpr const char* kind = "object";
    template <class K>
    static void keys(K& key) {
        const Need<Object> required{true};
        auto since = [](int version, bool (*written)(const Object&)) {
            return Need<Object>{false, nullptr, false, version, written};
        };
        key("type", &Object::type, Rule{}, required);
        key("name", &Object::name, Rule{}, since(2, hasName));
        key("material", &Object::material, atLeast(0));  // existence is checked at end of file
        key("pos", &Object::pos, Rule{}, required);
        key("radius", &Object::radius, above(0), since(1, usesRadius));
        key("size", &Object::size, above(0), since(1, usesSize));
        key("minor", &Object::minor, above(0), since(1, usesMinor));
        key("height", &Object::height, above(0), since(1, usesHeight));
        key("top", &Object::top, atLeast(0), since(3, usesTop));
        key("rot", &Object::rot, Rule{}, since(1, writesRot<Object>));
        key("orient", &Object::orient, Rule{}, since(2, writesOrient<Object>));
        key("mass", &Object::mass, atLeast(0), since(1, movesAlone));
        key("vel", &Object::vel, Rule{}, since(1, movesAlone));
        key("spin", &Object::spin, Rule{}, since(1, movesAlone));
        key("static", &Object::isStatic, Rule{}, since(1, movesAlone));
        key("op", &Object::op);
        key("blend", &Object::blend, atLeast(0));
        key("round", &Object::round, atLeast(0), since(3, isRounded));
        key("shell", &Object::shell, atLeast(0), since(3, isShelled));
        key("friction", &Object::friction, atLeast(0), since(2, hasFriction<Object>));
        key("restitution", &Object::restitution, between(0, 1),
            since(2, hasRestitution<Object>));
    }
};

// Motion keys (mass, vel, spin, static, friction, restitution) are the top level's: the parser
// refuses them on a member, and the writer leaves them out there. `in` is read and written by
// the parser and writer themselves: it names a group, which the records hold as an index.
template <>
struct Schema<Group> {
    static constexpr const char* kind = "group";
    template <class K>
    static void keys(K& key) {
        auto since3 = [](bool (*written)(const Group&)) {
            return Need<Group>{false, nullptr, false, 3, written};
        };
        key("name", &Group::name, Rule{}, Need<Group>{true, nullptr, false, 3});
        key("pos", &Group::pos, Rule{}, since3(nullptr));
        key("rot", &Group::rot, Rule{}, since3(isTurned));
        key("orient", &Group::orient, Rule{}, since3(writesOrient<Group>));
        key("op", &Group::op, Rule{}, since3(isCarving));
        key("blend", &Group::blend, atLeast(0), since3(isBlended));
        key("mass", &Group::mass, atLeast(0), since3(movesAlone));
        key("vel", &Group::vel, Rule{}, since3(movesAlone));
        key("spin", &Group::spin, Rule{}, since3(movesAlone));
        key("static", &Group::isStatic, Rule{}, since3(movesAlone));
        key("friction", &Group::friction, atLeast(0), since3(hasFriction<Group>));
        key("restitution", &Group::restitution, between(0, 1), since3(hasRestitution<Group>));
        key("mirror", &Group::mirror, Rule{}, since3(isMirrored));
        key("repeat", &Group::repeat, between(1, 64), since3(isRepeated));
        key("spacing", &Group::spacing, above(0), since3(hasSpacing));
    }
};

// The name the loader gives an unnamed material, and the saver writes for one.
inline std::string defaultMaterialName(size_t index) { return "material" + std::to_string(index); }

// One line of SceneComments as the file holds it, with its '\n': trailing blanks and CRs go,
// a line that is neither blank nor a comment becomes a comment ("# " before it), and a line is
// cut to kMaxLineBytes. The reader keeps what this gives; the writer passes whatever a program
// put in a comment through it, so a saved comment always reads back as the same line.
inline std::string commentLine(std::string_view line) {
    auto trimmed = [](std::string_view s) {
        size_t end = s.find_last_not_of(" \t\r");
        return end == std::string_view::npos ? std::string_view() : s.substr(0, end + 1);
    };
    std::string out(trimmed(line));
    size_t first = out.find_first_not_of(" \t");
    if (first != std::string::npos && out[first] != '#') out.insert(0, "# ");
    if (out.size() > size_t(kMaxLineBytes))
        out = std::string(trimmed(out.substr(0, kMaxLineBytes)));
    return out + '\n';
}

// Fills in the optional columns of a row, then calls fn(name, field, rule, need).
template <class R, class Fn>
struct KeyRow {
    Fn& fn;
    template <class Field>
    void operator()(const char* name, Field field, Rule rule = {}, Need<R> need = {}) {
        fn(name, field, rule, need);
    }
};

// Calls fn(name, field, rule, need) for every key of record R, in the order files are written.
template <class R, class Fn>
void forEachKey(Fn&& fn) {
    KeyRow<R, Fn> row{fn};
    Schema<R>::keys(row);
}

}  // namespace mb
