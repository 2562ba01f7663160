// sdf.cpp — signed distance functions and the scene's CSG chain: the CPU mirror of
// shaders/sdf.glsl and shaders/scene_map.glsl (see sdf.h for where the two differ).
#include "marchbox/scene/sdf.h"
#include "marchbox/scene/shapes.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace mb {

using glm::vec2;
using glm::vec3;

float sdSphere(vec3 p, float r) { return glm::length(p) - r; }

float sdTorus(vec3 p, float major, float minor) {
    vec2 q(glm::length(vec2(p.x, p.z)) - major, p.y);
    return glm::length(q) - minor;
}

// Quilez's capped cone: the distance to the trapezoid (r1 at -h, r2 at +h) in the (radial, y)
// half-plane, signed by the side of both caps and the slant.
float sdCone(vec3 p, float height, float r1, float r2) {
    const float h = 0.5f * height;
    const vec2 q(glm::length(vec2(p.x, p.z)), p.y);
    const vec2 k1(r2, h), k2(r2 - r1, 2.0f * h);
    const vec2 ca(q.x - std::min(q.x, q.y < 0.0f ? r1 : r2), std::abs(q.y) - h);
    const vec2 cb = q - k1 + k2 * std::clamp(glm::dot(k1 - q, k2) / glm::dot(k2, k2), 0.0f, 1.0f);
    const float s = cb.x < 0.0f && ca.y < 0.0f ? -1.0f : 1.0f;
    return s * std::sqrt(std::min(glm::dot(ca, ca), glm::dot(cb, cb)));
}

// Quilez's ellipsoid bound k0·(k0 − 1)/k1: exact on the surface, a bound off it.
float sdEllipsoid(vec3 p, vec3 r) {
    const float k0 = glm::length(p / r), k1 = glm::length(p / (r * r));
    return k1 > 0.0f ? k0 * (k0 - 1.0f) / k1 : -std::min(r.x, std::min(r.y, r.z));
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

glm::vec3 anglesShowing(const glm::quat& orient, const glm::vec3& rot) {
    const glm::quat held = glm::quat_cast(rotationFromEuler(rot));
    // |dot| is cos(half the angle between them): 1 - 1e-6 is 0.16 degrees, above float noise.
    if (std::abs(glm::dot(held, orient)) > 1.0f - 1e-6f) return rot;
    return eulerFromRotation(glm::mat3_cast(orient)) + vec3(0.0f);  // -0 + 0 is +0
}

float boundingRadius(const Object& o) {
    switch (o.type) {
        case ShapeType::Cone:
            return std::hypot(0.5f * o.height, o.radius);
        case ShapeType::Ellipsoid:
            return std::max(o.size.x, std::max(o.size.y, o.size.z));
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
        case ShapeType::Cone:  // the base rim, or the top's where the cone stands on its tip
            return 0.5f * o.height * up + o.radius * across;
        case ShapeType::Ellipsoid: {  // support along −y: |diag(size)·Rᵀ·y|
            const glm::vec3 row(r[0].y, r[1].y, r[2].y);
            return glm::length(row * o.size);
        }
    }
    return 0.0f;
}

SdfObject makeSdfObject(const Object& o) {
    SdfObject s{};
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
    s.top = o.top;
    s.round = o.round;
    s.shell = o.shell;
    s.bound = boundingRadius(o);
    s.material = o.material;
    return s;
}

SdfObject makeSdfObject(const Object& o, const Placement& parent) {
    SdfObject s = makeSdfObject(o);
    if (o.group < 0) return s;  // the turn's matrix to the bit, as a top-level object has it
    const glm::mat3 turn = glm::mat3_cast(parent.turn) * glm::transpose(s.toLocal);
    s.pos = parent.pos + parent.turn * o.pos;
    s.toLocal = glm::transpose(turn);
    return s;
}

bool exactShape(const SdfObject& o) { return shapeRow(o.type).exact && o.shell <= 0.0f; }

namespace {

// The shape's own distance, before rounding and hollowing.
float sdSolid(const SdfObject& o, vec3 q) {
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
        case ShapeType::Cone:
            return sdCone(q, o.height, o.radius, o.top);
        case ShapeType::Ellipsoid:
            return sdEllipsoid(q, o.size);
    }
    return 1e10f;
}

// The same shape with every face moved in by r (for rounding: the points within r of it), and
// how far its centre rises. A cone's slant moves in by r across it, r·√(1 + slope²) along its
// radius; where that passes a pointed top, the inset cone ends at its apex, lower down.
SdfObject inset(SdfObject o, float r, float* lift) {
    *lift = 0.0f;
    o.size -= vec3(r);
    o.height -= 2.0f * r;
    if (o.type == ShapeType::Cylinder) o.radius -= r;
    if (o.type == ShapeType::Cone) {
        const float slope = (o.radius - o.top) / (o.height + 2.0f * r);
        const float side = r * std::sqrt(1.0f + slope * slope);
        const float r1 = o.radius - slope * r - side, r2 = o.top + slope * r - side;
        o.radius = r1;
        o.top = std::max(r2, 0.0f);
        if (r2 < 0.0f) {
            const float height = o.height * r1 / (r1 - r2);
            *lift = 0.5f * (height - o.height);
            o.height = height;
        }
    }
    return o;
}

}  // namespace

