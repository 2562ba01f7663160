// export.cpp — load, simulate, mesh and write: the steps of `marchbox export`.
#include "marchbox/export/export.h"

#include "gltf_file.h"
#include "mesh.h"
#include "mesh_files.h"
#include "scene_parts.h"

#include "marchbox/scene/atomic_file.h"
#include "marchbox/scene/camera_path.h"
#include "marchbox/scene/printable.h"
#include "marchbox/scene/sdf.h"

#include <cctype>
#include <cstdio>
#include <filesystem>

namespace mb {

bool meshFormatOf(const std::string& path, MeshFormat* out) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    static const std::pair<const char*, MeshFormat> formats[] = {{".stl", MeshFormat::Stl},
                                                                 {".obj", MeshFormat::Obj},
                                                                 {".ply", MeshFormat::Ply},
                                                                 {".glb", MeshFormat::Glb}};
    for (const auto& [name, format] : formats)
        if (ext == name) return *out = format, true;
    return false;
}

std::string mtlPathFor(const std::string& objPath) {
    return std::filesystem::path(objPath).replace_extension(".mtl").string();
}

namespace {

bool stopped(const ExportSettings& s) { return s.stop && s.stop(); }

ExportResult failed(const std::string& error) {
    ExportResult r;
    r.error = error;
    return r;
}

ExportResult stoppedRun() {
    ExportResult r;
    r.status = ExportResult::Stopped;
    return r;
}

std::string cannotWrite(const std::string& path, const std::string& why) {
    return "cannot write '" + printable(path) + "': " + why;
}

// Every file the export writes, checked before the work so that a bad path fails at once.
std::string checkOutputs(const std::string& path, MeshFormat format) {
    std::string why = checkReplaceFile(path);
    if (!why.empty()) return cannotWrite(path, why);
    if (format == MeshFormat::Obj && !(why = checkReplaceFile(mtlPathFor(path))).empty())
        return cannotWrite(mtlPathFor(path), why);
    return "";
}

std::string voxelText(double voxel) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", voxel);
    return text;
}

// The world stepped on to `steps`, polling stop; false if it said so.
bool stepTo(PhysicsWorld& world, long long steps, const ExportSettings& s) {
    while (world.stepCount() < steps) {
        if (stopped(s)) return false;
        world.step();
    }
    return true;
}

// `scene` meshed at `voxel`, the sampling's progress mapped to [from, from + span] of
// "meshing". Failed (too fine) or Stopped as a result; Written otherwise.
ExportResult meshPart(const Scene& scene, double voxel, const ExportSettings& s, double from,
                      double span, TriangleMesh* mesh, std::vector<int>* materials) {
    const SceneSdf sdf = makeSceneSdf(scene);
    MeshSettings settings;
    settings.voxel = voxel;
    settings.memoryBudget = s.memoryBudget;
    settings.stop = s.stop;
    if (s.progress)
        settings.progress = [&](double done) { s.progress("meshing", from + span * done); };
    std::string why;
    const MeshStatus status = meshSdf(sdf, settings, mesh, &why);
    if (status == MeshStatus::Stopped) return stoppedRun();
    if (status == MeshStatus::TooLarge) return failed(why);
    if (materials) *materials = triangleMaterials(scene, sdf, *mesh);
    ExportResult r;
    r.status = ExportResult::Written;
    return r;
}

// The bytes written last, once the work is done and not stopped: files that go together (an
// OBJ and its MTL) all or none.
ExportResult writeFiles(const std::vector<FileBytes>& files, double voxel, size_t triangles) {
    size_t bad = 0;
    const std::string why = replaceFiles(files, &bad);
    if (!why.empty()) return failed(cannotWrite(files[bad].path, why));
    ExportResult r;
    r.status = ExportResult::Written;
    r.voxel = voxel;
    r.triangles = triangles;
    return r;
}

}  // namespace

ExportResult exportScene(const Scene& scene, const std::string& path, const ExportSettings& s) {
    MeshFormat format;
    if (!meshFormatOf(path, &format))
        return failed("cannot tell the format of '" + printable(path) +
                      "': its extension is not .stl, .obj, .ply or .glb");
    if (std::string error = checkOutputs(path, format); !error.empty()) return failed(error);

    Scene shown = scene;
    if (s.seconds > 0.0) {
        PhysicsWorld world(scene, s.physics);
        const long long steps = stepsFor(s.seconds, s.physics);
        for (long long i = 1; i <= steps; ++i) {
            if (stopped(s)) return stoppedRun();
            world.step();
            if (s.progress && i * 100 / steps != (i - 1) * 100 / steps)
                s.progress("simulating", double(i) / double(steps));
        }
        world.writeBack(shown);
    }
    const SceneSdf sdf = makeSceneSdf(shown);
    if (objectBounds(sdf).empty()) return failed("the scene has no solids to export");
    const double voxel = s.voxel > 0.0 ? s.voxel : defaultVoxel(sdf);

    TriangleMesh mesh;
    std::vector<int> materials;
    ExportResult meshed = meshPart(shown, voxel, s, 0.0, 1.0, &mesh, &materials);
    if (meshed.status != ExportResult::Written) return meshed;
    if (mesh.empty())
        return failed("nothing to mesh: every solid is thinner than a voxel of " +
                      voxelText(voxel) + " m");
    if (stopped(s)) return stoppedRun();

    switch (format) {
        case MeshFormat::Stl:
            return writeFiles({{path, stlBytes(mesh)}}, voxel, mesh.triangles.size());
        case MeshFormat::Ply: {
            std::vector<glm::vec3> colours;
            for (int m : pointMaterials(shown, sdf, mesh))
                colours.push_back(materialColour(shown, m));
            return writeFiles({{path, plyBytes(mesh, colours)}}, voxel, mesh.triangles.size());
        }
        case MeshFormat::Obj: {
            const std::string mtl = mtlPathFor(path);
            const std::string name = std::filesystem::path(mtl).filename().string();
            return writeFiles(
                {{mtl, mtlBytes(shown)}, {path, objBytes(mesh, materials, shown, name)}}, voxel,
                mesh.triangles.size());
        }
        case MeshFormat::Glb: {
            GltfDocument doc;
            doc.scene = &shown;
            doc.solids = objectBounds(sdf);
            doc.cameras.push_back(cameraAt(shown.keyframes, shown.camera, s.seconds));
            const size_t triangles = mesh.triangles.size();
            doc.parts.push_back({"solids", std::move(mesh), std::move(materials), {}});
            return writeFiles({{path, glbBytes(doc)}}, voxel, triangles);
        }
    }
    return failed("unknown format");
}

