// clipboard.cpp — cutting a scene down to the selection, and adding one scene to another.
#include "marchbox/editor/clipboard.h"

#include "marchbox/editor/scene_tree.h"
#include "marchbox/scene/scene_io.h"

#include <algorithm>
#include <map>
#include <sstream>

namespace mb {

// Only the materials the objects use, in their order, the objects renumbered to match.
static void keepUsedMaterials(Scene& s) {
    std::map<int, int> to;
    for (const Object& o : s.objects) to.emplace(o.material, 0);
    std::vector<Material> used;
    for (auto& [from, index] : to) {
        index = int(used.size());
        used.push_back(s.materials[size_t(from)]);
    }
    s.materials = std::move(used);
    for (Object& o : s.objects) o.material = to[o.material];
}

std::string copyText(const Scene& s, const std::vector<Item>& items) {
    std::vector<Item> keep = roots(s, items);
    if (keep.empty()) return "";
    Scene part = s;
    std::string why;
    for (Item& it : keep) {  // a member comes out to the top level, where it stands
        Renumbering r;
        if (parentOf(part, it) >= 0 && moveItem(part, it, {-1, -1}, &r, &why))
            for (Item& other : keep) other = r(other);
    }
    std::vector<Item> rest;
    for (Item it : children(part, -1))
        if (std::find(keep.begin(), keep.end(), it) == keep.end()) rest.push_back(it);
    eraseItems(part, rest);
    keepUsedMaterials(part);
    part.lights.clear();
    part.keyframes.clear();
    part.comments = {};
    return formatScene(part);
}

// The text's materials as indices into s.materials, adding those s lacks.
static std::vector<int> mergeMaterials(Scene& s, const std::vector<Material>& from) {
    std::vector<int> index;
    for (const Material& m : from) {
        auto same = std::find_if(s.materials.begin(), s.materials.end(),
                                 [&](const Material& own) { return own.name == m.name; });
        index.push_back(int(same - s.materials.begin()));
        if (same == s.materials.end()) s.materials.push_back(m);
    }
    return index;
}

// The scene's material records, as its file writes them.
static std::string materialRecords(const Scene& s) {
    Scene own;
    own.materials = s.materials;
    std::istringstream file(formatScene(own));
    std::string records;
    for (std::string line; std::getline(file, line);)
        if (line.compare(0, 9, "material ") == 0) records += line + "\n";
    return records;
}

static bool holdsMaterials(const std::string& text) {
    return text.compare(0, 9, "material ") == 0 || text.find("\nmaterial ") != std::string::npos;
}

// Records without the file's header read as the current version; where they bring no
// materials, their material indices are the scene's own, whose materials go first.
static bool readText(const Scene& s, const std::string& text, Scene* in, std::string* why) {
    std::string head;
    if (text.compare(0, 5, "scene") != 0) head = "scene version:3\n";
    if (!head.empty() && !holdsMaterials(text)) head += materialRecords(s);
    std::vector<SceneError> errors;
    if (parseScene(head + text, in, &errors)) return true;
    const int line = errors.front().line - int(std::count(head.begin(), head.end(), '\n'));
    *why = "the clipboard holds no scene text (line " + std::to_string(line) + ": " +
           errors.front().message + ")";
    return false;
}

// Whether `in` fits into `s`: its objects, groups and the materials `s` lacks.
static bool roomFor(const Scene& s, const Scene& in, std::string* why) {
    const int materials = int(std::count_if(in.materials.begin(), in.materials.end(),
                                            [&](const Material& m) {
                                                return !nameUsed(s, ItemKind::Material, m.name);
                                            }));
    return hasRoom(s, ItemKind::Object, int(in.objects.size()), why) &&
           hasRoom(s, ItemKind::Group, int(in.groups.size()), why) &&
           hasRoom(s, ItemKind::Material, materials, why);
}

bool pasteText(Scene& s, const std::string& text, std::vector<Item>* pasted, std::string* why) {
    Scene in;
    if (!readText(s, text, &in, why)) return false;
    if (in.objects.empty()) return *why = "the clipboard's scene text holds no objects", false;
    if (!roomFor(s, in, why)) return false;
    // After everything, in its own tree order, its indices moved on: the tree order holds.
    const int objects = int(s.objects.size()), groups = int(s.groups.size());
    const std::vector<int> material = mergeMaterials(s, in.materials);
    for (Object o : in.objects) {
        o.material = material[size_t(o.material)];
        o.group += o.group >= 0 ? groups : 0;
        o.name = unusedName(s, ItemKind::Object, o.name);
        s.objects.push_back(std::move(o));
    }
    for (Group g : in.groups) {
        g.parent += g.parent >= 0 ? groups : 0;
        g.first += objects;
        g.name = unusedName(s, ItemKind::Group, g.name);
        s.groups.push_back(std::move(g));
    }
    pasted->clear();
    for (Item it : children(s, -1))
        if (it.index >= (it.kind == ItemKind::Object ? objects : groups)) pasted->push_back(it);
    return true;
}

}  // namespace mb
