// scene_parse.cpp — scene text to Scene (parseScene), as docs/scene-format.md describes it.
//
// A line is split at blanks by hand; std::regex then checks only single tokens (a key:value
// field, a number, a vector, a name). libstdc++'s regex recurses once per character, so the
// line length is checked before any regex runs: no token is longer than kMaxLineBytes.
//
// Comment and blank lines are gathered until the next record, which keeps them (SceneComments);
// the ones after the last record are the file's end.
#include "marchbox/scene/scene_io.h"

#include "marchbox/scene/printable.h"
#include "marchbox/scene/sdf.h"
#include "marchbox/scene/shapes.h"

#include "scene_schema.h"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <regex>
#include <type_traits>
#include <vector>

namespace mb {
namespace {

constexpr size_t kMaxErrors = 100;  // then parsing stops: plenty to fix, and bounded memory
constexpr size_t kMaxQuote = 40;    // quoted tokens are cut here so a message stays one line

// What a bad value should have been ("a number"), or nullptr when the value was read.
using Expect = const char*;

struct Syntax {
    static constexpr const char* kNumber =
        R"([-+]?(?:[0-9]+(?:\.[0-9]+)?|\.[0-9]+)(?:[eE][-+]?[0-9]+)?)";
    std::regex field{R"(([A-Za-z0-9_]+):(.*))"};
    std::regex number{kNumber};
    std::regex vector{std::string("(") + kNumber + "),(" + kNumber + "),(" + kNumber + ")"};
    std::regex quaternion{std::string("(") + kNumber + "),(" + kNumber + "),(" + kNumber + "),(" +
                          kNumber + ")"};
    std::regex name{"[A-Za-z0-9_.-]+"};
};

const Syntax& syntax() {
    static const Syntax s;
    return s;
}

bool matches(std::string_view s, const std::regex& re, std::cmatch* m = nullptr) {
    std::cmatch unused;
    return std::regex_match(s.data(), s.data() + s.size(), m ? *m : unused, re);
}

std::string_view view(const std::csub_match& m) { return {m.first, size_t(m.length())}; }

// Control bytes (a lone CR, ESC, NUL) are shown as '?': echoed raw they would rewrite the
// terminal the message is printed on. A cut backs off to a whole UTF-8 character.
std::string quote(std::string_view s) {
    size_t n = s.size();
    if (n > kMaxQuote)
        for (n = kMaxQuote; n > 0 && (s[n] & 0xC0) == 0x80;) --n;
    return "'" + printable(s.substr(0, n)) + (n < s.size() ? "...'" : "'");
}

// from_chars reports underflow and overflow alike. long double (to 1e±4932) holds any mantissa
// that fits in a line, so when even it is out of range only the exponent's sign can tell.
bool belowOne(std::string_view digits) {
    long double x = 0;
    auto res = std::from_chars(digits.data(), digits.data() + digits.size(), x);
    if (res.ec == std::errc()) return std::fabs(x) < 1;
    size_t e = digits.find_first_of("eE");
    return e != std::string_view::npos && digits[e + 1] == '-';
}

// Reads a Number into a float or double. An underflow reads as a signed zero, the nearest
// value; an overflow is an error. from_chars takes no leading '+', so it is skipped.
template <class T>
Expect readNumber(std::string_view s, T& v) {
    if (!matches(s, syntax().number)) return "a number";
    std::string_view digits = s[0] == '+' ? s.substr(1) : s;
    auto res = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (res.ec == std::errc()) return nullptr;
    if (!belowOne(digits)) return "a number within float range";
    v = s[0] == '-' ? -T(0) : T(0);
    return nullptr;
}

Expect readValue(std::string_view s, float& v) { return readNumber(s, v); }

// Whole numbers use the Number syntax, so "256.0" and "2.56e2" read as 256; "2.5" does not.
// Read as double so a fraction too small for a float (4096.0001) is still seen.
Expect readValue(std::string_view s, int& v) {
    double d = 0;
    if (readNumber(s, d) || d != std::floor(d)) return "a whole number";
    if (std::fabs(d) > INT_MAX) return "a whole number within ±2147483647";
    v = int(d);
    return nullptr;
}

Expect readValue(std::string_view s, bool& v) {
    if (s != "0" && s != "1") return "0 or 1";
    v = s == "1";
    return nullptr;
}

Expect readValue(std::string_view s, std::string& v) {
    if (!matches(s, syntax().name)) return "a name of letters, digits, '_', '.' or '-'";
    v = std::string(s);
    return nullptr;
}

Expect readValue(std::string_view s, glm::vec3& v) {
    std::cmatch m;
    if (!matches(s, syntax().vector, &m)) return "a vector x,y,z";
    for (int i = 0; i < 3; ++i)
        if (readNumber(view(m[i + 1]), v[i])) return "a vector of numbers within float range";
    return nullptr;
}

// w,x,y,z, of length within 1e-3 of 1 (typed by hand, or from a save), then normalised.
Expect readValue(std::string_view s, glm::quat& q) {
    std::cmatch m;
    if (!matches(s, syntax().quaternion, &m)) return "a quaternion w,x,y,z";
    float c[4];
    for (int i = 0; i < 4; ++i)
        if (readNumber(view(m[i + 1]), c[i])) return "a quaternion of numbers within float range";
    const glm::quat read(c[0], c[1], c[2], c[3]);
    if (std::fabs(glm::length(read) - 1.0f) > 1e-3f)
        return "a unit quaternion (length within 1e-3 of 1)";
    // Normalised only where it is off by more than rounding: a saved unit quaternion must read
    // back to the same floats, and normalize() is not exact twice over.
    q = std::fabs(glm::length(read) - 1.0f) > 1e-6f ? glm::normalize(read) : read;
    return nullptr;
}

template <class T>
Expect readValue(std::string_view s, std::optional<T>& v) {
    T read{};
    if (Expect e = readValue(s, read)) return e;
    v = read;
    return nullptr;
}

// "a, b or c".
std::string listed(const std::vector<std::string>& names) {
    std::string s = names.front();
    for (size_t i = 1; i < names.size(); ++i)
        s += (i + 1 < names.size() ? ", " : " or ") + names[i];
    return s;
}

// The type's names, from the table of shapes: "sphere, box, ... or 0 to 6".
std::string typeChoices() {
    std::vector<std::string> names;
    for (const ShapeRow& row : kShapes) names.push_back(row.name);
    names.push_back("0 to " + std::to_string(kShapeTypeCount - 1));
    return listed(names);
}

// The shapes `round` applies to: "box, cylinder or cone".
std::string edgedShapes() {
    std::vector<std::string> names;
    for (const ShapeRow& row : kShapes)
        if (row.edges) names.push_back(row.name);
    return listed(names);
}

Expect readValue(std::string_view s, ShapeType& v) {
    static const std::string choices = typeChoices();
    int n = 0;
    while (n < kShapeTypeCount && s != shapeTypeName(ShapeType(n))) ++n;
    bool named = n < kShapeTypeCount;
    if (!named && (readValue(s, n) || n < 0 || n >= kShapeTypeCount)) return choices.c_str();
    v = ShapeType(n);
    return nullptr;
}

// Mirror planes: any of x, y, z, each at most once.
Expect readValue(std::string_view s, glm::bvec3& v) {
    v = glm::bvec3(false);
    for (char c : s) {
        int axis = c == 'x' ? 0 : c == 'y' ? 1 : c == 'z' ? 2 : -1;
        if (axis < 0 || v[axis]) return "letters x, y, z, each at most once";
        v[axis] = true;
    }
    return s.empty() ? "letters x, y, z, each at most once" : nullptr;
}

Expect readValue(std::string_view s, glm::ivec3& v) {
    std::cmatch m;
    if (!matches(s, syntax().vector, &m)) return "three whole numbers x,y,z";
    for (int i = 0; i < 3; ++i)
        if (readValue(view(m[i + 1]), v[i])) return "three whole numbers x,y,z";
    return nullptr;
}

Expect readValue(std::string_view s, CsgOp& v) {
    int n = 0;
    while (n < kCsgOpCount && s != csgOpName(CsgOp(n))) ++n;
    if (n == kCsgOpCount) return "union, subtract or intersect";
    v = CsgOp(n);
    return nullptr;
}

bool obeys(double v, const Rule& r) { return (r.above ? v > r.lo : v >= r.lo) && v <= r.hi; }
bool obeys(float v, const Rule& r) { return obeys(double(v), r); }
bool obeys(int v, const Rule& r) { return obeys(double(v), r); }
bool obeys(const glm::vec3& v, const Rule& r) {
    return obeys(v.x, r) && obeys(v.y, r) && obeys(v.z, r) && !(r.nonZero && v == glm::vec3(0));
}
bool obeys(const glm::ivec3& v, const Rule& r) { return obeys(glm::vec3(v), r); }
template <class T>
bool obeys(const T&, const Rule&) {
    return true;
}  // flags, names and enums have no range
bool obeys(const std::optional<float>& v, const Rule& r) { return !v || obeys(*v, r); }

// The text after "must be", e.g. "> 0", "1 to 179".
std::string describe(const Rule& r) {
    if (r.nonZero) return "non-zero";
    std::string lo = formatFloat(float(r.lo));
    if (r.lo == r.hi) return lo;
    if (std::isinf(r.hi)) return (r.above ? "> " : ">= ") + lo;
    return lo + " to " + formatFloat(float(r.hi));
}

std::vector<std::string_view> splitAtBlanks(std::string_view line) {
    std::vector<std::string_view> tokens;
    for (size_t i = line.find_first_not_of(" \t"); i != std::string_view::npos;
         i = line.find_first_not_of(" \t", i)) {
        size_t end = std::min(line.find_first_of(" \t", i), line.size());
        tokens.push_back(line.substr(i, end - i));
        i = end;
    }
    return tokens;
}

bool startsWith(std::string_view s, std::string_view prefix) {
    return s.substr(0, prefix.size()) == prefix;
}

template <class R>
bool is(std::string_view kind) {
    return kind == Schema<R>::kind;
}

struct Field {
    std::string_view key, value;
    bool used = false;  // matched a key of the record; the rest are unknown keys
};
using Fields = std::vector<Field>;

class Parser {
public:
    void run(std::string_view text);

