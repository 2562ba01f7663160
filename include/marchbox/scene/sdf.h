// marchbox/scene/sdf.h — the CPU mirror of the shaders' distances (shaders/sdf.glsl and
// shaders/scene_map.glsl), for picking, the simulator and the tests that hold the two together.
//
// [SECTION] Primitives: signed distance at the origin; the caller moves and turns the point
// [SECTION] Operators
// [SECTION] Scene map: the CSG chain of a whole scene, with per-object bounding spheres
//
// The primitives, the operators, sdObjectLocal and mapObjects have same-named GLSL functions
// that compute the same distances; tests check that both agree. The rest are not twins:
//   mapScene     is map() in GLSL;
//   sceneNormal  takes central differences (six samples), the shader's calcNormal a tetrahedron
//                (four), so the two agree only to within the difference of the estimates;
//   castRay      marches the ground with the objects, where the shader's castRay meets the ground
//                analytically and marches the objects only inside their bounds;
//   objectBounds is computed here for the shader too (its uBoundLo and uBoundHi); the rest have
//                no GLSL counterpart.
#pragma once

#include "marchbox/scene/scene.h"

#include <algorithm>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace mb {

//-----------------------------------------------------------------------------
// [SECTION] Primitives
//-----------------------------------------------------------------------------
float sdSphere(glm::vec3 p, float r);                     // exact
inline float sdBox(glm::vec3 p, glm::vec3 halfExtents) {  // exact
    const glm::vec3 q = glm::abs(p) - halfExtents;
    return glm::length(glm::max(q, glm::vec3(0.0f))) +
           std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
}
float sdTorus(glm::vec3 p, float major, float minor);         // exact; ring in the x-z plane
inline float sdCapsule(glm::vec3 p, float height, float r) {  // exact; segment [-h/2, h/2] on y
    const float h = 0.5f * height;
    p.y -= std::clamp(p.y, -h, h);
    return glm::length(p) - r;
}
inline float sdCylinder(glm::vec3 p, float height, float r) {  // exact; capped, axis y, length h
    const glm::vec2 d =
        glm::abs(glm::vec2(glm::length(glm::vec2(p.x, p.z)), p.y)) - glm::vec2(r, 0.5f * height);
    return std::min(std::max(d.x, d.y), 0.0f) + glm::length(glm::max(d, glm::vec2(0.0f)));
}
// exact; axis y, length h, base radius r1 at y = -h/2, top radius r2 at y = +h/2
float sdCone(glm::vec3 p, float height, float r1, float r2);
float sdEllipsoid(glm::vec3 p, glm::vec3 semiAxes);  // bound; exact on the surface

//-----------------------------------------------------------------------------
// [SECTION] Operators
//-----------------------------------------------------------------------------
// Each returns the combined distance in x and, in y, the blend weight of b (0: a wins, 1: b
// wins), which picks the surface's object. k is the smooth-blend radius; k = 0 is sharp.
glm::vec2 opUnion(float a, float b, float k);
glm::vec2 opSubtract(float a, float b, float k);  // carve b out of a
glm::vec2 opIntersect(float a, float b, float k);

//-----------------------------------------------------------------------------
// [SECTION] Scene map
//-----------------------------------------------------------------------------
// R = Rz(z)·Ry(y)·Rx(x), angles in degrees.
glm::mat3 rotationFromEuler(glm::vec3 degrees);
glm::vec3 eulerFromRotation(const glm::mat3& r);  // its angles, for showing an exact turn
// The angles that show a turn held exactly in `orient`: `rot` itself while it gives that turn
// (as loaded or typed: 170 about y, not its twin -10 with x and z flipped), else orient's own,
// never -0. Within 0.16 degrees counts as the same turn.
glm::vec3 anglesShowing(const glm::quat& orient, const glm::vec3& rot);

// The radius of a sphere about the object's centre that holds its shape.
float boundingRadius(const Object& o);
// How far the shape reaches below its centre, turned as it is: its centre height above the
// ground when it rests there (Add, and a change of type, which keeps that lowest point).
float depthBelowCentre(const Object& o);

// One object, resolved for evaluation: the same numbers the shader receives.
struct SdfObject {
    ShapeType type;
    CsgOp op;
    glm::vec3 pos;      // in the world (a member's composed with its groups')
    glm::mat3 toLocal;  // transpose of the object's rotation in the world
    glm::vec3 size;
    float radius, minor, height, blend;
    float top = 0.0f, round = 0.0f, shell = 0.0f;
    float bound;  // radius of a sphere about pos that holds the shape
    int material;
    int group = -1;  // index in SceneSdf::groups; -1: the top level
};

