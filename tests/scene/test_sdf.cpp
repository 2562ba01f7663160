// test_sdf.cpp — the CPU SDF mirror against the closed-form distances.
#include "marchbox/scene/sdf.h"

#include <gtest/gtest.h>
#include <cmath>

using namespace mb;
using glm::vec3;

TEST(Sdf, SphereIsDistanceToCentreMinusRadius) {
    EXPECT_FLOAT_EQ(sdSphere(vec3(3, 4, 0), 1.0f), 4.0f);
    EXPECT_FLOAT_EQ(sdSphere(vec3(0), 2.0f), -2.0f);
}

TEST(Sdf, BoxOutsideFaceEdgeCornerAndInside) {
    vec3 b(1, 2, 3);
    EXPECT_FLOAT_EQ(sdBox(vec3(3, 0, 0), b), 2.0f);             // face
    EXPECT_FLOAT_EQ(sdBox(vec3(2, 3, 0), b), std::sqrt(2.0f));  // edge
    EXPECT_FLOAT_EQ(sdBox(vec3(2, 3, 4), b), std::sqrt(3.0f));  // corner
    EXPECT_FLOAT_EQ(sdBox(vec3(0.5f, 0, 0), b), -0.5f);         // inside, nearest face x
}

TEST(Sdf, TorusRingInXZPlane) {
    EXPECT_FLOAT_EQ(sdTorus(vec3(2, 0, 0), 2.0f, 0.5f), -0.5f);  // on the ring's core
    EXPECT_FLOAT_EQ(sdTorus(vec3(0, 0, 0), 2.0f, 0.5f), 1.5f);   // centre of the hole
    EXPECT_FLOAT_EQ(sdTorus(vec3(0, 3, 2), 2.0f, 0.5f), 2.5f);   // above the ring
}

TEST(Sdf, CapsuleSegmentAlongY) {
    EXPECT_FLOAT_EQ(sdCapsule(vec3(0, 2, 0), 2.0f, 0.5f), 0.5f);  // above the top cap centre (y=1)
    EXPECT_FLOAT_EQ(sdCapsule(vec3(1, 0.3f, 0), 2.0f, 0.5f), 0.5f);  // beside the segment
}

TEST(Sdf, CylinderCappedAlongY) {
    EXPECT_FLOAT_EQ(sdCylinder(vec3(2, 0, 0), 2.0f, 1.0f), 1.0f);  // side
    EXPECT_FLOAT_EQ(sdCylinder(vec3(0, 3, 0), 2.0f, 1.0f), 2.0f);  // cap
    EXPECT_FLOAT_EQ(sdCylinder(vec3(4, 5, 0), 2.0f, 1.0f), 5.0f);  // rim: (3,4) away
    EXPECT_FLOAT_EQ(sdCylinder(vec3(0, 0, 0), 2.0f, 1.0f), -1.0f);
}

TEST(Sdf, SharpOperatorsAreMinAndMax) {
    EXPECT_FLOAT_EQ(opUnion(1, 2, 0).x, 1);
    EXPECT_FLOAT_EQ(opSubtract(1, 2, 0).x, 1);   // max(1, -2)
    EXPECT_FLOAT_EQ(opSubtract(1, -3, 0).x, 3);  // inside b: carved
    EXPECT_FLOAT_EQ(opIntersect(1, 2, 0).x, 2);
}

TEST(Sdf, SmoothUnionLowersByQuarterKWhereEqualAndNotBeyondK) {
    EXPECT_FLOAT_EQ(opUnion(1, 1, 0.4f).x, 1 - 0.1f);
    EXPECT_FLOAT_EQ(opUnion(1, 1.5f, 0.4f).x, 1);
}

TEST(Sdf, EulerRotationIsRzRyRx) {
    glm::mat3 r = rotationFromEuler(vec3(0, 0, 90));
    vec3 x = r * vec3(1, 0, 0);
    EXPECT_NEAR(x.y, 1.0f, 1e-6f);
    glm::mat3 r2 = rotationFromEuler(vec3(90, 90, 0));  // Ry(90)·Rx(90): y -> z -> x
    vec3 y = r2 * vec3(0, 1, 0);
    EXPECT_NEAR(y.x, 1.0f, 1e-6f);
}

TEST(Sdf, BoundingSphereSkipDoesNotChangeTheMap) {
    Scene s;
    s.materials.push_back({});
    Object a;
    a.type = ShapeType::Box;
    a.pos = vec3(0, 1, 0);
    Object b;
    b.type = ShapeType::Sphere;
    b.pos = vec3(0.4f, 1.4f, 0);
    b.radius = 0.4f;
    b.op = CsgOp::Subtract;
    b.blend = 0.05f;
    Object c;
    c.type = ShapeType::Torus;
    c.pos = vec3(3, 1, 0);
    c.radius = 1;
    c.minor = 0.2f;
    c.blend = 0.3f;
    s.objects = {a, b, c};
    SceneSdf sdf = makeSceneSdf(s);
    for (int i = 0; i < 2000; ++i) {
        vec3 p(std::fmod(i * 0.37f, 6.0f) - 2, std::fmod(i * 0.53f, 3.0f),
               std::fmod(i * 0.71f, 4.0f) - 2);
        float exact = 1e10f;
        for (const SdfObject& o : sdf.objects) {
            float d = sdObject(o, p);
            exact = o.op == CsgOp::Union      ? opUnion(exact, d, o.blend).x
                    : o.op == CsgOp::Subtract ? opSubtract(exact, d, o.blend).x
                                              : opIntersect(exact, d, o.blend).x;
        }
        ASSERT_FLOAT_EQ(mapObjects(sdf, p).d, exact) << "at " << p.x << "," << p.y << "," << p.z;
    }
}

TEST(Sdf, CastRayHitsTheNearestObjectAndReportsInsideAtOnce) {
    Scene s;
    s.materials.push_back({});
    Object a;
    a.pos = vec3(0, 1, 5);
    a.radius = 1;
    s.objects = {a};
    SceneSdf sdf = makeSceneSdf(s);
    RayHit h = castRay(sdf, vec3(0, 1, 0), vec3(0, 0, 1), 256, 1e-4f, 100);
    ASSERT_TRUE(h.hit);
    EXPECT_EQ(h.object, 0);
    EXPECT_NEAR(h.t, 4.0f, 1e-3f);
    RayHit inside = castRay(sdf, vec3(0, 1, 5), vec3(0, 0, 1), 256, 1e-4f, 100);
    EXPECT_TRUE(inside.hit);
    EXPECT_EQ(inside.t, 0.0f);
    RayHit down = castRay(sdf, vec3(0, 1, 0), vec3(0, -1, 0), 256, 1e-4f, 100);
    EXPECT_EQ(down.object, kHitGround);
}