float sdRoundedOrOther(const SdfObject& o, vec3 q) {
    float d;
    if (o.round > 0.0f) {
        float lift = 0.0f;  // set by inset, which must run before q is moved by it
        const SdfObject core = inset(o, o.round, &lift);
        d = sdSolid(core, q - vec3(0, lift, 0)) - o.round;
    } else {
        d = sdSolid(o, q);
    }
    // A shell keeps what lies within t inside the surface: max(d, −(d + t)).
    return o.shell > 0.0f ? std::abs(d + 0.5f * o.shell) - 0.5f * o.shell : d;
}

float sdObject(const SdfObject& o, vec3 p) { return sdObjectLocal(o, o.toLocal * (p - o.pos)); }

SdfGroup makeSdfGroup(const Scene& scene, int g) {
    const Group& group = scene.groups[size_t(g)];
    const Placement pose = groupPose(scene, g);
    SdfGroup s;
    s.parent = group.parent;
    s.op = group.op;
    s.blend = group.blend;
    s.pos = pose.pos;
    s.toLocal = glm::transpose(glm::mat3_cast(pose.turn));
    s.mirror = group.mirror;
    s.repeat = group.repeat;
    s.spacing = group.spacing;
    s.first = group.first;
    s.last = groupEnd(scene, g);
    return s;
}

SceneSdf makeSceneSdf(const Scene& scene) {
    SceneSdf sdf;
    for (size_t g = 0; g < scene.groups.size(); ++g)
        sdf.groups.push_back(makeSdfGroup(scene, int(g)));
    sdf.objects.reserve(scene.objects.size());
    for (const Object& o : scene.objects) {
        sdf.objects.push_back(makeSdfObject(o, groupPose(scene, o.group)));
        sdf.objects.back().group = o.group;
    }
    boundGroups(sdf);
    sdf.ground = scene.world.ground;
    sdf.floor = scene.world.floor;
    return sdf;
}

float objectReach(const SdfObject& o) { return o.bound + o.blend; }

int copyCount(const SdfGroup& g) { return g.repeat.x * g.repeat.y * g.repeat.z; }

// The copy at the group's origin, in copy indices along each axis: (n − 1) / 2.
static vec3 middleCopy(const SdfGroup& g) { return 0.5f * (vec3(g.repeat) - 1.0f); }

// Only union members add to a group's shape (subtract and intersect remove, a smooth union adds
// under its radius); a mirror reflects about planes through the group's origin, which keeps
// every distance from it; the copies spread the shape by the farthest copy's offset.
void boundGroups(SceneSdf& sdf) {
    for (SdfGroup& g : sdf.groups) g.copyBound = 0.0f;
    for (const SdfObject& o : sdf.objects)
        if (o.group >= 0 && o.op == CsgOp::Union) {
            SdfGroup& g = sdf.groups[size_t(o.group)];
            g.copyBound = std::max(g.copyBound, glm::length(o.pos - g.pos) + objectReach(o));
        }
    for (size_t i = sdf.groups.size(); i-- > 0;) {  // children come after their parents
        SdfGroup& g = sdf.groups[i];
        const vec3 spread = middleCopy(g) * g.spacing;
        g.bound = g.copyBound + glm::length(spread);
        if (g.parent >= 0 && g.op == CsgOp::Union && g.last > g.first) {
            SdfGroup& parent = sdf.groups[size_t(g.parent)];
            parent.copyBound =
                std::max(parent.copyBound, glm::length(g.pos - parent.pos) + g.bound + g.blend);
        }
    }
}

