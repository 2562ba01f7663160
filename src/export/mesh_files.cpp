// mesh_files.cpp — STL, OBJ + MTL and PLY, written into strings.
#include "mesh_files.h"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <glm/common.hpp>
#include <set>

namespace mb {

namespace {

// Little-endian on every machine Marchbox builds for (x86-64, AArch64): the bytes as they lie.
template <typename T>
void put(std::string& out, T value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    out.append(bytes, sizeof(T));
}

// The shortest text that reads back as the same float; −0 (a colour may be written so) as 0.
void putNumber(std::string& out, float v) {
    char text[32];
    auto end = std::to_chars(text, text + sizeof text, v + 0.0f).ptr;
    out.append(text, end);
}

void putVector(std::string& out, const char* key, glm::vec3 v) {
    out += key;
    for (int i = 0; i < 3; ++i) out += ' ', putNumber(out, v[i]);
    out += '\n';
}

}  // namespace

glm::vec3 materialColour(const Scene& scene, int m) {
    if (m < 0 || size_t(m) >= scene.materials.size()) return glm::vec3(0.8f);
    return glm::clamp(scene.materials[size_t(m)].color, 0.0f, 1.0f);
}

std::string stlBytes(const TriangleMesh& m) {
    std::string out;
    out.reserve(84 + 50 * m.triangles.size());
    std::string header = "binary STL written by marchbox export";
    header.resize(80, ' ');  // must not start with "solid": readers would take it for text
    out += header;
    put(out, uint32_t(m.triangles.size()));
    for (size_t t = 0; t < m.triangles.size(); ++t) {
        const glm::vec3 n = faceNormal(m, t);
        for (int i = 0; i < 3; ++i) put(out, n[i]);
        for (int c = 0; c < 3; ++c)
            for (int i = 0; i < 3; ++i) put(out, m.points[m.triangles[t][c]][i]);
        put(out, uint16_t(0));
    }
    return out;
}

std::vector<std::string> materialNames(const Scene& scene) {
    std::vector<std::string> names;
    std::set<std::string> taken;
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        std::string name = scene.materials[i].name;
        if (name.empty()) name = "material" + std::to_string(i);
        while (taken.count(name)) name += "_" + std::to_string(i);
        taken.insert(name);
        names.push_back(name);
    }
    return names;
}

std::string objBytes(const TriangleMesh& m, const std::vector<int>& materials, const Scene& scene,
                     const std::string& mtlFile) {
    std::string out;
    out.reserve(36 * m.points.size() + 30 * m.triangles.size());
    out += "# marchbox export: " + std::to_string(m.points.size()) + " vertices, " +
           std::to_string(m.triangles.size()) + " triangles, counter-clockwise from outside\n";
    out += "mtllib " + mtlFile + "\no solids\n";
    for (const glm::vec3& p : m.points) putVector(out, "v", p);
    const std::vector<std::string> names = materialNames(scene);
    // Faces grouped by material, each group in mesh order.
    std::vector<size_t> order(m.triangles.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    auto materialOf = [&](size_t t) { return std::max(materials[t], 0); };
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return materialOf(a) < materialOf(b); });
    int current = -1;
    for (size_t t : order) {
        if (materialOf(t) != current && size_t(materialOf(t)) < names.size()) {
            current = materialOf(t);
            out += "usemtl " + names[size_t(current)] + '\n';
        }
        out += 'f';
        for (int c = 0; c < 3; ++c) out += ' ' + std::to_string(m.triangles[t][c] + 1);
        out += '\n';
    }
    return out;
}

std::string mtlBytes(const Scene& scene) {
    std::string out = "# marchbox export: the scene's materials\n";
    const std::vector<std::string> names = materialNames(scene);
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& mat = scene.materials[i];
        out += "\nnewmtl " + names[i] + '\n';
        putVector(out, "Ka", mat.Ka * materialColour(scene, int(i)));
        putVector(out, "Kd", materialColour(scene, int(i)));
        putVector(out, "Ks", glm::vec3(std::min(mat.Ks, 1.0f)));
        out += "Ns ";
        putNumber(out, std::min(mat.C, 1000.0f));
        out += "\nd 1\nillum 2\n";
    }
    return out;
}

std::string plyBytes(const TriangleMesh& m, const std::vector<glm::vec3>& colours) {
    std::string out =
        "ply\nformat binary_little_endian 1.0\ncomment written by marchbox export\n"
        "element vertex " +
        std::to_string(m.points.size()) +
        "\nproperty float x\nproperty float y\nproperty float z\n"
        "property uchar red\nproperty uchar green\nproperty uchar blue\n"
        "element face " +
        std::to_string(m.triangles.size()) +
        "\nproperty list uchar uint vertex_indices\nend_header\n";
    out.reserve(out.size() + 15 * m.points.size() + 13 * m.triangles.size());
    for (size_t i = 0; i < m.points.size(); ++i) {
        for (int k = 0; k < 3; ++k) put(out, m.points[i][k]);
        const glm::vec3 c = glm::clamp(colours[i], 0.0f, 1.0f);
        for (int k = 0; k < 3; ++k) put(out, uint8_t(c[k] * 255.0f + 0.5f));
    }
    for (const glm::uvec3& t : m.triangles) {
        put(out, uint8_t(3));
        for (int k = 0; k < 3; ++k) put(out, uint32_t(t[k]));
    }
    return out;
}

}  // namespace mb