    Scene scene;
    std::vector<SceneError> errors;

private:
    void parseLine(std::string_view text);
    bool readFields(const std::vector<std::string_view>& tokens, size_t first, Fields* fields);
    void record(std::string_view kind, Fields& fields, std::string comment);
    void header(Fields& fields);
    void object(Fields& fields, std::string comment);
    void group(Fields& fields, std::string comment);
    int parentOf(Fields& fields, const char* kind);
    void checkShape(const Object& o);
    void keyframe(Fields& fields, std::string comment);
    template <class R>
    void single(Fields& fields, R& rec);
    template <class R>
    bool append(Fields& fields, std::vector<R>& list, int max, std::string comment);
    template <class R>
    void readRecord(Fields& fields, R& rec);
    template <class T>
    void readKey(const char* key, std::string_view text, T& v, const Rule& r);
    const Field* take(Fields& fields, const char* key);
    void finish();
    void finishKeyframes();
    void finishTree();
    void error(std::string message) { errorAt(line_, std::move(message)); }
    void errorAt(int line, std::string message);

    int line_ = 0;
    int version_ = 1;                         // the `scene` record's, which comes first
    int records_ = 0;                         // records so far, to check `scene` comes first
    std::map<std::string_view, int> counts_;  // records of each kind, for the limits
    std::vector<int> objectLines_;            // where each object is, for its material error
    std::vector<int> keyframeLines_;          // where each keyframe is, for a repeated t
    std::map<std::string, int> groupNames_;   // each group's index, by name
    // Objects and groups in file order: (true, group index) or (false, object index).
    std::vector<std::pair<bool, int>> tree_;
    std::string comment_;  // comment and blank lines since the last record
    bool stopped_ = false;
};

void Parser::errorAt(int line, std::string message) {
    if (stopped_) return;
    stopped_ = errors.size() == kMaxErrors;
    errors.push_back({line, stopped_ ? "too many errors, stopped reading" : std::move(message)});
}

void Parser::run(std::string_view text) {
    if (startsWith(text, "\xEF\xBB\xBF")) text.remove_prefix(3);  // a BOM, as some editors write
    for (size_t start = 0; start < text.size() && !stopped_;) {
        size_t end = std::min(text.find('\n', start), text.size());
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        ++line_;
        parseLine(line);
        start = end + 1;
    }
    if (!stopped_) finish();
    scene.comments.end = std::move(comment_);
}

void Parser::parseLine(std::string_view text) {
    if (text.size() > size_t(kMaxLineBytes))
        return error("line longer than " + std::to_string(kMaxLineBytes) + " bytes");
    std::vector<std::string_view> tokens = splitAtBlanks(text);
    if (tokens.empty() || tokens[0][0] == '#') {
        comment_ += commentLine(text);
        return;
    }
    if (tokens[0] == "-" && tokens.size() > 1) tokens.erase(tokens.begin());  // original's prefix
    // The original program's lines have no kind word: "r:" starts a material, "type:" an object.
    std::string_view kind = tokens[0];
    size_t first = 1;
    if (startsWith(kind, "r:") || startsWith(kind, "type:")) {
        kind = kind[0] == 'r' ? Schema<Material>::kind : Schema<Object>::kind;
        first = 0;
    }
    ++records_;
    // A record with a malformed field is not read: what else it lacks would only be a guess.
    Fields fields;
    std::string comment = std::move(comment_);
    comment_.clear();
    if (readFields(tokens, first, &fields)) record(kind, fields, std::move(comment));
}

bool Parser::readFields(const std::vector<std::string_view>& tokens, size_t first, Fields* fields) {
    bool ok = true;
    for (size_t i = first; i < tokens.size(); ++i) {
        std::cmatch m;
        if (matches(tokens[i], syntax().field, &m)) {
            fields->push_back({view(m[1]), view(m[2])});
        } else {
            error("expected key:value, got " + quote(tokens[i]));
            ok = false;
        }
    }
    return ok;
}

void Parser::record(std::string_view kind, Fields& fields, std::string comment) {
    SceneComments& c = scene.comments;
    if (is<SceneHeader>(kind)) {
        header(fields);
        comment_ =
            std::move(comment);  // a save starts with `scene version:1`: the next record keeps it
    } else if (is<Camera>(kind)) {
        single(fields, scene.camera);
        c.camera = std::move(comment);
    } else if (is<World>(kind)) {
        single(fields, scene.world);
        c.world = std::move(comment);
    } else if (is<RenderSettings>(kind)) {
        single(fields, scene.render);
        c.render = std::move(comment);
    } else if (is<Material>(kind)) {
        append(fields, scene.materials, kMaxMaterials, std::move(comment));
    } else if (is<Light>(kind)) {
        append(fields, scene.lights, kMaxLights, std::move(comment));
    } else if (is<Object>(kind)) {
        object(fields, std::move(comment));
    } else if (is<Keyframe>(kind)) {
        keyframe(fields, std::move(comment));
    } else if (is<Group>(kind)) {
        group(fields, std::move(comment));
    } else {
        error("unknown record kind " + quote(kind));
    }
}

void Parser::header(Fields& fields) {
    if (records_ > 1) error("'scene' must be the first record");
    SceneHeader h;
    readRecord(fields, h);
    version_ = h.version;
}

bool has(const Fields& fields, std::string_view key) {
    return std::any_of(fields.begin(), fields.end(), [&](const Field& f) { return f.key == key; });
}

// The group that `in` names, -1 for none; a member may not hold a motion key.
int Parser::parentOf(Fields& fields, const char* kind) {
    if (has(fields, "rot") && has(fields, "orient"))
        error(std::string(kind == std::string_view("object") ? "an " : "a ") + kind +
              " holds 'rot' or 'orient', not both");
    const Field* in = take(fields, "in");
    if (!in) return -1;
    if (version_ < 3) return error("'in' needs scene version:3"), -1;
    auto found = groupNames_.find(std::string(in->value));
    if (found == groupNames_.end())
        return error("'in' names no group defined above: " + quote(in->value)), -1;
    for (const char* key : {"mass", "vel", "spin", "static", "friction", "restitution"})
        if (has(fields, key))
            error(quote(key) + " on a member: it moves with its group, whose top level has it");
    return found->second;
}

void Parser::object(Fields& fields, std::string comment) {
    const int parent = parentOf(fields, "object");
    if (!append(fields, scene.objects, kMaxObjects, std::move(comment))) return;
    objectLines_.push_back(line_);
    Object& o = scene.objects.back();
    o.group = parent;
    if (version_ < shapeRow(o.type).since)
        error(quote(shapeTypeName(o.type)) +
              " needs scene version:" + std::to_string(shapeRow(o.type).since));
    checkShape(o);
    tree_.push_back({false, int(scene.objects.size()) - 1});
}

// "a sphere", "an ellipsoid".
static std::string withArticle(std::string_view noun) {
    const bool vowel =
        !noun.empty() && std::string_view("aeiou").find(noun[0]) != std::string_view::npos;
    return (vowel ? "an " : "a ") + std::string(noun);
}

void Parser::checkShape(const Object& o) {
    const bool edged = hasEdges(o.type);
    if (o.round > 0.0f && !edged)
        error("'round' is for a " + edgedShapes() + ", not " + withArticle(shapeTypeName(o.type)));
    else if (o.round > 0.0f && o.round >= halfThinnest(o))
        error("'round' must be less than " + formatFloat(halfThinnest(o)) +
              ", half the shape's smallest extent");
    if (o.shell > 0.0f && o.shell >= halfThinnest(o))
        error("'shell' must be less than " + formatFloat(halfThinnest(o)) +
              ", half the shape's smallest extent");
    if (reads(o.type, kTopKey) && o.top >= o.radius)
        error("'top' must be less than 'radius' (" + formatFloat(o.radius) + ")");
}

void Parser::group(Fields& fields, std::string comment) {
    if (version_ < 3) return error("a 'group' record needs scene version:3");
    const int parent = parentOf(fields, "group");
    if (parent >= 0 && groupDepth(scene, parent) >= kMaxGroupDepth)
        error("groups nested more than " + std::to_string(kMaxGroupDepth) + " deep");
    if (!append(fields, scene.groups, kMaxGroups, std::move(comment))) return;
    Group& g = scene.groups.back();
    g.parent = parent;
    const int copies = g.repeat.x * g.repeat.y * g.repeat.z;
    if (copies > kMaxRepeatCopies)
        error("'repeat' makes " + std::to_string(copies) + " copies, more than " +
              std::to_string(kMaxRepeatCopies));
    const int index = int(scene.groups.size()) - 1;
    if (!g.name.empty() && !groupNames_.emplace(g.name, index).second)
        error("a second group named " + quote(g.name));
    tree_.push_back({true, index});
}

// The keys a keyframe leaves out come from the camera record, which may follow it: until the
// end of the file they are NaN, which no file can hold.
void Parser::keyframe(Fields& fields, std::string comment) {
    if (version_ < 2) return error("a 'keyframe' record needs scene version:2");
    Keyframe k;
    constexpr float kUnset = std::numeric_limits<float>::quiet_NaN();
    k.pos = k.target = glm::vec3(kUnset);
    k.fov = kUnset;
    readRecord(fields, k);
    k.comment = std::move(comment);
    scene.keyframes.push_back(std::move(k));
    keyframeLines_.push_back(line_);
}

template <class R>
void Parser::single(Fields& fields, R& rec) {
    if (++counts_[Schema<R>::kind] > 1) error(std::string("second ") + Schema<R>::kind + " record");
    readRecord(fields, rec);
}

// Records past the limit are counted, reported once and not read: the file is already invalid.
template <class R>
bool Parser::append(Fields& fields, std::vector<R>& list, int max, std::string comment) {
    int n = ++counts_[Schema<R>::kind];
    if (n == max + 1) error("more than " + std::to_string(max) + " " + Schema<R>::kind + "s");
    if (n > max) return false;
    R rec;
    readRecord(fields, rec);
    rec.comment = std::move(comment);
    list.push_back(std::move(rec));
    return true;
}

template <class R>
void Parser::readRecord(Fields& fields, R& rec) {
    std::string picks;  // the alternative keys, e.g. "'pos' or 'dir'"
    int picked = 0;
    forEachKey<R>([&](const char* key, auto field, const Rule& rule, const Need<R>& need) {
        const Field* f = take(fields, key);
        if (need.pick) picks += (picks.empty() ? "'" : " or '") + std::string(key) + "'";
        if (need.pick && f) {
            ++picked;
            rec.*need.pick = need.when;
        }
        if (f && version_ < need.since)
            error(quote(key) + " needs scene version:" + std::to_string(need.since));
        if (f) readKey(key, f->value, std::invoke(field, rec), rule);
        if (!f && need.required) error(std::string("missing required key '") + key + "'");
    });
    if (!picks.empty() && picked != 1)
        error(std::string(Schema<R>::kind) + " needs exactly one of " + picks);
    for (const Field& f : fields)
        if (!f.used) error("unknown key " + quote(f.key) + " in " + Schema<R>::kind);
}

// The first field named `key`, marking every such field used; a second one is an error.
const Field* Parser::take(Fields& fields, const char* key) {
    const Field* first = nullptr;
    int n = 0;
    for (Field& f : fields) {
        if (f.key != key) continue;
        f.used = true;
        if (n++ == 0) first = &f;
    }
    if (n > 1) error("repeated key " + quote(key));
    return first;
}

template <class T>
void Parser::readKey(const char* key, std::string_view text, T& v, const Rule& rule) {
    if (Expect e = readValue(text, v))
        return error(quote(key) + " must be " + e + ", got " + quote(text));
    if (obeys(v, rule)) return;
    // A positive number too small for a float reads as zero: say so, or "> 0" makes no sense.
    const bool underflowed = std::is_same_v<T, float> && v == T{} &&
                             text.find_first_of("123456789") < text.find_first_of("eE");
    error(quote(key) + " must be " + describe(rule) +
          (underflowed ? ", and " + quote(text) + " is too small for a float: it reads as 0" : ""));
}

// A body's turn is its exact orient (a save writes it), and rot then only shows it in degrees,
// as the file wrote them where it did (anglesShowing): so a file read, saved and read again
// gives the same scene whichever of the two it held.
template <class R>
void exactTurn(R& o) {
    if (o.dynamic() && !o.orient) o.orient = glm::quat_cast(rotationFromEuler(o.rot));
    if (o.orient) o.rot = anglesShowing(*o.orient, o.rot);
}

// Checks that need the whole file: material indices, names for unnamed materials, keyframes'
// defaults and order; and version 1's meaning, where only spheres moved.
void Parser::finish() {
    for (Object& o : scene.objects) {
        if (version_ < 2 && o.type != ShapeType::Sphere && o.dynamic()) o.isStatic = true;
        exactTurn(o);
    }
    for (Group& g : scene.groups) exactTurn(g);
    finishKeyframes();
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        int m = scene.objects[i].material;
        if (m >= int(scene.materials.size()))
            errorAt(objectLines_[i], "material " + std::to_string(m) + " does not exist");
    }
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i].name.empty()) scene.materials[i].name = defaultMaterialName(i);
    finishTree();
}

