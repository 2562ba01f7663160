// test_gizmo.cpp — the view's handles: projection against the camera's own rays, hit testing,
// and drags that keep the grabbed point under the mouse.
#include "marchbox/editor/gizmo.h"

#include "marchbox/scene/camera.h"
#include "marchbox/scene/sdf.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

using namespace mb;

namespace {

const glm::vec2 kView(320, 180);
const Camera kOblique{{3, 4, -6}, {0, 0.5f, 0}, 50};  // looks down on the origin from aside
const Camera kFront{{0, 0, -5}, {0, 0, 0}, 50};       // looks along +z at the origin
const glm::vec3 kCentre(0.2f, 0.5f, 0.1f);

glm::vec2 pixelOf(const Camera& c, glm::vec3 p) {
    glm::vec2 px(-1.0f);
    EXPECT_TRUE(projectToPixel(c, p, kView, &px));
    return px;
}

GizmoFrame worldFrame(const Camera& c) { return gizmoFrame(c, kCentre, glm::mat3(1.0f), kView); }

void expectNear(glm::vec3 a, glm::vec3 b, float tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

// Drags handle h of frame f from world point `from` to world point `to`, both on screen.
GizmoDelta drag(const Camera& c, const GizmoFrame& f, GizmoHandle h, glm::vec3 from, glm::vec3 to,
                bool snap = false) {
    GizmoDrag d;
    EXPECT_TRUE(d.begin(c, f, h, pixelOf(c, from), kView));
    GizmoDelta out;
    EXPECT_TRUE(d.follow(c, pixelOf(c, to), kView, snap, &out));
    return out;
}

}  // namespace

TEST(Gizmo, ProjectionIsTheInverseOfTheCamerasRay) {
    // Independent of projectToPixel's algebra: the camera's own ray through the pixel found
    // must point at the world point.
    const glm::vec3 points[] = {{0, 0, 0}, {1, 2, 3}, {-2, 0.3f, 1}, {4, 0, -2}};
    for (glm::vec3 p : points) {
        glm::vec2 px = pixelOf(kOblique, p);
        glm::vec3 ray = cameraRay(cameraBasis(kOblique), px, kView);
        EXPECT_GT(glm::dot(ray, glm::normalize(p - kOblique.pos)), 0.999999f) << p.x;
    }
    glm::vec2 px;
    EXPECT_FALSE(projectToPixel(kOblique, kOblique.pos - (kOblique.target - kOblique.pos), kView,
                                &px));  // behind the camera
}

TEST(Gizmo, HandlesKeepTheirLengthOnScreenAtAnyDistance) {
    for (float z : {-1.0f, 4.0f, 30.0f}) {
        const glm::vec3 centre(0, 0, z);
        GizmoFrame f = gizmoFrame(kFront, centre, glm::mat3(1.0f), kView);
        float onScreen = glm::distance(pixelOf(kFront, centre),
                                       pixelOf(kFront, centre + f.length * glm::vec3(0, 1, 0)));
        EXPECT_NEAR(onScreen, GizmoSettings{}.lengthPixels, 0.5f) << z;
    }
}

TEST(Gizmo, HitFindsTheHandleUnderTheMouse) {
    const GizmoFrame f = worldFrame(kOblique);
    const float L = f.length;
    for (int i = 0; i < 3; ++i) {
        glm::vec3 axis = f.axes[i];
        GizmoHandle h = hitGizmo(kOblique, f, GizmoMode::Move,
                                 pixelOf(kOblique, kCentre + 0.8f * L * axis), kView);
        EXPECT_EQ(h, (GizmoHandle{HandleKind::Axis, i}));
        h = hitGizmo(kOblique, f, GizmoMode::Scale, pixelOf(kOblique, kCentre + 0.9f * L * axis),
                     kView);
        EXPECT_EQ(h, (GizmoHandle{HandleKind::Scale, i}));
        h = hitGizmo(kOblique, f, GizmoMode::Rotate, pixelOf(kOblique, ringPoint(f, i, 2.0f)),
                     kView);
        EXPECT_EQ(h, (GizmoHandle{HandleKind::Ring, i}));
        const glm::vec3 square = 0.4f * L * (f.axes[(i + 1) % 3] + f.axes[(i + 2) % 3]);
        h = hitGizmo(kOblique, f, GizmoMode::Move, pixelOf(kOblique, kCentre + square), kView);
        EXPECT_EQ(h, (GizmoHandle{HandleKind::Plane, i}));
    }
    // Beside the handles, and past an axis's end by more than pickPixels.
    const glm::vec2 centre = pixelOf(kOblique, kCentre);
    EXPECT_EQ(hitGizmo(kOblique, f, GizmoMode::Move, centre + glm::vec2(0, -70), kView).kind,
              HandleKind::None);
    EXPECT_EQ(hitGizmo(kOblique, f, GizmoMode::Move,
                       pixelOf(kOblique, kCentre + 1.3f * L * f.axes[0]), kView)
                  .kind,
              HandleKind::None);
}

TEST(Gizmo, ClosestPointOfALineToARay) {
    float t = 0;
    // The x axis, and a ray straight down through (2, 5, 1): nearest at x = 2.
    ASSERT_TRUE(closestOnLine({0, 0, 0}, {1, 0, 0}, {2, 5, 1}, {0, -1, 0}, &t));
    EXPECT_NEAR(t, 2.0f, 1e-6f);
    // A line through (1, 0, 0) along z, a ray along -x through (5, 0, 3): they cross at z = 3.
    ASSERT_TRUE(closestOnLine({1, 0, 0}, {0, 0, 1}, {5, 0, 3}, {-1, 0, 0}, &t));
    EXPECT_NEAR(t, 3.0f, 1e-6f);
    EXPECT_FALSE(closestOnLine({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, &t));  // parallel
}

TEST(Gizmo, AxisDragKeepsTheGrabbedPointUnderTheMouse) {
    const GizmoFrame f = worldFrame(kOblique);
    for (int i = 0; i < 3; ++i) {
        const glm::vec3 a = f.axes[i];
        GizmoDelta d = drag(kOblique, f, {HandleKind::Axis, i}, kCentre + 0.7f * f.length * a,
                            kCentre + 1.9f * f.length * a);
        expectNear(d.move, 1.2f * f.length * a, 1e-3f * f.length);
        EXPECT_EQ(d.scaleAxis, -1);
    }
}

TEST(Gizmo, CtrlSnapsMovesToWholeSteps) {
    const GizmoFrame f = worldFrame(kOblique);
    const glm::vec3 x = f.axes[0];
    GizmoDelta d = drag(kOblique, f, {HandleKind::Axis, 0}, kCentre + 0.5f * x,
                        kCentre + 0.5f * x + 0.337f * x, true);
    EXPECT_NEAR(d.move.x, 0.3f, 1e-6f);
    d = drag(kOblique, f, {HandleKind::Plane, 1}, kCentre + glm::vec3(0.1f, 0, 0.1f),
             kCentre + glm::vec3(0.36f, 0, -0.12f), true);
    expectNear(d.move, {0.3f, 0.0f, -0.2f}, 1e-6f);
}

TEST(Gizmo, PlaneDragStaysOnThePlaneUnderTheMouse) {
    const GizmoFrame f = worldFrame(kOblique);
    const glm::vec3 from = kCentre + glm::vec3(0.1f, 0, 0.1f),
                    to = kCentre + glm::vec3(0.9f, 0, -0.6f);
    GizmoDelta d = drag(kOblique, f, {HandleKind::Plane, 1}, from, to);
    expectNear(d.move, to - from, 1e-3f);
}

TEST(Gizmo, RingDragTurnsTheGrabbedPointToTheMouse) {
    // Face on, the ring's angle on screen is its angle in the world, whichever way its axis
    // points: +z looks away from the camera, so the screen turns the other way round.
    for (const Camera& c : {kFront, Camera{{0, 0, 5}, {0, 0, 0}, 50}}) {
        const GizmoFrame f = gizmoFrame(c, glm::vec3(0), glm::mat3(1.0f), kView);
        GizmoDelta d =
            drag(c, f, {HandleKind::Ring, 2}, ringPoint(f, 2, 0.3f), ringPoint(f, 2, 1.1f));
        expectNear(d.turn * ringPoint(f, 2, 0.3f), ringPoint(f, 2, 1.1f), 1e-3f * f.length);
        EXPECT_NEAR(glm::angle(d.turn), 0.8f, 1e-3f);
    }
}

TEST(Gizmo, CtrlSnapsTurnsToFifteenDegrees) {
    const GizmoFrame f = gizmoFrame(kFront, glm::vec3(0), glm::mat3(1.0f), kView);
    GizmoDelta d = drag(kFront, f, {HandleKind::Ring, 2}, ringPoint(f, 2, 0.0f),
                        ringPoint(f, 2, glm::radians(37.0f)), true);
    EXPECT_NEAR(glm::degrees(glm::angle(d.turn)), 30.0f, 1e-3f);
}

TEST(Gizmo, ScaleDragSizesByTheRatioOfDistancesFromTheCentre) {
    const GizmoFrame f = worldFrame(kOblique);
    const glm::vec3 z = f.axes[2];
    GizmoDelta d = drag(kOblique, f, {HandleKind::Scale, 2}, kCentre + 0.5f * f.length * z,
                        kCentre + 1.0f * f.length * z);
    EXPECT_EQ(d.scaleAxis, 2);
    EXPECT_NEAR(d.scale, 2.0f, 1e-3f);
    d = drag(kOblique, f, {HandleKind::Scale, 2}, kCentre + 0.5f * f.length * z,
             kCentre + 0.73f * f.length * z, true);
    EXPECT_NEAR(d.scale, 1.5f, 1e-6f);
}

TEST(Gizmo, ScaleSizesWhatEachShapeHasAlongThatAxis) {
    GizmoDelta d;
    d.scale = 2.0f;
    Object box;
    box.type = ShapeType::Box;
    box.size = {0.5f, 0.6f, 0.7f};
    d.scaleAxis = 2;
    EXPECT_EQ(applyGizmo(box, d).size, glm::vec3(0.5f, 0.6f, 1.4f));
    Object capsule;
    capsule.type = ShapeType::Capsule;
    d.scaleAxis = 1;
    EXPECT_EQ(applyGizmo(capsule, d).height, 2.0f);
    EXPECT_EQ(applyGizmo(capsule, d).radius, 0.5f);
    Object torus;
    torus.type = ShapeType::Torus;
    EXPECT_EQ(applyGizmo(torus, d).minor, 0.2f);  // across the tube
    d.scaleAxis = 0;
    EXPECT_EQ(applyGizmo(torus, d).radius, 1.0f);
    d.scale = 0.0f;  // dragged through the centre: the smallest size, never zero
    EXPECT_EQ(applyGizmo(Object{}, d).radius, GizmoSettings{}.minSize);
}

TEST(Gizmo, TurnIsInWorldAxesAndKeptExactlyForBodies) {
    Object o;
    o.rot = {0, 90, 0};
    GizmoDelta d;
    d.turn = glm::angleAxis(glm::half_pi<float>(), glm::vec3(1, 0, 0));
    const glm::vec3 local(0, 0, 1);  // Ry(90°) takes it to +x; a turn about world x keeps it
    Object body = applyGizmo(o, d);
    ASSERT_TRUE(body.orient.has_value());
    expectNear(body.orientation() * local, {1, 0, 0}, 1e-5f);
    expectNear(rotationFromEuler(body.rot) * local, {1, 0, 0}, 1e-5f);  // rot shows it too
    o.isStatic = true;  // a static object keeps its turn in rot, as its file does
    Object still = applyGizmo(o, d);
    EXPECT_FALSE(still.orient.has_value());
    expectNear(still.orientation() * glm::vec3(0, 1, 0), {0, 0, 1}, 1e-5f);
    EXPECT_EQ(still.pos, o.pos);
}

TEST(Gizmo, ALightGetsMoveHandlesAndAMarkerToPick) {
    Scene s;
    s.camera = kOblique;
    s.lights = {Light{true, {0, -1, 0}}, Light{false, {1, 2, 0}}, Light{false, {-1, 1, 1}}};
    s.objects = {Object{}};
    s.objects[0].rot = {0, 0, 90};
    GizmoFrame f;
    GizmoMode shown = GizmoMode::Move;
    ASSERT_TRUE(selectionGizmo(s, {ItemKind::Light, 1}, GizmoMode::Rotate, kView, &f, &shown));
    EXPECT_EQ(shown, GizmoMode::Move);
    EXPECT_EQ(f.centre, s.lights[1].vec);
    EXPECT_FALSE(selectionGizmo(s, {ItemKind::Light, 0}, GizmoMode::Move, kView, &f, &shown));
    EXPECT_FALSE(selectionGizmo(s, {ItemKind::Material, 0}, GizmoMode::Move, kView, &f, &shown));
    // Scale handles follow the object's own axes: turned 90° about z, its x points up.
    ASSERT_TRUE(selectionGizmo(s, {ItemKind::Object, 0}, GizmoMode::Scale, kView, &f, &shown));
    expectNear(f.axes[0], {0, 1, 0}, 1e-6f);
    ASSERT_TRUE(selectionGizmo(s, {ItemKind::Object, 0}, GizmoMode::Move, kView, &f, &shown));
    expectNear(f.axes[0], {1, 0, 0}, 1e-6f);

    const glm::vec2 marker = pixelOf(kOblique, s.lights[2].vec);
    EXPECT_EQ(pickLightMarker(s, marker + glm::vec2(5, 0), kView, 8.0f), 2);
    EXPECT_EQ(pickLightMarker(s, marker + glm::vec2(12, 0), kView, 8.0f), -1);
    s.lights[1].vec = s.lights[2].vec + 0.5f * glm::normalize(kOblique.pos - s.lights[2].vec);
    EXPECT_EQ(pickLightMarker(s, marker, kView, 8.0f), 1);  // in front of light 2
}

TEST(Gizmo, HandlesSeenEndOnAreHiddenAndCannotBeTaken) {
    // kFront looks along +z: the z arrow is a dot over the centre, the planes through z slivers.
    const GizmoFrame f = gizmoFrame(kFront, glm::vec3(0), glm::mat3(1.0f), kView);
    EXPECT_FALSE(handleShown(kFront, f, {HandleKind::Axis, 2}));
    EXPECT_FALSE(handleShown(kFront, f, {HandleKind::Plane, 0}));
    EXPECT_TRUE(handleShown(kFront, f, {HandleKind::Plane, 2}));
    EXPECT_TRUE(handleShown(kFront, f, {HandleKind::Axis, 0}));
    EXPECT_TRUE(handleShown(kFront, f, {HandleKind::Ring, 0}));
    const glm::vec2 nearCentre = pixelOf(kFront, glm::vec3(0)) + glm::vec2(0.0f, 3.0f);
    EXPECT_EQ(hitGizmo(kFront, f, GizmoMode::Move, nearCentre, kView).kind, HandleKind::None);
    EXPECT_EQ(hitGizmo(kFront, f, GizmoMode::Scale, nearCentre, kView).kind, HandleKind::None);
}

// Where two rings cross on screen, the ring in front is the one meant: a drag on the z ring near
// where the x ring's back half passed tipped a domino about x.
TEST(Gizmo, WhereRingsCrossTheOneInFrontIsTaken) {
    const GizmoFrame f = worldFrame(kOblique);
    const float reach = GizmoSettings{}.pickPixels;
    auto ring = [&](int i, int m) { return ringPoint(f, i, glm::two_pi<float>() * m / 720.0f); };
    int crossings = 0;
    for (int front = 0; front < 3; ++front)
        for (int back = 0; back < 3; ++back) {
            if (front == back) continue;
            for (int j = 0; j < 720; j += 4) {
                const glm::vec3 p = ring(front, j);
                const glm::vec2 px = pixelOf(kOblique, p);
                // The back ring's point nearest on screen.
                glm::vec3 q = ring(back, 0);
                for (int m = 1; m < 720; ++m)
                    if (glm::distance(pixelOf(kOblique, ring(back, m)), px) <
                        glm::distance(pixelOf(kOblique, q), px))
                        q = ring(back, m);
                if (glm::distance(pixelOf(kOblique, q), px) > 2.0f) continue;
                // A pixel nearer the back ring than the front one, within reach of both, where
                // every part of the back ring within reach lies behind p.
                const glm::vec2 at = glm::mix(px, pixelOf(kOblique, q), 0.6f);
                bool behind = glm::distance(at, px) <= reach - 1.0f;
                for (int m = 0; m < 720 && behind; ++m)
                    if (glm::distance(pixelOf(kOblique, ring(back, m)), at) <= reach + 1.0f)
                        behind = glm::distance(kOblique.pos, ring(back, m)) >
                                 glm::distance(kOblique.pos, p) + 0.05f * f.length;
                if (!behind) continue;
                ++crossings;
                EXPECT_EQ(hitGizmo(kOblique, f, GizmoMode::Rotate, at, kView),
                          (GizmoHandle{HandleKind::Ring, front}))
                    << "front " << front << " back " << back << " at step " << j;
            }
        }
    EXPECT_GT(crossings, 0) << "no front half crossing a back half in this view";
}