ExportEstimate estimateExport(const Scene& scene, double voxel) {
    const SceneSdf sdf = makeSceneSdf(scene);
    ExportEstimate e;
    e.voxel = voxel > 0.0 ? voxel : defaultVoxel(sdf);
    if (e.voxel <= 0.0) return e;
    double area = 0.0;
    for (const SdfObject& o : sdf.objects) area += 4.0 * 3.14159265 * double(o.bound) * o.bound;
    // A surface crosses (|nx| + |ny| + |nz|)·area/S² voxel faces, 3/2 on average over the
    // directions, and each crossed face is a quad of two triangles.
    const double faces = 1.5 * area / (e.voxel * e.voxel);
    e.triangles = 2.0 * faces;
    // A float and its share of OpenVDB's leaf nodes for each voxel of the band; a vertex, a
    // normal, an index triple and a colour for each triangle.
    constexpr double kBytesPerVoxel = 8.0, kBytesPerTriangle = 48.0;
    e.bytes = faces * 2.0 * kBandVoxels * kBytesPerVoxel + e.triangles * kBytesPerTriangle;
    return e;
}

double exportVertexError(const Scene& scene, double voxel) {
    const SceneSdf sdf = makeSceneSdf(scene);
    if (objectBounds(sdf).empty()) return -1.0;
    TriangleMesh mesh;
    if (meshPart(scene, voxel > 0.0 ? voxel : defaultVoxel(sdf), ExportSettings(), 0.0, 1.0, &mesh,
                 nullptr)
                .status != ExportResult::Written ||
        mesh.empty())
        return -1.0;
    return largestVertexError(sdf, mesh);
}

ExportResult exportAnimation(const Scene& scene, const std::string& path,
                             const ExportFrames& frames, const ExportSettings& s) {
    MeshFormat format;
    if (!meshFormatOf(path, &format) || format != MeshFormat::Glb)
        return failed("an animated export is a .glb file, not '" + printable(path) + "'");
    if (std::string error = checkOutputs(path, format); !error.empty()) return failed(error);
    const SceneSdf whole = makeSceneSdf(scene);
    if (objectBounds(whole).empty()) return failed("the scene has no solids to export");
    const double voxel = s.voxel > 0.0 ? s.voxel : defaultVoxel(whole);

    // The parts, each meshed once: the static solids, then each body in its own frame.
    const std::vector<BodyRef> bodies = dynamicBodies(scene);
    GltfDocument doc;
    doc.scene = &scene;
    doc.solids = objectBounds(whole);
    std::vector<Scene> partScenes{staticPart(scene)};
    for (BodyRef b : bodies) partScenes.push_back(bodyAtOrigin(scene, b));
    size_t triangles = 0;
    for (size_t i = 0; i < partScenes.size(); ++i) {
        GltfPart part;
        part.name = i == 0 ? "static solids" : bodyName(scene, bodies[i - 1]);
        const double n = double(partScenes.size());
        ExportResult r =
            meshPart(partScenes[i], voxel, s, double(i) / n, 1.0 / n, &part.mesh, &part.materials);
        if (r.status != ExportResult::Written) return r;
        triangles += part.mesh.triangles.size();
        if (i > 0 || !part.mesh.empty()) doc.parts.push_back(std::move(part));
    }
    if (triangles == 0)
        return failed("nothing to mesh: every solid is thinner than a voxel of " +
                      voxelText(voxel) + " m");

    // The run, played once from t = 0 as render --frames plays it: frame k at stepsFor(k / fps).
    PhysicsWorld world(scene, s.physics);
    Scene shown = scene;
    const size_t firstBody = doc.parts.size() - bodies.size();
    for (int k = frames.first; k <= frames.last; ++k) {
        const double t = k / frames.fps;
        if (!stepTo(world, stepsFor(t, s.physics), s)) return stoppedRun();
        world.writeBack(shown);
        doc.times.push_back(t);
        for (size_t b = 0; b < bodies.size(); ++b)
            doc.parts[firstBody + b].poses.push_back(bodyPose(shown, bodies[b]));
        doc.cameras.push_back(cameraAt(scene.keyframes, scene.camera, t));
        if (s.progress)
            s.progress("simulating",
                       double(k - frames.first + 1) / (frames.last - frames.first + 1));
    }
    // Without keyframes the camera stands still: one view, not a channel of equal keys.
    if (scene.keyframes.empty()) doc.cameras.resize(1);
    if (stopped(s)) return stoppedRun();
    return writeFiles({{path, glbBytes(doc)}}, voxel, triangles);
}

}  // namespace mb
