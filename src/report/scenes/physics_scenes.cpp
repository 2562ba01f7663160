// physics_scenes.cpp — builders of the physics test and benchmark scenes.
#include "marchbox/report/physics_scenes.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

namespace mb {

namespace {

// Numerical Recipes LCG: the same numbers everywhere, unlike <random>'s distributions.
struct Lcg {
    std::uint32_t state;
    float next() {  // [0, 1)
        state = state * 1664525u + 1013904223u;
        return float(state >> 8) / float(1u << 24);
    }
    float range(float lo, float hi) { return lo + (hi - lo) * next(); }
};

constexpr float kDensity = 1000.0f;  // kg/m³, water

float sphereMass(float radius) {
    return kDensity * 4.0f / 3.0f * float(M_PI) * radius * radius * radius;
}

// pileScene's walled bin, about 8 layers deep, for bodies `spacing` apart: `side` by `side` in
// each layer, body i in column x, layer y and row z of cell(i).
struct Bin {
    int side;
    float spacing;
    glm::ivec3 cell(int i) const { return {i % side, i / (side * side), (i / side) % side}; }
    // Body i's centre, the lowest layer's `lift` above the ground.
    glm::vec3 place(int i, float lift) const {
        const glm::ivec3 c = cell(i);
        return {spacing * (float(c.x) - 0.5f * float(side - 1)), lift + spacing * float(c.y),
                spacing * (float(c.z) - 0.5f * float(side - 1))};
    }
};

}  // namespace

Scene physicsWorld(float gravity, float restitution, float friction, bool ground) {
    Scene s;
    s.world.gravity = gravity;
    s.world.restitution = restitution;
    s.world.friction = friction;
    s.world.ground = ground;
    s.materials.push_back(Material{});
    return s;
}

Object dynamicSphere(glm::vec3 pos, float radius, float mass, glm::vec3 vel) {
    Object o;
    o.type = ShapeType::Sphere;
    o.pos = pos;
    o.radius = radius;
    o.mass = mass;
    o.vel = vel;
    return o;
}

Object dynamicBox(glm::vec3 pos, glm::vec3 halfExtents, float mass) {
    Object o;
    o.type = ShapeType::Box;
    o.pos = pos;
    o.size = halfExtents;
    o.mass = mass;
    return o;
}

Object staticBox(glm::vec3 pos, glm::vec3 halfExtents) {
    Object o = dynamicBox(pos, halfExtents, 1.0f);
    o.isStatic = true;
    return o;
}

void addWalls(Scene& scene, float inner, float height, float thickness) {
    const float h = 0.5f * height, t = 0.5f * thickness, off = inner + t, len = inner + thickness;
    scene.objects.push_back(staticBox({off, h, 0}, {t, h, len}));
    scene.objects.push_back(staticBox({-off, h, 0}, {t, h, len}));
    scene.objects.push_back(staticBox({0, h, off}, {len, h, t}));
    scene.objects.push_back(staticBox({0, h, -off}, {len, h, t}));
}

namespace {

// Walls about a bin for `count` bodies `spacing` apart and of size about r: 0.3·r of room beside
// the outer ones, half as high as the bodies stack and one spacing more.
Bin addBin(Scene& scene, int count, float spacing, float r) {
    const int side = std::max(2, int(std::ceil(std::sqrt(count / 8.0f))));
    const float inner = 0.5f * spacing * float(side) + 0.3f * r;
    addWalls(scene, inner, 0.5f * spacing * float(count / (side * side) + 2), 0.1f);
    return {side, spacing};
}

}  // namespace

Scene freeFallScene(float height) {
    Scene s = physicsWorld(9.81f, 0.0f, 0.0f, false);
    s.objects.push_back(dynamicSphere({0, height, 0}, 0.5f, 1.0f));
    return s;
}

Scene projectileScene(glm::vec3 vel) {
    Scene s = physicsWorld(9.81f, 0.0f, 0.0f, false);
    s.objects.push_back(dynamicSphere({0, 0, 0}, 0.5f, 1.0f, vel));
    return s;
}

Scene bounceScene(float height, float restitution) {
    Scene s = physicsWorld(9.81f, restitution, 0.0f, true);
    const float r = 0.1f;
    s.objects.push_back(dynamicSphere({0, height + r, 0}, r, 1.0f));
    return s;
}

Scene headOnScene(float restitution, float m1, float m2, float v1, float v2) {
    Scene s = physicsWorld(0.0f, restitution, 0.0f, false);
    s.objects.push_back(dynamicSphere({-1, 0, 0}, 0.5f, m1, {v1, 0, 0}));
    s.objects.push_back(dynamicSphere({1, 0, 0}, 0.5f, m2, {v2, 0, 0}));
    return s;
}

Scene slideScene(float speed, float friction) {
    Scene s = physicsWorld(9.81f, 0.0f, friction, true);
    s.objects.push_back(dynamicSphere({0, 0.5f, 0}, 0.5f, 1.0f, {speed, 0, 0}));
    return s;
}

Scene rollScene(float speed, float rolling) {
    Scene s = physicsWorld(9.81f, 0.0f, 0.5f, true);
    s.world.rolling = rolling;
    const float r = 0.5f;
    Object o = dynamicSphere({0, r, 0}, r, 1.0f, {speed, 0, 0});
    o.spin = {0, 0, -speed / r};  // ω × (−r·y) = v: no slip at the contact
    s.objects.push_back(o);
    return s;
}

Scene spinScene(float spin, float friction) {
    Scene s = physicsWorld(9.81f, 0.0f, friction, true);
    Object o = dynamicSphere({0, 0.5f, 0}, 0.5f, 1.0f);
    o.spin = {0, 0, -spin};  // rolls towards +x once friction has its way
    s.objects.push_back(o);
    return s;
}

glm::vec3 bowlCentre(float bowlRadius) { return {0, 1.0f + 0.7f * bowlRadius, 0}; }

Scene bowlScene(float bowlRadius, float ballRadius, float degrees, float friction) {
    Scene s = physicsWorld(9.81f, 0.0f, friction, true);
    s.objects.push_back(staticBox({0, 0.5f, 0}, {2, 0.5f, 2}));
    Object hole;
    hole.type = ShapeType::Sphere;
    hole.pos = bowlCentre(bowlRadius);
    hole.radius = bowlRadius;
    hole.isStatic = true;
    hole.op = CsgOp::Subtract;
    s.objects.push_back(hole);
    const float a = degrees * float(M_PI) / 180.0f, swing = bowlRadius - ballRadius;
    s.objects.push_back(dynamicSphere(hole.pos + swing * glm::vec3(std::sin(a), -std::cos(a), 0),
                                      ballRadius, 1.0f));
    return s;
}

Scene rampScene(float degrees, float friction, float rolling) {
    Scene s = physicsWorld(9.81f, 0.0f, friction, false);
    s.world.rolling = rolling;
    Object plank = staticBox({0, 0, 0}, {20, 0.5f, 2});
    plank.rot = {0, 0, degrees};
    s.objects.push_back(plank);
    const float a = degrees * float(M_PI) / 180.0f, r = 0.2f;
    const glm::vec3 up(std::cos(a), std::sin(a), 0), normal(-std::sin(a), std::cos(a), 0);
    s.objects.push_back(dynamicSphere(3.0f * up + (0.5f + r) * normal, r, 1.0f));
    return s;
}

Scene cradleScene(int count, float speed) {
    Scene s = physicsWorld(0.0f, 1.0f, 0.0f, false);
    const float r = 0.5f, gap = 0.05f;  // the striker starts 5 cm from the touching row
    s.objects.push_back(dynamicSphere({-2.0f * r - gap, 0, 0}, r, 1.0f, {speed, 0, 0}));
    for (int i = 0; i < count; ++i)
        s.objects.push_back(dynamicSphere({2.0f * r * float(i), 0, 0}, r, 1.0f));
    return s;
}

namespace {

// The slope of slopeScene and tubeSlopeScene, without its body; `*place` is the point `lift`
// above its top face, 3 m up the slope from its middle.
Scene plankScene(float degrees, float friction, float lift, glm::vec3* place) {
    Scene s = physicsWorld(9.81f, 0.0f, friction, false);
    s.world.rolling = 0.0f;
    Object plank = staticBox({}, {20.0f, 0.5f, 2.0f});
    plank.rot = {0.0f, 0.0f, degrees};
    s.objects.push_back(plank);
    const float t = degrees * float(M_PI) / 180.0f;
    const glm::vec3 along(std::cos(t), std::sin(t), 0.0f), up(-std::sin(t), std::cos(t), 0.0f);
    *place = 3.0f * along + (0.5f + lift) * up;
    return s;
}

}  // namespace

Scene slopeScene(float degrees, float friction, Object body) {
    const float lift = body.type == ShapeType::Box ? body.size.y : body.radius;
    Scene s = plankScene(degrees, friction, lift, &body.pos);
    if (body.type == ShapeType::Box) body.rot = {0.0f, 0.0f, degrees};
    s.objects.push_back(body);
    return s;
}

Scene tubeSlopeScene(float degrees, float friction, float outer, float inner) {
    glm::vec3 place;
    Scene s = plankScene(degrees, friction, outer, &place);
    const int g = addGroup(s, "tube", place, {90.0f, 0.0f, 0.0f}, 1.0f);
    Object wall;
    wall.type = ShapeType::Cylinder;
    wall.radius = outer;
    wall.height = 0.6f;
    Object bore = wall;
    bore.radius = inner;
    bore.height = 0.8f;  // longer: no skin left over either end
    bore.op = CsgOp::Subtract;
    addMember(s, g, wall);
    addMember(s, g, bore);
    return s;
}

Scene boxStackScene(int count) {
    Scene s = physicsWorld(9.81f, 0.3f, 0.6f, true);
    for (int k = 0; k < count; ++k)
        s.objects.push_back(dynamicBox({0, 0.5f + float(k), 0}, {0.5f, 0.5f, 0.5f}));
    return s;
}

Scene pyramidScene(int base) {
    Scene s = physicsWorld(9.81f, 0.0f, 0.6f, true);
    for (int row = 0; row < base; ++row)
        for (int k = 0; k < base - row; ++k)
            s.objects.push_back(dynamicBox(
                {0.5f * float(k) - 0.25f * float(base - row - 1), 0.25f + 0.5f * float(row), 0.0f},
                glm::vec3(0.25f)));
    return s;
}

Scene thinBoxScene(float speed) {
    Scene s = physicsWorld(0.0f, 0.0f, 0.3f, false);
    s.objects.push_back(staticBox({2.0f, 0, 0}, {0.05f, 2.0f, 2.0f}));
    Object thin = dynamicBox({0, 0, 0}, {0.025f, 0.3f, 0.3f});
    thin.vel = {speed, 0, 0};
    s.objects.push_back(thin);
    return s;
}

Scene thinBodiesBin(std::uint32_t seed) {
    Scene s = physicsWorld(9.81f, 0.8f, 0.3f, true);
    s.objects.push_back(staticBox({0, -0.5f, 0}, {3, 0.5f, 3}));
    s.objects.push_back(staticBox({3.5f, 1, 0}, {0.5f, 2, 3}));
    s.objects.push_back(staticBox({-3.5f, 1, 0}, {0.5f, 2, 3}));
    const ShapeType types[] = {ShapeType::Sphere,   ShapeType::Box,      ShapeType::Torus,
                               ShapeType::Capsule,  ShapeType::Cylinder, ShapeType::Cone,
                               ShapeType::Ellipsoid};
    Lcg rng{seed};
    auto vec = [&](float lo, float hi) {
        return glm::vec3(rng.range(lo, hi), rng.range(lo, hi), rng.range(lo, hi));
    };
    const int bodies = 2 + int(rng.range(0.0f, 6.0f));
    for (int i = 0; i < bodies; ++i) {
        Object o = dynamicSphere({rng.range(-1, 1), 1.6f + 3.2f * float(i), rng.range(-1, 1)}, 1.0f,
                                 std::pow(10.0f, rng.range(-2, 2)));
        o.type = types[int(rng.range(0.0f, 7.0f))];
        const bool thin = rng.next() < 0.5f;
        const float across = thin ? rng.range(0.005f, 0.05f) : rng.range(0.1f, 0.5f);
        const float along = thin ? rng.range(0.5f, 3.0f) : rng.range(0.1f, 0.6f);
        // Every shape `along` long: a sphere a third as wide, a torus across its ring.
        o.radius = o.type == ShapeType::Sphere  ? along / 6.0f
                   : o.type == ShapeType::Torus ? along / 2.0f
                                                : across;
        o.minor = std::min(across, along / 4.0f);
        o.height = along;
        o.size = {across, along / 2.0f, across};
        o.rot = vec(-90, 90);
        const float speed = rng.next() < 0.5f ? 30.0f : 3.0f;
        o.vel = vec(-speed, speed);
        o.spin = vec(-10, 10);
        s.objects.push_back(o);
    }
    return s;
}

Scene stackScene(float massRatio) {
    Scene s = physicsWorld(9.81f, 0.0f, 0.3f, true);
    const float r = 0.5f;
    addWalls(s, 1.02f * r, 6.0f * r, 0.2f);
    s.objects.push_back(dynamicSphere({0, r, 0}, r, 1.0f));
    s.objects.push_back(dynamicSphere({0, 3.0f * r, 0}, r, massRatio));
    return s;
}

Scene tunnelScene(float speed, float angleDegrees) {
    Scene s = physicsWorld(0.0f, 0.5f, 0.3f, false);
    s.objects.push_back(staticBox({0, 0, 0}, {2.0f, 2.0f, 0.01f}));  // 2 cm thick
    const float a = angleDegrees * float(M_PI) / 180.0f;
    const glm::vec3 dir(std::sin(a), 0, std::cos(a));
    s.objects.push_back(dynamicSphere(-3.0f * dir, 0.05f, 0.1f, speed * dir));
    return s;
}

Scene restingScene(float radius, float x) {
    Scene s = physicsWorld(9.81f, 0.5f, 0.3f, true);
    s.objects.push_back(dynamicSphere({x, radius, 0}, radius, sphereMass(radius)));
    return s;
}

Scene pileScene(int count, std::uint32_t seed, float r) {
    Scene s = physicsWorld(9.81f, 0.3f, 0.5f, true);
    Lcg rng{seed};
    const float spacing = 2.4f * r;
    const int side = std::max(2, int(std::ceil(std::sqrt(count / 8.0f))));  // about 8 layers
    const float inner = 0.5f * spacing * float(side) + 0.3f * r;
    addWalls(s, inner, 0.5f * spacing * float(count / (side * side) + 2), 0.1f);
    for (int i = 0; i < count; ++i) {
        const int layer = i / (side * side), row = (i / side) % side, col = i % side;
        const glm::vec3 pos(
            spacing * (float(col) - 0.5f * float(side - 1)) + rng.range(-0.1f, 0.1f) * r,
            r + 0.5f * r + spacing * float(layer),
            spacing * (float(row) - 0.5f * float(side - 1)) + rng.range(-0.1f, 0.1f) * r);
        const float radius = r * rng.range(0.8f, 1.0f);
        s.objects.push_back(dynamicSphere(pos, radius, sphereMass(radius)));
    }
    return s;
}

// The same bin as pileScene, filled with boxes, capsules, cylinders and spheres of about r, each
// turned at random: the mixed pile the rigid bodies are timed on against Bullet. The type
// follows col + row + layer, so that each body's neighbours along every axis are of other
// types whatever the bin's width (by index, a width divisible by 4 stacked columns of one type).
Scene mixedPileScene(int count, std::uint32_t seed, float r) {
    Scene s = physicsWorld(9.81f, 0.3f, 0.5f, true);
    Lcg rng{seed};
    const Bin bin = addBin(s, count, 2.4f * r, r);
    const ShapeType types[4] = {ShapeType::Box, ShapeType::Capsule, ShapeType::Cylinder,
                                ShapeType::Sphere};
    for (int i = 0; i < count; ++i) {
        Object o = dynamicSphere(bin.place(i, r + 0.5f * r), r * rng.range(0.8f, 1.0f), 1.0f);
        const glm::ivec3 cell = bin.cell(i);
        o.type = types[(cell.x + cell.y + cell.z) % 4];
        o.size = glm::vec3(0.7f * o.radius);
        o.height = o.radius;
        if (o.type == ShapeType::Capsule) o.radius *= 0.5f;
        o.rot = {rng.range(0.0f, 180.0f), rng.range(0.0f, 180.0f), rng.range(0.0f, 180.0f)};
        s.objects.push_back(o);
    }
    return s;
}

Scene gasScene(int count, std::uint32_t seed) {
    Scene s = physicsWorld(0.0f, 1.0f, 0.0f, false);
    Lcg rng{seed};
    const float r = 0.1f, inner = 1.0f, t = 0.2f, len = inner + 2.0f * t;
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {-1.0f, 1.0f}) {
            glm::vec3 pos(0.0f), half(len);
            pos[axis] = sign * (inner + t);
            half[axis] = t;
            s.objects.push_back(staticBox(pos, half));
        }
    const int side = int(std::ceil(std::cbrt(float(count))));
    const float spacing = 2.0f * inner / float(side);
    for (int i = 0; i < count; ++i) {
        const glm::vec3 cell(float(i % side), float(i / side % side), float(i / (side * side)));
        const glm::vec3 pos = -glm::vec3(inner) + spacing * (cell + 0.5f);
        const glm::vec3 vel(rng.range(-5, 5), rng.range(-5, 5), rng.range(-5, 5));
        s.objects.push_back(dynamicSphere(pos, r, 1.0f, vel));
    }
    return s;
}

