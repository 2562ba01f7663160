// marchbox/scene/scene.h — the scene model: plain data, defaults from docs/scene-format.md.
//
// [SECTION] Limits
// [SECTION] Records (Camera, Keyframe, World, RenderSettings, Material, Light, Object, Group)
// [SECTION] Scene (and the file's comments)
//
// Units are metres, seconds, kilograms; +y is up. Angles in `rot` are degrees, as in the file.
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <glm/vector_relational.hpp>
#include <optional>
#include <string>
#include <vector>

namespace mb {

//-----------------------------------------------------------------------------
// [SECTION] Limits
//-----------------------------------------------------------------------------
constexpr int kMaxObjects = 4096;  // more objects in a file is a load error
constexpr int kMaxGroups = 1024;
constexpr int kMaxGroupDepth = 8;     // a group inside 8 others is an error
constexpr int kMaxRepeatCopies = 4096;  // a group's repeat counts multiplied
constexpr int kMaxMaterials = 256;
constexpr int kMaxLights = 16;
constexpr int kMaxLineBytes = 4096;  // longer lines are an error, checked before any regex runs

//-----------------------------------------------------------------------------
// [SECTION] Records
//-----------------------------------------------------------------------------
enum class ShapeType : int {
    Sphere = 0,
    Box = 1,
    Torus = 2,
    Capsule = 3,
    Cylinder = 4,
    Cone = 5,       // version 3: a frustum along local y, base `radius` below, `top` above
    Ellipsoid = 6,  // version 3: semi-axes `size`
};
constexpr int kShapeTypeCount = 7;
enum class CsgOp : int { Union = 0, Subtract = 1, Intersect = 2 };
constexpr int kCsgOpCount = 3;

struct Camera {
    glm::vec3 pos{0.0f, 2.0f, -6.0f};
    glm::vec3 target{0.0f, 1.0f, 0.0f};
    float fov = 50.0f;  // vertical, degrees, 1..179
};

// A point of the camera's path over time (format version 2). The loader fills the keys a record
// leaves out from the `camera` record.
struct Keyframe {
    float t = 0.0f;  // s, >= 0; no two keyframes share one
    glm::vec3 pos{0.0f};
    glm::vec3 target{0.0f};
    float fov = 50.0f;
    std::string comment{};
};

struct World {
    float gravity = 9.81f;     // m/s² along -y, >= 0
    float restitution = 0.8f;  // 0..1
    float friction = 0.3f;     // Coulomb coefficient, >= 0
    float rolling = 0.02f;  // rolling resistance: torque = rolling · radius · normal force, >= 0
    float floor = 0.0f;     // height of the ground plane
    bool ground = true;     // false removes the ground plane
};

struct RenderSettings {
    int steps = 256;         // max march steps, 1..4096
    float epsilon = 0.001f;  // hit distance, > 0
    int shadows = 1;         // 0 none, 1 hard, 2 soft
    int reflections = 3;     // max mirror bounces, 0..8
    float fog = 0.0f;        // exp² density, >= 0
    bool ao = false;
    int aa = 1;  // samples per pixel per axis, 1..4
};

struct Material {
    std::string name;       // [A-Za-z0-9_.-]+; the loader names unnamed materials "materialN"
    glm::vec3 color{1.0f};  // r g b, each >= 0
    float Ka = 0.1f, Kd = 0.8f, Ks = 0.5f;
    float C = 32.0f;        // shininess, > 0
    float Kr = 0.0f;        // mirror reflectivity, 0..1
    std::string comment{};  // the file's lines just above this record (see SceneComments)
};

struct Light {
    bool directional = false;  // true: `dir` record, `vec` is the direction light travels
    glm::vec3 vec{0.0f};       // point light position, or direction
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    std::string comment{};
};

struct Object {
    ShapeType type = ShapeType::Sphere;
    glm::vec3 pos{0.0f};
    int material = 0;
    float radius = 0.5f;
    glm::vec3 size{0.5f};             // box half-extents
    float minor = 0.1f;               // torus tube radius
    float height = 1.0f;              // capsule segment / cylinder length along local y
    glm::vec3 rot{0.0f};              // Euler degrees, R = Rz(z)·Ry(y)·Rx(x)
    std::optional<glm::quat> orient;  // the exact turn (unit, w,x,y,z); where set, rot is unused
    float mass = 1.0f;
    glm::vec3 vel{0.0f};   // m/s
    glm::vec3 spin{0.0f};  // angular velocity, rad/s
    bool isStatic = false;
    CsgOp op = CsgOp::Union;
    float blend = 0.0f;                              // smooth-blend radius, 0 = sharp
    std::string name{};                              // [A-Za-z0-9_.-]+, or empty: none
    std::optional<float> friction{}, restitution{};  // the object's own; absent: the world's
    float top = 0.0f;    // a cone's top radius, 0 <= top < radius
    float round = 0.0f;  // edge radius of a box, cylinder or cone; faces keep their place
    float shell = 0.0f;  // wall thickness: 0 solid, else hollow inside the surface
    int group = -1;      // index in Scene::groups of the group it belongs to; -1: top level
    std::string comment{};  // `{}`: aggregates built without it stay warning-free
    // The editor's, for this session only: not drawn in its view (hidden), not taken by a click
    // or a box (locked). No file holds them, and Scene equality, which reads the file's keys,
    // does not see them: they never make a scene unsaved.
    bool hidden{}, locked{};