// Whether the shape's distance is exact (else a bound: an ellipsoid, a shell).
bool exactShape(const SdfObject& o);

// A group, resolved for evaluation: its frame in the world and the run of objects it holds.
struct SdfGroup {
    int parent = -1;
    CsgOp op = CsgOp::Union;
    float blend = 0.0f;
    glm::vec3 pos{0.0f};
    glm::mat3 toLocal{1.0f};
    glm::bvec3 mirror{false};
    glm::ivec3 repeat{1};
    glm::vec3 spacing{1.0f};
    int first = 0, last = 0;  // objects [first, last) of SceneSdf::objects
    float copyBound = 0.0f;   // radius of a sphere about pos that holds one copy's shape
    float bound = 0.0f;       // ... that holds the group's shape, every copy
};

// Object o on its own, in its group's frame `parent` (groupPose of its group) in the world.
SdfObject makeSdfObject(const Object& o, const Placement& parent);
SdfObject makeSdfObject(const Object& o);  // a top-level object: its own pos and turn
// The shape at the origin. Sharp solid boxes, cylinders and capsules, most of what the simulator
// probes, are worked out inline where it asks: in a pile of tables, the calls and the switch
// were 45 % of each sample's instructions. Rounded, hollowed and other shapes: sdRoundedOrOther.
float sdRoundedOrOther(const SdfObject& o, glm::vec3 local);
inline float sdObjectLocal(const SdfObject& o, glm::vec3 local) {
    if (o.round > 0.0f || o.shell > 0.0f) return sdRoundedOrOther(o, local);
    switch (o.type) {
        case ShapeType::Box:
            return sdBox(local, o.size);
        case ShapeType::Cylinder:
            return sdCylinder(local, o.height, o.radius);
        case ShapeType::Capsule:
            return sdCapsule(local, o.height, o.radius);
        default:
            return sdRoundedOrOther(o, local);
    }
}
float sdObject(const SdfObject& o, glm::vec3 p);  // the shape in world space

constexpr int kHitGround = -1;  // SceneSample::object for the ground plane
constexpr int kHitNone = -2;    // nothing in reach

struct SceneSample {
    float d;     // signed distance to the scene
    int object;  // index of the surface's object, kHitGround or kHitNone
};

// The scene's objects, groups and ground, ready to evaluate many times.
struct SceneSdf {
    std::vector<SdfObject> objects;
    std::vector<SdfGroup> groups;  // as Scene::groups; objects' `group` index it
    bool ground = true;
    float floor = 0.0f;
};

SceneSdf makeSceneSdf(const Scene& scene);
// Sets every group's bounds from its members', the deepest groups first.
void boundGroups(SceneSdf& sdf);
int copyCount(const SdfGroup& g);
// Moves every object and group by -origin (the static collider's local frames).
void shiftSceneSdf(SceneSdf& sdf, glm::vec3 origin);
// Group g's own shape at p, members only (not joined to anything outside it).
SceneSample mapGroup(const SceneSdf& sdf, int g, glm::vec3 p);

// The sphere about pos within which the object can change the chain: its bound grown by its
// blend, since a smooth blend reaches k beyond the sharp surface.
float objectReach(const SdfObject& o);

struct Box {
    glm::vec3 lo{1e30f}, hi{-1e30f};  // empty until something is added
    bool empty() const { return lo.x > hi.x; }
};

// Every object's reach: outside it the scene is the ground alone, so rays need no marching.
// A group's members reach as far as their bounding spheres in each of its mirrors and copies.
Box objectBounds(const SceneSdf& sdf);
SceneSample mapScene(const SceneSdf& sdf, glm::vec3 p);
SceneSample mapObjects(const SceneSdf& sdf, glm::vec3 p);  // without the ground plane
glm::vec3 sceneNormal(const SceneSdf& sdf, glm::vec3 p);   // central differences, unit length

struct RayHit {
    bool hit = false;
    float t = 0.0f;  // distance along the unit direction
    int object = kHitNone;
    int steps = 0;
};

// Sphere tracing of mapScene, the ground included: a hit where the distance drops below epsilon
// (at once when the origin is inside a surface), a miss past maxDistance or maxSteps. The
// shader's castRay meets the ground analytically instead and counts a ray out of steps as
// grazing the object it is nearest to: the two agree where a march converges.
RayHit castRay(const SceneSdf& sdf, glm::vec3 origin, glm::vec3 dir, int maxSteps, float epsilon,
               float maxDistance);

}  // namespace mb