void shiftSceneSdf(SceneSdf& sdf, vec3 origin) {
    for (SdfObject& o : sdf.objects) o.pos -= origin;
    for (SdfGroup& g : sdf.groups) g.pos -= origin;
}

namespace {

void add(Box& b, const Box& other) {
    b.lo = glm::min(b.lo, other.lo);
    b.hi = glm::max(b.hi, other.hi);
}

Box around(vec3 centre, float reach) { return {centre - reach, centre + reach}; }

// A sphere that holds part of a group's solid, in the world.
struct Ball {
    vec3 centre;
    float radius;
};

// More balls than this are replaced by the eight corners of their box: repeats nested eight deep
// would otherwise multiply them by 64 at each level.
constexpr size_t kMostBalls = 64;

void keepFew(std::vector<Ball>& balls) {
    if (balls.size() <= kMostBalls) return;
    Box b;
    for (const Ball& ball : balls) add(b, around(ball.centre, ball.radius));
    balls.clear();
    for (int c = 0; c < 8; ++c)
        balls.push_back(
            {vec3((c & 1) ? b.hi.x : b.lo.x, (c & 2) ? b.hi.y : b.lo.y, (c & 4) ? b.hi.z : b.lo.z),
             0.0f});
}

// The balls' images in group g: each mirror's reflection, and the copies at the corners of its
// lattice, which hold every copy between them in their box. Turning a ball leaves it a ball, so
// the box about them is as tight turned as not.
void addImages(const SdfGroup& g, std::vector<Ball>& balls) {
    const glm::mat3 toWorld = glm::transpose(g.toLocal);
    const vec3 spread = middleCopy(g) * g.spacing;
    std::vector<Ball> images;
    for (const Ball& ball : balls) {
        const vec3 q = g.toLocal * (ball.centre - g.pos);
        for (int m = 0; m < 8; ++m)
            for (int c = 0; c < 8; ++c) {
                vec3 image = q;
                bool used = true;
                for (int a = 0; a < 3; ++a) {
                    used &= (!(m >> a & 1) || g.mirror[a]) && (!(c >> a & 1) || spread[a] > 0.0f);
                    if (m >> a & 1) image[a] = -image[a];
                    image[a] += (c >> a & 1) ? spread[a] : -spread[a];
                }
                if (used) images.push_back({g.pos + toWorld * image, ball.radius + g.blend});
            }
    }
    balls = std::move(images);
    keepFew(balls);
}

// The balls that hold each group's solid, in the world: its union members' bounding spheres and
// its member groups' balls, in its mirrors and copies. The sphere about the group's origin
// (bound) held a member 10 m off it in a box 21 m wide, which gave an export 21 times too coarse
// a voxel.
std::vector<std::vector<Ball>> groupBalls(const SceneSdf& sdf) {
    std::vector<std::vector<Ball>> balls(sdf.groups.size());
    for (const SdfObject& o : sdf.objects)
        if (o.group >= 0 && o.op == CsgOp::Union)
            balls[size_t(o.group)].push_back({o.pos, objectReach(o)});
    for (size_t i = sdf.groups.size(); i-- > 0;) {  // children come after their parents
        const SdfGroup& g = sdf.groups[i];
        keepFew(balls[i]);
        addImages(g, balls[i]);
        if (g.parent < 0 || g.op != CsgOp::Union) continue;
        std::vector<Ball>& parent = balls[size_t(g.parent)];
        parent.insert(parent.end(), balls[i].begin(), balls[i].end());
    }
    return balls;
}

}  // namespace

Box objectBounds(const SceneSdf& sdf) {
    Box b;
    for (const SdfObject& o : sdf.objects)
        if (o.group < 0) add(b, around(o.pos, objectReach(o)));
    const std::vector<std::vector<Ball>> balls = groupBalls(sdf);
    for (size_t i = 0; i < sdf.groups.size(); ++i)
        if (sdf.groups[i].parent < 0)
            for (const Ball& ball : balls[i]) add(b, around(ball.centre, ball.radius));
    return b;
}

// "Nothing yet": far enough to lose every min, small enough that smooth blends stay finite.
constexpr float kFar = 1e10f;