int addGroup(Scene& scene, const std::string& name, glm::vec3 pos, glm::vec3 rot, float mass) {
    Group g;
    g.name = name + std::to_string(scene.groups.size());
    g.first = int(scene.objects.size());
    g.pos = pos;
    g.rot = rot;
    g.mass = mass;
    scene.groups.push_back(g);
    return int(scene.groups.size()) - 1;
}

void addMember(Scene& scene, int group, Object member) {
    member.group = group;
    scene.objects.push_back(member);
}

void addCup(Scene& scene, glm::vec3 pos, float radius, float mass, glm::vec3 rot) {
    const int g = addGroup(scene, "cup", pos, rot, mass);
    Object outer;
    outer.type = ShapeType::Cylinder;
    outer.radius = radius;
    outer.height = 1.6f * radius;
    Object inner = outer;
    inner.radius = 0.88f * radius;
    inner.pos = {0.0f, 0.12f * radius, 0.0f};
    inner.op = CsgOp::Subtract;
    addMember(scene, g, outer);
    addMember(scene, g, inner);
}

// Cups 2.6·r apart, their bounding spheres' (1.28·r) width whatever their turn, and balls
// half as far apart above them.
Scene cupPileScene(int cups, int balls, std::uint32_t seed, float r, bool walls) {
    Scene s = physicsWorld(9.81f, 0.3f, 0.5f, true);
    Lcg rng{seed};
    const float spacing = 2.6f * r, lift = 1.3f * r;
    const int side = std::max(2, int(std::ceil(std::sqrt((cups + balls / 8) / 4.0f))));
    const float inner = 0.5f * spacing * float(side) + 0.3f * r;
    const int cupLayers = (cups + side * side - 1) / (side * side);
    const int ballLayers = (balls + 4 * side * side - 1) / (4 * side * side);
    if (walls) addWalls(s, inner, spacing * float(cupLayers + ballLayers + 1), 0.1f);
    for (int i = 0; i < cups; ++i) {
        const int layer = i / (side * side), row = (i / side) % side, col = i % side;
        const glm::vec3 pos(spacing * (float(col) - 0.5f * float(side - 1)),
                            lift + spacing * float(layer),
                            spacing * (float(row) - 0.5f * float(side - 1)));
        const glm::vec3 rot(rng.range(-30.0f, 30.0f), rng.range(0.0f, 180.0f),
                            rng.range(-30.0f, 30.0f));
        addCup(s, pos, r, 0.5f, rot);
    }
    const float ball = 0.4f * r, top = lift + spacing * float(cupLayers);
    for (int i = 0; i < balls; ++i) {
        const int perLayer = 4 * side * side;
        const int layer = i / perLayer, row = (i / (2 * side)) % (2 * side), col = i % (2 * side);
        s.objects.push_back(
            dynamicSphere({0.5f * spacing * (float(col) - 0.5f * float(2 * side - 1)),
                           top + 2.5f * ball * float(layer),
                           0.5f * spacing * (float(row) - 0.5f * float(2 * side - 1))},
                          ball * rng.range(0.9f, 1.0f), sphereMass(ball)));
    }
    return s;
}

