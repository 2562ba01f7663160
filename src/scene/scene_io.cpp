// scene_io.cpp — canonical scene text (formatScene, formatFloat) and Scene equality.
// A record's comment lines are written just above it, the file's last ones at the end.
// Both walk the key tables of scene_schema.h; parsing is in scene_parse.cpp, files in
// scene_file.cpp.
#include "marchbox/scene/scene_io.h"

#include "scene_schema.h"

#include <algorithm>
#include <charconv>
#include <functional>

namespace mb {

std::string formatFloat(float v) {
    // Shortest round-trip form, e.g. "0.1", "1e-05", "-0"; every output matches the Number
    // syntax for finite v. 64 bytes holds any float.
    char buf[64];
    auto res = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, res.ptr);
}

namespace {

std::string formatValue(float v) { return formatFloat(v); }
std::string formatValue(int v) { return std::to_string(v); }
std::string formatValue(bool v) { return v ? "1" : "0"; }
std::string formatValue(const std::string& v) { return v; }
std::string formatValue(ShapeType v) { return shapeTypeName(v); }
std::string formatValue(CsgOp v) { return csgOpName(v); }
std::string formatValue(const glm::vec3& v) {
    return formatFloat(v.x) + ',' + formatFloat(v.y) + ',' + formatFloat(v.z);
}
std::string formatValue(const glm::quat& q) {
    return formatFloat(q.w) + ',' + formatFloat(q.x) + ',' + formatFloat(q.y) + ',' +
           formatFloat(q.z);
}
std::string formatValue(const glm::ivec3& v) {
    return std::to_string(v.x) + ',' + std::to_string(v.y) + ',' + std::to_string(v.z);
}
std::string formatValue(const glm::bvec3& v) {
    return std::string(v.x ? "x" : "") + (v.y ? "y" : "") + (v.z ? "z" : "");
}
template <class T>
std::string formatValue(const std::optional<T>& v) {
    return formatValue(*v);
}  // written: set

// Comment lines as they were read; anything else a program put there made one (commentLine).
void writeComment(std::string& out, std::string_view text) {
    for (size_t start = 0; start < text.size();) {
        size_t end = std::min(text.find('\n', start), text.size());
        out += commentLine(text.substr(start, end - start));
        start = end + 1;
    }
}

// `in`: the name of the group that holds the record, if any (not in the key tables: the record
// holds the group's index).
template <class R>
void writeRecord(std::string& out, const R& rec, std::string_view comment = {},
                 std::string_view in = {}) {
    writeComment(out, comment);
    out += Schema<R>::kind;
    if (!in.empty()) out += " in:" + std::string(in);
    forEachKey<R>([&](const char* name, auto field, Rule, Need<R> need) {
        if (need.pick && rec.*need.pick != need.when) return;  // the other spelling is written
        if (need.written && !need.written(rec)) return;        // absent: the default applies
        out += ' ';
        out += name;
        out += ':';
        out += formatValue(std::invoke(field, rec));
    });
    out += '\n';
}

// A key that neither record writes (a box's radius, a member's mass) means nothing to either.
template <class R>
bool sameRecord(const R& a, const R& b) {
    bool same = true;
    forEachKey<R>([&](const char*, auto field, Rule, Need<R> need) {
        if (need.written && !need.written(a) && !need.written(b)) return;
        same = same && std::invoke(field, a) == std::invoke(field, b);
        if (need.pick) same = same && a.*need.pick == b.*need.pick;
    });
    return same;
}

template <class R>
bool sameList(const std::vector<R>& a, const std::vector<R>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const R& x, const R& y) {
        return sameRecord(x, y) && x.comment == y.comment;
    });
}

// Which group holds each object and group, and where each group stands.
bool sameTree(const Scene& a, const Scene& b) {
    auto objectGroups = [](const Scene& s) {
        std::vector<int> v;
        for (const Object& o : s.objects) v.push_back(o.group);
        for (const Group& g : s.groups) v.insert(v.end(), {g.parent, g.first});
        return v;
    };
    return objectGroups(a) == objectGroups(b);
}

}  // namespace

std::string formatScene(const Scene& scene) {
    const SceneComments& c = scene.comments;
    std::string out;
    writeRecord(out, SceneHeader{kSceneVersion});
    writeRecord(out, scene.camera, c.camera);
    std::vector<Keyframe> keys = scene.keyframes;
    std::stable_sort(keys.begin(), keys.end(),
                     [](const Keyframe& a, const Keyframe& b) { return a.t < b.t; });
    for (const Keyframe& k : keys) writeRecord(out, k, k.comment);
    writeRecord(out, scene.world, c.world);
    writeRecord(out, scene.render, c.render);
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        // An empty name would not read back as a Name; write the one the loader would give.
        Material m = scene.materials[i];
        if (m.name.empty()) m.name = defaultMaterialName(i);
        writeRecord(out, m, m.comment);
    }
    for (const Light& l : scene.lights) writeRecord(out, l, l.comment);
    auto parentName = [&](int g) { return g < 0 ? std::string() : scene.groups[size_t(g)].name; };
    size_t g = 0;  // groups stand before objects[first], in tree order
    for (size_t i = 0; i <= scene.objects.size(); ++i) {
        for (; g < scene.groups.size() && scene.groups[g].first <= int(i); ++g) {
            Group group = scene.groups[g];
            if (group.dynamic() && !group.orient) group.orient = group.orientation();
            writeRecord(out, group, group.comment, parentName(group.parent));
        }
        if (i == scene.objects.size()) break;
        Object o = scene.objects[i];
        if (o.dynamic() && !o.orient) o.orient = o.orientation();  // a body's turn, exactly
        writeRecord(out, o, o.comment, parentName(o.group));
    }
    writeComment(out, c.end);
    return out;
}

// Compares every key of every record (the key tables list every field), floats exactly, and
// the comments as text.
bool operator==(const Scene& a, const Scene& b) {
    return sameRecord(a.camera, b.camera) && sameRecord(a.world, b.world) &&
           sameRecord(a.render, b.render) && sameList(a.materials, b.materials) &&
           sameList(a.lights, b.lights) && sameList(a.objects, b.objects) &&
           sameList(a.groups, b.groups) && sameTree(a, b) &&
           sameList(a.keyframes, b.keyframes) && a.comments == b.comments;
}

}  // namespace mb
