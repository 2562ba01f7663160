// test_mesh_files.cpp — the file writers, read back field by field: binary STL, OBJ and MTL,
// binary PLY, and glb read back through TinyGLTF's loader.
#include "gltf_file.h"
#include "mesh_files.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <sstream>

using namespace mb;
using glm::vec3;

namespace {

// A tetrahedron wound outward, and a scene with three materials for it.
TriangleMesh tetrahedron() {
    TriangleMesh m;
    m.points = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1)};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
}

Scene threeMaterials() {
    Scene s;
    s.materials.resize(3);
    s.materials[0].name = "red";
    s.materials[0].color = vec3(0.9f, 0.15f, 0.1f);
    s.materials[0].C = 48;
    s.materials[1].name = "bright";
    s.materials[1].color = vec3(2.0f, 0.5f, -0.0f);  // over 1: clamped
    s.materials[2].name = "red";                     // a second "red"
    return s;
}

template <typename T>
T at(const std::string& bytes, size_t offset) {
    T v;
    std::memcpy(&v, bytes.data() + offset, sizeof(T));
    return v;
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

double linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

tinygltf::Model readGlb(const std::string& bytes) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    EXPECT_TRUE(loader.LoadBinaryFromMemory(&model, &err, &warn,
                                            reinterpret_cast<const unsigned char*>(bytes.data()),
                                            unsigned(bytes.size())))
        << err;
    return model;
}

}  // namespace

TEST(MeshFiles, StlHasItsCountNormalsAndCorners) {
    const TriangleMesh m = tetrahedron();
    const std::string stl = stlBytes(m);
    ASSERT_EQ(stl.size(), 84u + 50u * 4u);
    EXPECT_NE(stl.substr(0, 5), "solid");  // readers take a header starting so for text
    EXPECT_EQ(at<uint32_t>(stl, 80), 4u);
    for (size_t t = 0; t < 4; ++t) {
        const size_t base = 84 + 50 * t;
        for (int k = 0; k < 3; ++k)
            EXPECT_FLOAT_EQ(at<float>(stl, base + 4 * k), faceNormal(m, t)[k]);
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k)
                EXPECT_EQ(at<float>(stl, base + 12 + 12 * c + 4 * k),
                          m.points[m.triangles[t][c]][k]);
        EXPECT_EQ(at<uint16_t>(stl, base + 48), 0);
    }
    EXPECT_FLOAT_EQ(faceNormal(m, 3).x, 1.0f / std::sqrt(3.0f));  // outward, off the origin
}

TEST(MeshFiles, ObjGroupsFacesByMaterialWithOneBasedIndices) {
    const Scene s = threeMaterials();
    const std::string obj = objBytes(tetrahedron(), {1, 0, -1, 1}, s, "solids.mtl");
    const std::vector<std::string> l = lines(obj);
    EXPECT_EQ(l[1], "mtllib solids.mtl");
    std::vector<std::string> body(l.begin() + 3, l.end());
    const std::vector<std::string> want = {"v 0 0 0",       "v 1 0 0", "v 0 1 0", "v 0 0 1",
                                           "usemtl red",    "f 1 2 4", "f 1 4 3",  // 0, and -1 as 0
                                           "usemtl bright", "f 1 3 2", "f 2 3 4"};
    EXPECT_EQ(body, want);
}

TEST(MeshFiles, MtlNamesEachMaterialOnceWithItsColour) {
    const std::vector<std::string> l = lines(mtlBytes(threeMaterials()));
    std::vector<std::string> names, kd;
    for (const std::string& line : l) {
        if (line.rfind("newmtl ", 0) == 0) names.push_back(line.substr(7));
        if (line.rfind("Kd ", 0) == 0) kd.push_back(line);
    }
    EXPECT_EQ(names, (std::vector<std::string>{"red", "bright", "red_2"}));
    EXPECT_EQ(kd, (std::vector<std::string>{"Kd 0.9 0.15 0.1", "Kd 1 0.5 0", "Kd 1 1 1"}));
}

