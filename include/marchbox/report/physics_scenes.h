// marchbox/report/physics_scenes.h — the scenes the physics tests and report share.
//
// Each builds a whole Scene: the analytic cases (free fall, bounce, collisions, slide to roll)
// and the stiff and extreme ones (stacks, piles, gas, tunnelling). Randomness is a fixed LCG, so
// every build gives the same scene on every platform.
#pragma once

#include "marchbox/scene/scene.h"

#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace mb {

// An empty world: no objects, the given gravity, restitution and friction, ground at y = 0.
Scene physicsWorld(float gravity, float restitution, float friction, bool ground);
Object dynamicSphere(glm::vec3 pos, float radius, float mass, glm::vec3 vel = glm::vec3(0.0f));
Object staticBox(glm::vec3 pos, glm::vec3 halfExtents);

// Static walls around the x-z rectangle |x|, |z| < inner, from the ground to `height`.
void addWalls(Scene& scene, float inner, float height, float thickness);

Scene freeFallScene(float height);                   // no ground; one sphere at rest
Scene projectileScene(glm::vec3 vel);                // no ground; launched from the origin
Scene bounceScene(float height, float restitution);  // dropped from its lowest point at height
Scene headOnScene(float restitution, float m1, float m2, float v1,
                  float v2);                    // along x, no gravity
Scene slideScene(float speed, float friction);  // resting on the ground, sliding along +x
Scene rollScene(float speed, float rolling);    // on the ground, rolling without slip along +x
Scene spinScene(float spin, float friction);    // on the ground, at rest, spinning about −z
Scene cradleScene(int count, float speed);      // a touching row along x, and a striker
// A box (top at y = 1) with a sphere of bowlRadius subtracted from its top, the bowl's bottom
// 0.3·bowlRadius deep; a sphere of ballRadius at rest on the bowl, `degrees` from its bottom,
// on the +x side. Its centre swings on a circle of bowlRadius − ballRadius about bowlCentre().
Scene bowlScene(float bowlRadius, float ballRadius, float degrees, float friction);
glm::vec3 bowlCentre(float bowlRadius);
// A 40 m plank tilted `degrees` about z (its top rises along +x), no ground; a sphere of 0.2 at
// rest on its top face, 3 m up the slope from its middle.
Scene rampScene(float degrees, float friction, float rolling);
// A 40 m plank tilted `degrees` about z (its top rises along +x), no ground; `body` at rest on
// its top face 3 m up the slope from its middle, a box turned with the plank.
Scene slopeScene(float degrees, float friction, Object body);
// The same slope with a tube on it instead: a dynamic group of 1 kg, a cylinder of radius `outer`
// and 0.6 m long less a coaxial one of radius `inner`, 0.8 m long, its axis along z (across
// the slope). Rolling without slip it goes down at a = g·sin θ / (1 + (r0² + r1²)/(2·r0²)).
Scene tubeSlopeScene(float degrees, float friction, float outer, float inner);
Object dynamicBox(glm::vec3 pos, glm::vec3 halfExtents, float mass = 1.0f);
Scene boxStackScene(int count);  // unit boxes one on another on the ground, μ = 0.6, e = 0.3
Scene pyramidScene(int base);    // boxes of 0.5 m, `base` wide at the bottom, μ = 0.6, e = 0
// A box 5 cm thick at `speed` along +x at a static wall 10 cm thick 2 m away; no gravity.
Scene thinBoxScene(float speed);
// Bin `seed` of the thin fast bodies: the ground and two walls 6 m apart, and 2 to 7 bodies of
// every shape thrown in at up to 30 m/s, half of them thin (0.5 to 3 m long, 5 to 50 mm across),
// of 0.01 to 100 kg, spinning, each 3.2 m above the last so that none touches another or the
// ground at the start.
Scene thinBodiesBin(std::uint32_t seed);
Scene stackScene(float massRatio);                   // heavy on light, in a well barely wider
Scene tunnelScene(float speed, float angleDegrees);  // at a 2 cm plate, angle from its normal
Scene restingScene(float radius, float x);           // at rest on the ground at x
// Dropped into a walled bin, about 8 layers deep: radii from 0.8·r to r.
Scene pileScene(int count, std::uint32_t seed, float r = 0.1f);
// The same bin with boxes, capsules, cylinders and spheres of about r in turn, each turned.
Scene mixedPileScene(int count, std::uint32_t seed, float r = 0.2f);
Scene gasScene(int count, std::uint32_t seed);  // elastic, frictionless, in a closed box
// Adds a top-level group named `name` and its index, and returns that index; addMember gives it
// its members, which must follow it at once (the scene's tree order).
int addGroup(Scene& scene, const std::string& name, glm::vec3 pos, glm::vec3 rot, float mass);
void addMember(Scene& scene, int group, Object member);
// A dynamic cup (a group, named "cupN" for the Nth group) standing at pos, turned by rot: a
// cylinder of `radius`, 1.6·radius tall, less a cylinder of 0.88·radius from 0.12·radius above
// its bottom to 0.12·radius above its rim. Its inner floor is 0.12·radius above its bottom.
void addCup(Scene& scene, glm::vec3 pos, float radius, float mass, glm::vec3 rot = glm::vec3(0.0f));
// A walled bin, as pileScene's, with `cups` cups of radius r, each turned at random, and above
// them `balls` balls of 0.4·r: dropped cups and balls, layer by layer (version 3 groups).
// `walls` false: the same heap on the open ground, with no static object.
Scene cupPileScene(int cups, int balls, std::uint32_t seed, float r = 0.25f, bool walls = true);

// A box of half extents `half` with a hole of `radius` through it along y, `offset` off its
// middle along x: a dynamic group at (0, 1, 0), above the ground, whose mass properties are
// integrated (the hole carves the box), and their closed form.
struct HoledBox {
    glm::dvec3 half{0.5, 0.3, 0.4};
    double radius = 0.15, offset = 0.1;
    float mass = 2.0f;
};
Scene holedBoxScene(const HoledBox& box);
// A solid's volume V = ∫dV (m³), first moment ∫x dV (m⁴) and second ∫x·xᵀ dV (m⁵), about the
// frame it is given in.
struct SolidMoments {
    double volume = 0.0;
    glm::dvec3 first{0.0};
    glm::dmat3 second{0.0};
};
SolidMoments holedBoxMoments(const HoledBox& box);  // in the group's frame, in closed form

// A table (a dynamic group of union members: a box top on four cylinder legs, about 2·r by
// 1.4·r by 1.4·r), its origin halfway up, at pos, turned by rot.
void addTable(Scene& scene, glm::vec3 pos, glm::vec3 rot, float r, float mass);
// `count` tables of size r dropped into pileScene's walled bin, each turned at random.
Scene tablePileScene(int count, std::uint32_t seed, float r = 0.25f);

}  // namespace mb