// Puts objects and groups in tree order: each group followed at once by its members, in file
// order, recursively; the top level keeps its file order.
void Parser::finishTree() {
    if (scene.groups.empty()) return;
    std::vector<std::vector<std::pair<bool, int>>> members(scene.groups.size() + 1);
    for (auto [isGroup, i] : tree_) {
        const int parent =
            isGroup ? scene.groups[size_t(i)].parent : scene.objects[size_t(i)].group;
        members[size_t(parent + 1)].push_back({isGroup, i});
    }
    Scene& s = scene;
    std::vector<Object> objects;
    std::vector<Group> groups;
    std::vector<int> newIndex(s.groups.size());
    std::function<void(int, int)> emit = [&](int parent, int newParent) {
        for (auto [isGroup, i] : members[size_t(parent + 1)]) {
            if (!isGroup) {
                objects.push_back(std::move(s.objects[size_t(i)]));
                objects.back().group = newParent;
                continue;
            }
            newIndex[size_t(i)] = int(groups.size());
            groups.push_back(std::move(s.groups[size_t(i)]));
            groups.back().parent = newParent;
            groups.back().first = int(objects.size());
            emit(i, newIndex[size_t(i)]);
        }
    };
    emit(-1, -1);
    s.objects = std::move(objects);
    s.groups = std::move(groups);
}

