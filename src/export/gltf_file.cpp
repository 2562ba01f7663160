// gltf_file.cpp — the glTF document built as TinyGLTF's model, one buffer, written as GLB.
#include "gltf_file.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>
#include <map>
#include <sstream>

namespace mb {

namespace {

constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;  // bufferView targets

// The shortest turn that takes unit vector a to unit vector b.
glm::quat turnFromTo(glm::vec3 a, glm::vec3 b) {
    const float c = glm::dot(a, b);
    if (c < -0.999999f) {  // opposite: half a turn about any axis across a
        glm::vec3 axis = glm::cross(glm::vec3(1, 0, 0), a);
        if (glm::length(axis) < 1e-3f) axis = glm::cross(glm::vec3(0, 1, 0), a);
        return glm::angleAxis(glm::pi<float>(), glm::normalize(axis));
    }
    const glm::vec3 v = glm::cross(a, b);
    return glm::normalize(glm::quat(1.0f + c, v.x, v.y, v.z));
}

// The sRGB transfer function undone: a display value 0..1 to linear light.
double linearFromDisplay(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

class Builder {
public:
    explicit Builder(const GltfDocument& doc) : doc_(doc) {
        model_.asset.version = "2.0";
        model_.asset.generator = "marchbox export";
        model_.buffers.emplace_back();
        model_.scenes.emplace_back();
        model_.defaultScene = 0;
    }

    std::string write() {
        for (const GltfPart& part : doc_.parts) addPart(part);
        addCamera();
        addLights();
        if (channels_ > 0) model_.animations.push_back(std::move(animation_));
        std::ostringstream out;
        tinygltf::TinyGLTF gltf;
        gltf.WriteGltfSceneToStream(&model_, out, false, true);
        return out.str();
    }

private:
    // Bytes into the one buffer, 4-aligned, as a view of their own.
    int addView(const void* data, size_t bytes, int target) {
        std::vector<unsigned char>& buffer = model_.buffers[0].data;
        buffer.resize((buffer.size() + 3) / 4 * 4);
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = buffer.size();
        view.byteLength = bytes;
        view.target = target;
        buffer.insert(buffer.end(), static_cast<const unsigned char*>(data),
                      static_cast<const unsigned char*>(data) + bytes);
        model_.bufferViews.push_back(view);
        return int(model_.bufferViews.size()) - 1;
    }

    template <typename T>
    int addAccessor(const std::vector<T>& values, int components, int type, int component,
                    int target, bool bounds) {
        tinygltf::Accessor a;
        a.bufferView = addView(values.data(), values.size() * sizeof(T), target);
        a.componentType = component;
        a.type = type;
        a.count = values.size() / size_t(components);
        if (bounds) {
            a.minValues.assign(size_t(components), 1e300);
            a.maxValues.assign(size_t(components), -1e300);
            for (size_t i = 0; i < values.size(); ++i) {
                double& lo = a.minValues[i % size_t(components)];
                double& hi = a.maxValues[i % size_t(components)];
                lo = std::min(lo, double(values[i])), hi = std::max(hi, double(values[i]));
            }
        }
        model_.accessors.push_back(a);
        return int(model_.accessors.size()) - 1;
    }

    int material(int m) {
        const std::vector<Material>& materials = doc_.scene->materials;
        if (m < 0 || size_t(m) >= materials.size()) m = materials.empty() ? -1 : 0;
        auto found = materials_.find(m);
        if (found != materials_.end()) return found->second;
        tinygltf::Material out;
        glm::vec3 colour(0.8f);
        float shininess = 32.0f;
        if (m >= 0) {
            out.name = materials[size_t(m)].name;
            colour = glm::clamp(materials[size_t(m)].color, 0.0f, 1.0f);
            shininess = materials[size_t(m)].C;
        }
        out.pbrMetallicRoughness.baseColorFactor = {linearFromDisplay(colour.r),
                                                    linearFromDisplay(colour.g),
                                                    linearFromDisplay(colour.b), 1.0};
        out.pbrMetallicRoughness.metallicFactor = 0.0;
        out.pbrMetallicRoughness.roughnessFactor =
            std::clamp(std::pow(2.0 / (double(shininess) + 2.0), 0.25), 0.0, 1.0);
        model_.materials.push_back(out);
        return materials_[m] = int(model_.materials.size()) - 1;
    }

    // One primitive per material: the points its triangles use, renumbered.
    int addMesh(const GltfPart& part) {
        const TriangleMesh& mesh = part.mesh;
        const std::vector<glm::vec3> normals = pointNormals(mesh);
        std::map<int, std::vector<size_t>> byMaterial;
        for (size_t t = 0; t < mesh.triangles.size(); ++t)
            byMaterial[material(part.materials.empty() ? -1 : part.materials[t])].push_back(t);
        tinygltf::Mesh out;
        out.name = part.name;
        std::vector<uint32_t> index(mesh.points.size());
        for (const auto& [mat, triangles] : byMaterial) {
            std::fill(index.begin(), index.end(), UINT32_MAX);
            std::vector<float> positions, norms;
            std::vector<uint32_t> indices;
            for (size_t t : triangles)
                for (int c = 0; c < 3; ++c) {
                    const uint32_t p = mesh.triangles[t][c];
                    if (index[p] == UINT32_MAX) {
                        index[p] = uint32_t(positions.size() / 3);
                        for (int k = 0; k < 3; ++k)
                            positions.push_back(mesh.points[p][k]), norms.push_back(normals[p][k]);
                    }
                    indices.push_back(index[p]);
                }
            tinygltf::Primitive prim;
            prim.mode = TINYGLTF_MODE_TRIANGLES;
            prim.material = mat;
            prim.attributes["POSITION"] =
                addAccessor(positions, 3, TINYGLTF_TYPE_VEC3, TINYGLTF_COMPONENT_TYPE_FLOAT,
                            kArrayBuffer, true);
            prim.attributes["NORMAL"] = addAccessor(
                norms, 3, TINYGLTF_TYPE_VEC3, TINYGLTF_COMPONENT_TYPE_FLOAT, kArrayBuffer, false);
            prim.indices =
                addAccessor(indices, 1, TINYGLTF_TYPE_SCALAR, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                            kElementArrayBuffer, false);
            out.primitives.push_back(prim);
        }
        model_.meshes.push_back(out);
        return int(model_.meshes.size()) - 1;
    }

    int addNode(tinygltf::Node node) {
        model_.nodes.push_back(std::move(node));
        const int n = int(model_.nodes.size()) - 1;
        model_.scenes[0].nodes.push_back(n);
        return n;
    }

    static std::vector<double> rotation(glm::quat q) { return {q.x, q.y, q.z, q.w}; }
    static std::vector<double> translation(glm::vec3 p) { return {p.x, p.y, p.z}; }

    int timeAccessor() {
        if (times_ < 0) {
            std::vector<float> t(doc_.times.begin(), doc_.times.end());
            times_ =
                addAccessor(t, 1, TINYGLTF_TYPE_SCALAR, TINYGLTF_COMPONENT_TYPE_FLOAT, 0, true);
        }
        return times_;
    }

    // A node's translation and rotation at every key. Each quaternion takes the sign nearer the
    // one before, so that interpolating between keys turns the short way.
    void animate(int node, const std::vector<Placement>& poses) {
        std::vector<float> moves, turns;
        glm::quat last(1, 0, 0, 0);
        for (const Placement& p : poses) {
            glm::quat q = glm::normalize(p.turn);
            if (glm::dot(q, last) < 0.0f) q = -q;
            last = q;
            moves.insert(moves.end(), {p.pos.x, p.pos.y, p.pos.z});
            turns.insert(turns.end(), {q.x, q.y, q.z, q.w});
        }
        const int input = timeAccessor();
        const int move =
            addAccessor(moves, 3, TINYGLTF_TYPE_VEC3, TINYGLTF_COMPONENT_TYPE_FLOAT, 0, false);
        const int turn =
            addAccessor(turns, 4, TINYGLTF_TYPE_VEC4, TINYGLTF_COMPONENT_TYPE_FLOAT, 0, false);
        for (auto [output, path] : {std::pair{move, "translation"}, std::pair{turn, "rotation"}}) {
            tinygltf::AnimationSampler sampler;
            sampler.input = input;
            sampler.output = output;
            sampler.interpolation = "LINEAR";
            animation_.samplers.push_back(sampler);
            tinygltf::AnimationChannel channel;
            channel.sampler = int(animation_.samplers.size()) - 1;
            channel.target_node = node;
            channel.target_path = path;
            animation_.channels.push_back(channel);
            ++channels_;
        }
    }

    void addPart(const GltfPart& part) {
        tinygltf::Node node;
        node.name = part.name;
        if (!part.mesh.empty()) node.mesh = addMesh(part);
        if (!part.poses.empty()) {
            node.translation = translation(part.poses.front().pos);
            node.rotation = rotation(glm::normalize(part.poses.front().turn));
        }
        const int n = addNode(std::move(node));
        if (!part.poses.empty() && !doc_.times.empty()) animate(n, part.poses);
    }

    glm::vec3 centre() const {
        return doc_.solids.empty() ? glm::vec3(0.0f) : 0.5f * (doc_.solids.lo + doc_.solids.hi);
    }
    float radius() const {
        return doc_.solids.empty() ? 0.0f : 0.5f * glm::length(doc_.solids.hi - doc_.solids.lo);
    }

    // The first key's field of view throughout: glTF 2.0 animates no camera property.
    void addCamera() {
        if (doc_.cameras.empty()) return;
        const Camera& first = doc_.cameras.front();
        float farthest = 0.0f;
        for (const Camera& c : doc_.cameras)
            farthest = std::max(farthest, glm::length(c.pos - centre()) + radius());
        tinygltf::Camera camera;
        camera.type = "perspective";
        camera.name = "camera";
        camera.perspective.yfov = glm::radians(double(first.fov));
        camera.perspective.aspectRatio = 16.0 / 9.0;  // render's 640x360
        camera.perspective.znear = 0.01;
        camera.perspective.zfar = std::max(1000.0, 2.0 * double(farthest));
        model_.cameras.push_back(camera);
        tinygltf::Node node;
        node.name = "camera";
        node.camera = int(model_.cameras.size()) - 1;
        node.translation = translation(first.pos);
        node.rotation = rotation(cameraTurn(first));
        const int n = addNode(std::move(node));
        if (doc_.cameras.size() == doc_.times.size() && !doc_.times.empty()) {
            std::vector<Placement> poses;
            for (const Camera& c : doc_.cameras) poses.push_back({c.pos, cameraTurn(c)});
            animate(n, poses);
        }
    }

    // KHR_lights_punctual: colour 0..1 and intensity apart. The renderer's lights do not fall
    // off with distance, a glTF point light does (candela, over d²): a point light is as bright
    // at the solids' centre as the renderer's is everywhere. A directional light shines along
    // its node's −z.
    void addLights() {
        for (size_t i = 0; i < doc_.scene->lights.size(); ++i) {
            const Light& l = doc_.scene->lights[i];
            const float peak = std::max({l.color.r, l.color.g, l.color.b});
            tinygltf::Light out;
            out.name = "light " + std::to_string(i);
            out.type = l.directional ? "directional" : "point";
            const glm::vec3 colour = peak > 0.0f ? l.color / peak : glm::vec3(1.0f);
            out.color = {colour.r, colour.g, colour.b};
            const double d2 = l.directional ? 1.0 : std::max(1.0f, glm::distance(l.vec, centre()));
            out.intensity = double(l.intensity) * peak * d2 * d2;
            model_.lights.push_back(out);
            tinygltf::Node node;
            node.name = out.name;
            if (l.directional) {
                const float len = glm::length(l.vec);
                const glm::vec3 dir = len > 0.0f ? l.vec / len : glm::vec3(0, -1, 0);
                node.rotation = rotation(turnFromTo(glm::vec3(0, 0, -1), dir));
            } else {
                node.translation = translation(l.vec);
            }
            tinygltf::Value::Object light;
            light["light"] = tinygltf::Value(int(model_.lights.size()) - 1);
            node.extensions["KHR_lights_punctual"] = tinygltf::Value(light);
            addNode(std::move(node));
        }
    }

    const GltfDocument& doc_;
    tinygltf::Model model_;
    tinygltf::Animation animation_;
    int channels_ = 0;
    int times_ = -1;
    std::map<int, int> materials_;  // scene material → glTF material
};

}  // namespace

glm::quat cameraTurn(const Camera& camera) {
    glm::vec3 forward = camera.target - camera.pos;
    if (glm::length(forward) <= 0.0f) forward = glm::vec3(0, 0, 1);
    const glm::vec3 z = -glm::normalize(forward);
    glm::vec3 x = glm::cross(glm::vec3(0, 1, 0), z);
    // Straight up or down: any right-hand side will do; lookAt's is as degenerate.
    x = glm::length(x) > 1e-6f ? glm::normalize(x) : glm::vec3(1, 0, 0);
    const glm::vec3 y = glm::cross(z, x);
    return glm::normalize(glm::quat_cast(glm::mat3(x, y, z)));
}

std::string glbBytes(const GltfDocument& doc) { return Builder(doc).write(); }

}  // namespace mb