TEST(MeshFiles, PlyHeaderThenVerticesWithColoursThenFaces) {
    const TriangleMesh m = tetrahedron();
    const std::vector<vec3> colours = {vec3(1, 0, 0), vec3(0, 0.5f, 1), vec3(2, -1, 0.2f), vec3(0)};
    const std::string ply = plyBytes(m, colours);
    const std::string header =
        "ply\nformat binary_little_endian 1.0\ncomment written by marchbox export\n"
        "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
        "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face 4\n"
        "property list uchar uint vertex_indices\nend_header\n";
    ASSERT_EQ(ply.substr(0, header.size()), header);
    ASSERT_EQ(ply.size(), header.size() + 4 * 15 + 4 * 13);
    const uint8_t want[4][3] = {{255, 0, 0}, {0, 128, 255}, {255, 0, 51}, {0, 0, 0}};
    for (size_t i = 0; i < 4; ++i) {
        const size_t base = header.size() + 15 * i;
        for (int k = 0; k < 3; ++k) EXPECT_EQ(at<float>(ply, base + 4 * k), m.points[i][k]);
        for (int k = 0; k < 3; ++k) EXPECT_EQ(at<uint8_t>(ply, base + 12 + k), want[i][k]);
    }
    for (size_t t = 0; t < 4; ++t) {
        const size_t base = header.size() + 60 + 13 * t;
        EXPECT_EQ(at<uint8_t>(ply, base), 3);
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(at<uint32_t>(ply, base + 1 + 4 * k), m.triangles[t][k]);
    }
}

TEST(Gltf, StillMeshHasAPrimitivePerMaterialWithItsColour) {
    const Scene s = threeMaterials();
    GltfDocument doc;
    doc.scene = &s;
    doc.parts.push_back({"solids", tetrahedron(), {1, 0, 0, 1}, {}});
    const tinygltf::Model model = readGlb(glbBytes(doc));
    ASSERT_EQ(model.meshes.size(), 1u);
    ASSERT_EQ(model.meshes[0].primitives.size(), 2u);
    size_t indices = 0;
    for (const tinygltf::Primitive& p : model.meshes[0].primitives) {
        indices += model.accessors[size_t(p.indices)].count;
        const tinygltf::Accessor& pos = model.accessors[size_t(p.attributes.at("POSITION"))];
        EXPECT_EQ(pos.minValues, (std::vector<double>{0, 0, 0}));
        EXPECT_EQ(pos.count, 4u);  // each pair of faces here touches all four corners
    }
    EXPECT_EQ(indices, 12u);
    ASSERT_EQ(model.materials.size(), 2u);
    const tinygltf::Material* red = nullptr;
    for (const tinygltf::Material& m : model.materials)
        if (m.name == "red") red = &m;
    ASSERT_NE(red, nullptr);
    const std::vector<double>& base = red->pbrMetallicRoughness.baseColorFactor;
    EXPECT_NEAR(base[0], linear(0.9), 1e-6);
    EXPECT_NEAR(base[1], linear(0.15), 1e-6);
    EXPECT_NEAR(base[2], linear(0.1), 1e-6);
    EXPECT_EQ(red->pbrMetallicRoughness.metallicFactor, 0.0);
    EXPECT_NEAR(red->pbrMetallicRoughness.roughnessFactor, std::pow(2.0 / 50.0, 0.25), 1e-9);
    EXPECT_TRUE(model.animations.empty());
    EXPECT_TRUE(model.cameras.empty());
}