Scene holedBoxScene(const HoledBox& h) {
    Scene s = physicsWorld(9.81f, 0.3f, 0.5f, true);
    const int g = addGroup(s, "holed", {0.0f, 1.0f, 0.0f}, glm::vec3(0.0f), h.mass);
    addMember(s, g, dynamicBox({}, glm::vec3(h.half)));
    Object hole;
    hole.type = ShapeType::Cylinder;
    hole.pos = {float(h.offset), 0.0f, 0.0f};
    hole.radius = float(h.radius);
    hole.height = float(2.0 * h.half.y + 0.4);  // through, and 0.2 m out of either face
    hole.op = CsgOp::Subtract;
    addMember(s, g, hole);
    return s;
}

// The box's moments less the cylinder's (2·b long inside it): V = 8abc − π·r²·2b; the hole's
// centre shifts s_x; S_xx of the hole is its own r²/4 per volume plus the offset's d².
SolidMoments holedBoxMoments(const HoledBox& h) {
    const glm::dvec3 e = h.half;
    const double r = h.radius, d = h.offset;
    const double box = 8.0 * e.x * e.y * e.z, hole = M_PI * r * r * 2.0 * e.y;
    SolidMoments m;
    m.volume = box - hole;
    m.first = {-hole * d, 0.0, 0.0};
    m.second = glm::dmat3(0.0);
    m.second[0][0] = box * e.x * e.x / 3.0 - hole * (r * r / 4.0 + d * d);
    m.second[1][1] = box * e.y * e.y / 3.0 - hole * e.y * e.y / 3.0;
    m.second[2][2] = box * e.z * e.z / 3.0 - hole * r * r / 4.0;
    return m;
}