namespace {

// Where q (in the group's frame) falls along each axis of the copies, in copy indices, neither
// rounded nor clamped.
vec3 copyCoord(const SdfGroup& g, vec3 q) { return q / g.spacing + middleCopy(g); }

// Copy (i, j, k) sits at ((i − (n−1)/2)·s, ...) in the group's frame; the mirror folds the point
// onto the positive side of each mirrored plane before the copy's members see it. False where
// the copy's bounding sphere is at least `cull` from q.
bool groupImage(const SdfGroup& g, vec3 q, glm::ivec3 index, float cull, vec3* image) {
    q -= (vec3(index) - middleCopy(g)) * g.spacing;
    if (glm::length(q) - g.copyBound >= cull) return false;
    for (int a = 0; a < 3; ++a)
        if (g.mirror[a]) q[a] = std::abs(q[a]);
    *image = g.pos + glm::transpose(g.toLocal) * q;
    return true;
}

// Whether a member whose distance is at least `lower` leaves the chain's distance d as it is:
// union and subtract do when it is k beyond what they keep; intersect always needs its value.
bool leavesAlone(CsgOp op, float lower, float k, float d) {
    return (op == CsgOp::Union && lower >= d + k) || (op == CsgOp::Subtract && lower >= k - d);
}

void join(SceneSample& s, SceneSample member, CsgOp op, float k) {
    vec2 r = op == CsgOp::Union      ? opUnion(s.d, member.d, k)
             : op == CsgOp::Subtract ? opSubtract(s.d, member.d, k)
                                     : opIntersect(s.d, member.d, k);
    s.d = r.x;
    if (r.y > 0.5f) s.object = member.object;
}

// The chain of `parent`'s members among objects [first, last), a group's as one member.
SceneSample mapChain(const SceneSdf& sdf, int parent, int first, int last, vec3 p) {
    SceneSample s{kFar, kHitNone};
    for (int i = first; i < last;) {
        const SdfObject& o = sdf.objects[size_t(i)];
        if (o.group == parent) {
            if (!leavesAlone(o.op, glm::length(p - o.pos) - o.bound, o.blend, s.d))
                join(s, {sdObject(o, p), i}, o.op, o.blend);
            ++i;
            continue;
        }
        int g = o.group;  // the member group that holds object i
        while (sdf.groups[size_t(g)].parent != parent) g = sdf.groups[size_t(g)].parent;
        const SdfGroup& group = sdf.groups[size_t(g)];
        if (!leavesAlone(group.op, glm::length(p - group.pos) - group.bound, group.blend, s.d))
            join(s, mapGroup(sdf, g, p), group.op, group.blend);
        i = group.last;
    }
    return s;
}

}  // namespace

// The union of the copies, sharp whether or not they overlap, as groups.glsl finds it: first the
// copy whose cell holds the point, then only the box of copies whose bounding spheres reach
// nearer than that one's distance. A copy beyond it cannot lower the union, and 4,096 copies
// each evaluated at every point took a dynamic group's setup two minutes.
SceneSample mapGroup(const SceneSdf& sdf, int g, vec3 p) {
    const SdfGroup& group = sdf.groups[size_t(g)];
    if (copyCount(group) == 1 && !glm::any(group.mirror))
        return mapChain(sdf, g, group.first, group.last, p);
    const vec3 q = group.toLocal * (p - group.pos), last = vec3(group.repeat - 1);
    SceneSample best{kFar, kHitNone};
    auto visit = [&](glm::ivec3 index) {
        vec3 image;
        if (!groupImage(group, q, index, best.d, &image)) return;
        const SceneSample s = mapChain(sdf, g, group.first, group.last, image);
        if (s.d < best.d) best = s;
    };
    const glm::ivec3 nearest(glm::clamp(glm::floor(copyCoord(group, q) + 0.5f), vec3(0.0f), last));
    visit(nearest);
    // Clamped as floats: a far best (kFar, nothing there) makes no integer overflow.
    const float reach = best.d + group.copyBound;
    const glm::ivec3 lo(glm::clamp(glm::ceil(copyCoord(group, q - reach)), vec3(0.0f), last));
    const glm::ivec3 hi(glm::clamp(glm::floor(copyCoord(group, q + reach)), vec3(0.0f), last));
    for (int k = lo.z; k <= hi.z; ++k)
        for (int j = lo.y; j <= hi.y; ++j)
            for (int i = lo.x; i <= hi.x; ++i)
                if (glm::ivec3(i, j, k) != nearest) visit({i, j, k});
    return best;
}

SceneSample mapObjects(const SceneSdf& sdf, vec3 p) {
    return mapChain(sdf, -1, 0, int(sdf.objects.size()), p);
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