    // A dynamic object is moved by the simulator, whatever its type; every other top-level
    // object is a static collider, and a member is part of its group's solid. (A version 1
    // file's other shapes load static: only spheres moved.)
    bool dynamic() const { return group < 0 && !isStatic && mass > 0.0f; }
    // Body to world: orient where set, else rot.
    glm::quat orientation() const;
};

// A group gathers the objects and groups whose `group`/`parent` name it into one shape: its
// members combine with one another only (a member's subtract carves its group), in its own frame
// (a member's pos and turn are relative to the group's), and the result joins its own parent's
// chain by `op` and `blend` at the group's place, as one object would. A top-level group with
// a mass is one rigid body. Groups are stored in tree order (see Scene).
struct Group {
    std::string name;  // required, unique among groups
    int parent = -1;   // index in Scene::groups; -1: the top level
    // Its place among its siblings: it stands just before objects[first] in the tree order
    // (objects.size() at the end). Its members are objects[first, end) of groupEnd().
    int first = 0;
    glm::vec3 pos{0.0f};
    glm::vec3 rot{0.0f};
    std::optional<glm::quat> orient;
    CsgOp op = CsgOp::Union;
    float blend = 0.0f;
    float mass = 1.0f;  // the motion keys: top level only
    glm::vec3 vel{0.0f};   // the centre of mass's velocity, m/s
    glm::vec3 spin{0.0f};  // rad/s
    bool isStatic = false;
    std::optional<float> friction{}, restitution{};
    glm::bvec3 mirror{false};  // keep the positive half about each local plane, reflected
    glm::ivec3 repeat{1};      // copies along x, y, z: each 1..64, product <= 4096
    glm::vec3 spacing{1.0f};   // between copies, each > 0
    std::string comment{};

    bool dynamic() const { return parent < 0 && !isStatic && mass > 0.0f; }
    glm::quat orientation() const;
};

//-----------------------------------------------------------------------------
// [SECTION] Scene
//-----------------------------------------------------------------------------
// A file's comment and blank lines, each run kept with the record that follows it, so a save
// writes a person's notes back where they were. Every string is whole lines, each blank or
// starting with '#' after blanks, each ending in '\n'. Materials, lights and objects carry
// their own `comment` and take it along when they are deleted; these are the others'.
struct SceneComments {
    std::string camera, world, render;  // above the `camera`, `world`, `render` records; what
                                        // was above `scene version:1` goes to the next record
    std::string end;                    // below the last record: stays at the end
    bool operator==(const SceneComments&) const = default;
};

struct Scene {
    Camera camera;
    World world;
    RenderSettings render;
    std::vector<Material> materials;
    std::vector<Light> lights;
    // Tree order: a group's members (objects and groups, recursively) follow it at once, so a
    // group's objects are one run of `objects`; top-level records keep their file order. The
    // CSG chain is evaluated in this order.
    std::vector<Object> objects;
    std::vector<Group> groups;
    std::vector<Keyframe> keyframes;  // in order of t
    SceneComments comments;
};

const char* shapeTypeName(ShapeType t);  // "sphere", "box", ...
const char* csgOpName(CsgOp op);         // "union", "subtract", "intersect"
bool hasEdges(ShapeType t);              // a box, cylinder or cone: what `round` applies to
// Half the shape's smallest extent: what `round` and `shell` must stay under.
float halfThinnest(const Object& o);

// Group trees (Scene::groups in tree order).
int groupEnd(const Scene& scene, int g);    // one past g's last object in the tree order
int groupDepth(const Scene& scene, int g);  // 1 for a top-level group
int topGroupOf(const Scene& scene, const Object& o);  // its top-level group, or -1
// Where a member stands in the world: its group chain's turns and moves applied to its own.
struct Placement {
    glm::vec3 pos{0.0f};
    glm::quat turn{1.0f, 0.0f, 0.0f, 0.0f};
};
Placement groupPose(const Scene& scene, int g);          // the group's frame in the world
Placement worldPose(const Scene& scene, const Object& o);  // the object's frame in the world

}  // namespace mb
