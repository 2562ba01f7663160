// test_scene_parts.cpp — the parts of an animated export: the static solids keep their own
// chain with the bodies taken out, and a body alone in its own frame is the same solid as in the
// scene, seen from its pos and turn.
#include "scene_parts.h"

#include "marchbox/scene/sdf.h"

#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>

using namespace mb;
using glm::vec3;

namespace {

Object object(ShapeType type, vec3 pos, int group = -1) {
    Object o;
    o.type = type;
    o.pos = pos;
    o.group = group;
    o.isStatic = group < 0;  // members carry no motion
    return o;
}

Group group(const std::string& name, vec3 pos, int first, int parent = -1) {
    Group g;
    g.name = name;
    g.pos = pos;
    g.first = first;
    g.parent = parent;
    g.isStatic = true;
    return g;
}

// In tree order: a static box; a dynamic ball; a static group "table" of a top and a nested
// group "legs" of two legs; a dynamic group "cup" carved by a member; a static torus.
Scene mixedScene() {
    Scene s;
    s.materials.resize(3);
    s.objects.push_back(object(ShapeType::Box, vec3(0, 0.5f, 0)));
    Object ball = object(ShapeType::Sphere, vec3(1, 2, 0));
    ball.isStatic = false;
    ball.name = "ball";
    s.objects.push_back(ball);
    s.groups.push_back(group("table", vec3(-2, 0, 1), 2));
    s.objects.push_back(object(ShapeType::Box, vec3(0, 0.8f, 0), 0));
    s.groups.push_back(group("legs", vec3(0, 0.4f, 0), 3, 0));
    s.objects.push_back(object(ShapeType::Cylinder, vec3(-0.4f, 0, 0), 1));
    s.objects.push_back(object(ShapeType::Cylinder, vec3(0.4f, 0, 0), 1));
    Group cup = group("cup", vec3(2, 1, -1), 5);
    cup.isStatic = false;
    cup.orient = glm::normalize(glm::quat(0.9f, 0.2f, -0.3f, 0.1f));
    cup.op = CsgOp::Subtract;  // against the scene: dropped in its own part
    s.groups.push_back(cup);
    s.objects.push_back(object(ShapeType::Cylinder, vec3(0, 0, 0), 2));
    Object hole = object(ShapeType::Cylinder, vec3(0, 0.1f, 0), 2);
    hole.radius = 0.4f;
    hole.op = CsgOp::Subtract;
    s.objects.push_back(hole);
    s.objects.push_back(object(ShapeType::Torus, vec3(0, 0.3f, 3)));
    return s;
}

// Points through and around the scene, on a lattice with no symmetry about the shapes.
std::vector<vec3> probes(vec3 centre, float reach) {
    std::vector<vec3> points;
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 9; ++j)
            for (int k = 0; k < 9; ++k)
                points.push_back(centre + reach * (vec3(i, j, k) / 4.0f - 1.0f) + vec3(0.013f));
    return points;
}

}  // namespace

TEST(SceneParts, DynamicBodiesInTreeOrderWithTheirNames) {
    const Scene s = mixedScene();
    const std::vector<BodyRef> bodies = dynamicBodies(s);
    ASSERT_EQ(bodies.size(), 2u);
    EXPECT_FALSE(bodies[0].group);
    EXPECT_EQ(bodies[0].index, 1);
    EXPECT_TRUE(bodies[1].group);
    EXPECT_EQ(bodies[1].index, 2);
    EXPECT_EQ(bodyName(s, bodies[0]), "ball");
    EXPECT_EQ(bodyName(s, bodies[1]), "cup");
    EXPECT_EQ(bodyName(s, {false, 0}), "box 0");
}

TEST(SceneParts, StaticPartKeepsTheRestRenumbered) {
    const Scene s = mixedScene();
    const Scene part = staticPart(s);
    ASSERT_EQ(part.objects.size(), 5u);  // box, table top, two legs, torus
    ASSERT_EQ(part.groups.size(), 2u);   // table, legs
    EXPECT_EQ(part.groups[0].name, "table");
    EXPECT_EQ(part.groups[0].first, 1);
    EXPECT_EQ(part.groups[1].parent, 0);
    EXPECT_EQ(part.groups[1].first, 2);
    EXPECT_EQ(part.objects[1].group, 0);
    EXPECT_EQ(part.objects[3].group, 1);
    EXPECT_EQ(part.objects[4].type, ShapeType::Torus);
    EXPECT_EQ(part.objects[4].group, -1);
    EXPECT_EQ(groupEnd(part, 0), 4);
    // The union of what stays, evaluated piece by piece in the whole scene.
    const SceneSdf a = makeSceneSdf(part);
    for (vec3 p : probes(vec3(0, 1, 1), 3.0f)) {
        const float want =
            std::min({sdObject(makeSdfObject(s.objects[0]), p), mapGroup(makeSceneSdf(s), 0, p).d,
                      sdObject(makeSdfObject(s.objects[7]), p)});
        ASSERT_NEAR(mapObjects(a, p).d, want, 1e-5f) << p.x << "," << p.y << "," << p.z;
    }
}

TEST(SceneParts, ABodyAloneIsItsSolidInItsOwnFrame) {
    const Scene s = mixedScene();
    const SceneSdf whole = makeSceneSdf(s);
    for (BodyRef body : dynamicBodies(s)) {
        const Scene alone = bodyAtOrigin(s, body);
        const SceneSdf sdf = makeSceneSdf(alone);
        const Placement pose = bodyPose(s, body);
        for (vec3 local : probes(vec3(0), 1.0f)) {
            const vec3 world = pose.pos + pose.turn * local;
            const float want = body.group ? mapGroup(whole, body.index, world).d
                                          : sdObject(whole.objects[size_t(body.index)], world);
            ASSERT_NEAR(mapObjects(sdf, local).d, want, 1e-5f) << bodyName(s, body);
        }
        EXPECT_EQ(alone.materials.size(), s.materials.size());
    }
}