void Parser::finishKeyframes() {
    for (Keyframe& k : scene.keyframes) {
        for (int i = 0; i < 3; ++i) {
            if (std::isnan(k.pos[i])) k.pos[i] = scene.camera.pos[i];
            if (std::isnan(k.target[i])) k.target[i] = scene.camera.target[i];
        }
        if (std::isnan(k.fov)) k.fov = scene.camera.fov;
    }
    std::vector<size_t> order(scene.keyframes.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return scene.keyframes[a].t < scene.keyframes[b].t;
    });
    std::vector<Keyframe> sorted;
    for (size_t i = 0; i < order.size(); ++i) {
        if (i > 0 && scene.keyframes[order[i]].t == scene.keyframes[order[i - 1]].t)
            errorAt(keyframeLines_[std::max(order[i], order[i - 1])],
                    "a second keyframe at t " + formatFloat(scene.keyframes[order[i]].t));
        sorted.push_back(scene.keyframes[order[i]]);
    }
    scene.keyframes = std::move(sorted);
}

}  // namespace

bool parseScene(std::string_view text, Scene* out, std::vector<SceneError>* errors) {
    Parser p;
    p.run(text);
    std::stable_sort(p.errors.begin(), p.errors.end(),
                     [](const SceneError& a, const SceneError& b) { return a.line < b.line; });
    bool ok = p.errors.empty();
    if (errors) *errors = std::move(p.errors);
    if (!ok) return false;
    if (out) *out = std::move(p.scene);
    return true;
}

}  // namespace mb
