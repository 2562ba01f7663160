// sdf.cpp — signed distance functions and the scene's CSG chain: the CPU mirror of
// shaders/sdf.glsl and shaders/scene_map.glsl (see sdf.h for where the two differ).
#include "marchbox/scene/sdf.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace mb {

using glm::vec2;
using glm::vec3;

float sdSphere(vec3 p, float r) { return glm::length(p) - r; }

float sdBox(vec3 p, vec3 b) {
    vec3 q = glm::abs(p) - b;
    return glm::length(glm::max(q, vec3(0.0f))) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
}

float sdTorus(vec3 p, float major, float minor) {
    vec2 q(glm::length(vec2(p.x, p.z)) - major, p.y);
    return glm::length(q) - minor;
}

float sdCapsule(vec3 p, float height, float r) {
    float h = 0.5f * height;
    p.y -= std::clamp(p.y, -h, h);
    return glm::length(p) - r;
}

float sdCylinder(vec3 p, float height, float r) {
    vec2 d = glm::abs(vec2(glm::length(vec2(p.x, p.z)), p.y)) - vec2(r, 0.5f * height);
    return std::min(std::max(d.x, d.y), 0.0f) + glm::length(glm::max(d, vec2(0.0f)));
}

// Polynomial smooth minimum (Quilez): it differs from min only where |a-b| < k, which is what
// lets the scene map skip objects whose bounding sphere is farther than k. y = weight of b.
glm::vec2 opUnion(float a, float b, float k) {
    float w = b < a ? 1.0f : 0.0f;
    if (k <= 0.0f) return vec2(std::min(a, b), w);
    float h = std::max(k - std::abs(a - b), 0.0f) / k;
    return vec2(std::min(a, b) - h * h * k * 0.25f, w);
}

// max(a, -b) = -min(-a, b)
glm::vec2 opSubtract(float a, float b, float k) {
    vec2 u = opUnion(-a, b, k);
    return vec2(-u.x, u.y);
}

// max(a, b) = -min(-a, -b)
glm::vec2 opIntersect(float a, float b, float k) {
    vec2 u = opUnion(-a, -b, k);
    return vec2(-u.x, u.y);
}

glm::mat3 rotationFromEuler(vec3 degrees) {
    vec3 r = glm::radians(degrees);
    glm::mat4 m(1.0f);
    m = glm::rotate(m, r.z, vec3(0, 0, 1));
    m = glm::rotate(m, r.y, vec3(0, 1, 0));
    m = glm::rotate(m, r.x, vec3(1, 0, 0));
    return glm::mat3(m);
}

// R = Rz·Ry·Rx has R[row 2][col 0] = −sin y, R[2][1] = cos y·sin x, R[2][2] = cos y·cos x,
// R[1][0] = sin z·cos y, R[0][0] = cos z·cos y (glm indexes [col][row]).
glm::vec3 eulerFromRotation(const glm::mat3& r) {
    const float y = std::asin(std::clamp(-r[0][2], -1.0f, 1.0f));
    return glm::degrees(vec3(std::atan2(r[1][2], r[2][2]), y, std::atan2(r[0][1], r[0][0])));
}

float boundingRadius(const Object& o) {
    switch (o.type) {
        case ShapeType::Sphere:
            return o.radius;
        case ShapeType::Box:
            return glm::length(o.size);
        case ShapeType::Torus:
            return o.radius + o.minor;
        case ShapeType::Capsule:
            return 0.5f * o.height + o.radius;
        case ShapeType::Cylinder:
            return std::hypot(0.5f * o.height, o.radius);
    }
    return 0.0f;
}

// A unit axis a reaches |a_y| below a point; a circle of radius r across it, r·sqrt(1 − a_y²).
float depthBelowCentre(const Object& o) {
    const glm::mat3 r = o.orient ? glm::mat3_cast(*o.orient) : rotationFromEuler(o.rot);
    const float up = std::abs(r[1].y);  // the local y axis (glm's column 1), upright part
    const float across = std::sqrt(std::max(0.0f, 1.0f - up * up));
    switch (o.type) {
        case ShapeType::Sphere:
            return o.radius;
        case ShapeType::Box:
            return std::abs(r[0].y) * o.size.x + up * o.size.y + std::abs(r[2].y) * o.size.z;
        case ShapeType::Torus:  // the ring lies across local y
            return o.radius * across + o.minor;
        case ShapeType::Capsule:
            return 0.5f * o.height * up + o.radius;
        case ShapeType::Cylinder:
            return 0.5f * o.height * up + o.radius * across;
    }
    return 0.0f;
}