// The table's origin halfway up it: the top, r × 0.1·r × 0.7·r (half extents), from 0.5·r to
// 0.7·r; legs of radius 0.1·r from −0.7·r up to the top's underside, 0.8·r and 0.5·r in from the
// middle along x and z. The legs' boxes only touch the top's, so the mass comes in closed form.
// All of it lies within 1.42·r of the origin.
void addTable(Scene& scene, glm::vec3 pos, glm::vec3 rot, float r, float mass) {
    const int g = addGroup(scene, "table", pos, rot, mass);
    addMember(scene, g, dynamicBox({0.0f, 0.6f * r, 0.0f}, {r, 0.1f * r, 0.7f * r}));
    for (const float x : {-0.8f * r, 0.8f * r})
        for (const float z : {-0.5f * r, 0.5f * r}) {
            Object o;
            o.type = ShapeType::Cylinder;
            o.pos = {x, -0.1f * r, z};
            o.radius = 0.1f * r;
            o.height = 1.2f * r;
            addMember(scene, g, o);
        }
}

// Tables 3·r apart in every direction, clear of one another whatever their turn, 8 layers deep
// as in pileScene, each turned at random.
Scene tablePileScene(int count, std::uint32_t seed, float r) {
    Scene s = physicsWorld(9.81f, 0.3f, 0.5f, true);
    Lcg rng{seed};
    const Bin bin = addBin(s, count, 3.0f * r, r);
    for (int i = 0; i < count; ++i) {
        const glm::vec3 rot(rng.range(0.0f, 180.0f), rng.range(0.0f, 180.0f),
                            rng.range(0.0f, 180.0f));
        addTable(s, bin.place(i, 1.5f * r), rot, r, 1.0f);
    }
    return s;
}

}  // namespace mb