TEST(Gltf, AnimatedPartsCameraAndLights) {
    Scene s = threeMaterials();
    Light point;
    point.vec = vec3(0, 3, -4);  // 5 m from the solids' centre below
    point.color = vec3(0.5f, 1.0f, 0.25f);
    point.intensity = 2.0f;
    Light sun;
    sun.directional = true;
    sun.vec = vec3(0, -1, 0);
    s.lights = {point, sun};
    GltfDocument doc;
    doc.scene = &s;
    doc.solids.lo = vec3(-1), doc.solids.hi = vec3(1);
    doc.times = {0.5, 0.6, 0.7};
    doc.parts.push_back({"static solids", tetrahedron(), {0, 0, 0, 0}, {}});
    const glm::quat q = glm::angleAxis(0.3f, glm::normalize(vec3(1, 2, 3)));
    std::vector<Placement> poses = {{vec3(0, 1, 0), q}, {vec3(0, 2, 0), -q}, {vec3(0, 3, 0), q}};
    doc.parts.push_back({"ball", tetrahedron(), {1, 1, 1, 1}, poses});
    for (int k = 0; k < 3; ++k) {
        Camera c;
        c.pos = vec3(float(k), 2, -6);
        doc.cameras.push_back(c);
    }
    const tinygltf::Model model = readGlb(glbBytes(doc));
    ASSERT_EQ(model.nodes.size(), 5u);  // two parts, the camera, two lights
    EXPECT_EQ(model.nodes[1].name, "ball");
    EXPECT_EQ(model.nodes[1].translation, (std::vector<double>{0, 1, 0}));
    EXPECT_EQ(model.nodes[2].camera, 0);
    ASSERT_EQ(model.animations.size(), 1u);
    const tinygltf::Animation& a = model.animations[0];
    ASSERT_EQ(a.channels.size(), 4u);  // the ball's and the camera's translation and rotation
    for (const tinygltf::AnimationChannel& c : a.channels) {
        const tinygltf::AnimationSampler& sampler = a.samplers[size_t(c.sampler)];
        EXPECT_EQ(model.accessors[size_t(sampler.input)].count, 3u);
        EXPECT_EQ(model.accessors[size_t(sampler.output)].count, 3u);
        EXPECT_EQ(model.accessors[size_t(sampler.input)].maxValues, (std::vector<double>{0.7f}));
        if (c.target_node == 1 && c.target_path == "rotation") {
            // -q is q's turn; written with q's sign, so the keys interpolate the short way.
            const tinygltf::Accessor& out = model.accessors[size_t(sampler.output)];
            const tinygltf::BufferView& view = model.bufferViews[size_t(out.bufferView)];
            const float* keys =
                reinterpret_cast<const float*>(model.buffers[0].data.data() + view.byteOffset);
            for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(keys[4 * k + 3], q.w);
        }
    }
    ASSERT_EQ(model.lights.size(), 2u);
    EXPECT_EQ(model.lights[0].type, "point");
    EXPECT_EQ(model.lights[0].color, (std::vector<double>{0.5, 1.0, 0.25}));
    EXPECT_NEAR(model.lights[0].intensity, 2.0 * 25.0, 1e-4);  // as bright 5 m away
    EXPECT_EQ(model.lights[1].type, "directional");
    const std::vector<double>& r = model.nodes[4].rotation;
    const glm::quat turn{float(r[3]), float(r[0]), float(r[1]), float(r[2])};
    const vec3 shines = turn * vec3(0, 0, -1);
    EXPECT_NEAR(shines.y, -1.0f, 1e-6f);
}

// The renderer's camera at the origin looking along +z sees +x on its left: glTF's camera
// looks down its −z with +x on its right, so its +x must be the world's −x.
TEST(Gltf, CameraTurnLooksAtTheTarget) {
    Camera c;
    c.pos = vec3(0);
    c.target = vec3(0, 0, 5);
    glm::quat q = cameraTurn(c);
    const vec3 forward = q * vec3(0, 0, -1), right = q * vec3(1, 0, 0), up = q * vec3(0, 1, 0);
    EXPECT_NEAR(glm::distance(forward, vec3(0, 0, 1)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(right, vec3(-1, 0, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(up, vec3(0, 1, 0)), 0.0f, 1e-6f);
    c.pos = vec3(3, 4, -2);
    c.target = vec3(-1, 0.5f, 2);
    q = cameraTurn(c);
    EXPECT_NEAR(glm::distance(q * vec3(0, 0, -1), glm::normalize(c.target - c.pos)), 0.0f, 1e-6f);
    EXPECT_NEAR((q * vec3(1, 0, 0)).y, 0.0f, 1e-6f);  // level: no roll
}