SdfObject makeSdfObject(const Object& o) {
    SdfObject s;
    s.type = o.type;
    s.op = o.op;
    s.pos = o.pos;
    // Euler angles give the matrix directly, to the bit as before orient existed.
    s.toLocal = glm::transpose(o.orient ? glm::mat3_cast(*o.orient) : rotationFromEuler(o.rot));
    s.size = o.size;
    s.radius = o.radius;
    s.minor = o.minor;
    s.height = o.height;
    s.blend = o.blend;
    s.bound = boundingRadius(o);
    s.material = o.material;
    return s;
}

float sdObjectLocal(const SdfObject& o, vec3 q) {
    switch (o.type) {
        case ShapeType::Sphere:
            return sdSphere(q, o.radius);
        case ShapeType::Box:
            return sdBox(q, o.size);
        case ShapeType::Torus:
            return sdTorus(q, o.radius, o.minor);
        case ShapeType::Capsule:
            return sdCapsule(q, o.height, o.radius);
        case ShapeType::Cylinder:
            return sdCylinder(q, o.height, o.radius);
    }
    return 1e10f;
}

float sdObject(const SdfObject& o, vec3 p) { return sdObjectLocal(o, o.toLocal * (p - o.pos)); }

SceneSdf makeSceneSdf(const Scene& scene) {
    SceneSdf sdf;
    sdf.objects.reserve(scene.objects.size());
    for (const Object& o : scene.objects) sdf.objects.push_back(makeSdfObject(o));
    sdf.ground = scene.world.ground;
    sdf.floor = scene.world.floor;
    return sdf;
}

float objectReach(const SdfObject& o) { return o.bound + o.blend; }

Box objectBounds(const SceneSdf& sdf) {
    Box b;
    for (const SdfObject& o : sdf.objects) {
        b.lo = glm::min(b.lo, o.pos - objectReach(o));
        b.hi = glm::max(b.hi, o.pos + objectReach(o));
    }
    return b;
}

// "Nothing yet": far enough to lose every min, small enough that smooth blends stay finite.
constexpr float kFar = 1e10f;

SceneSample mapObjects(const SceneSdf& sdf, vec3 p) {
    SceneSample s{kFar, kHitNone};
    for (size_t i = 0; i < sdf.objects.size(); ++i) {
        const SdfObject& o = sdf.objects[i];
        // The bounding sphere gives dObj >= bound. Union and subtract are unchanged when the
        // object is k beyond what they would keep; intersect always needs the exact value.
        float bound = glm::length(p - o.pos) - o.bound;
        if (o.op == CsgOp::Union && bound >= s.d + o.blend) continue;
        if (o.op == CsgOp::Subtract && bound >= o.blend - s.d) continue;
        float d = sdObject(o, p);
        vec2 r = o.op == CsgOp::Union      ? opUnion(s.d, d, o.blend)
                 : o.op == CsgOp::Subtract ? opSubtract(s.d, d, o.blend)
                                           : opIntersect(s.d, d, o.blend);
        s.d = r.x;
        if (r.y > 0.5f) s.object = int(i);
    }
    return s;
}

SceneSample mapScene(const SceneSdf& sdf, vec3 p) {
    SceneSample s = mapObjects(sdf, p);
    if (sdf.ground) {
        float g = p.y - sdf.floor;
        if (g < s.d) s = {g, kHitGround};
    }
    return s;
}

vec3 sceneNormal(const SceneSdf& sdf, vec3 p) {
    const float h = 1e-4f * std::max(1.0f, glm::length(p) * 1e-2f);
    vec3 n(mapScene(sdf, p + vec3(h, 0, 0)).d - mapScene(sdf, p - vec3(h, 0, 0)).d,
           mapScene(sdf, p + vec3(0, h, 0)).d - mapScene(sdf, p - vec3(0, h, 0)).d,
           mapScene(sdf, p + vec3(0, 0, h)).d - mapScene(sdf, p - vec3(0, 0, h)).d);
    float len = glm::length(n);
    return len > 0.0f ? n / len : vec3(0, 1, 0);
}

RayHit castRay(const SceneSdf& sdf, vec3 origin, vec3 dir, int maxSteps, float epsilon,
               float maxDistance) {
    RayHit hit;
    float t = 0.0f;
    for (int i = 0; i < maxSteps; ++i) {
        SceneSample s = mapScene(sdf, origin + dir * t);
        hit.steps = i + 1;
        if (s.d < epsilon) {
            hit.hit = s.object != kHitNone;
            hit.t = t;
            hit.object = s.object;
            return hit;
        }
        t += s.d;
        if (t > maxDistance) break;
    }
    return hit;
}

}  // namespace mb
