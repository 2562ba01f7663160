// test_camera_control.cpp — orbit, pan, zoom and fly keep the camera's shape.
#include "marchbox/editor/camera_control.h"
#include "marchbox/editor/picking.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

using namespace mb;

static const Camera kStart{{0, 2, -6}, {0, 1, 0}, 50};

TEST(CameraControl, OrbitKeepsDistanceAndTarget) {
    Camera c = kStart;
    float d = glm::length(c.pos - c.target);
    orbitCamera(c, {120, -40});
    EXPECT_NEAR(glm::length(c.pos - c.target), d, 1e-4f);
    EXPECT_EQ(c.target, kStart.target);
    EXPECT_NE(c.pos, kStart.pos);
}

TEST(CameraControl, OrbitRightSwingsTheCameraToTheViewsLeft) {
    Camera c = kStart;  // looking along +z: the view's left is +x
    orbitCamera(c, {50, 0});
    EXPECT_GT(c.pos.x, 0.0f);
}

TEST(CameraControl, OrbitStopsShortOfThePole) {
    Camera c = kStart;
    orbitCamera(c, {0, 100000});
    glm::vec3 dir = glm::normalize(c.pos - c.target);
    EXPECT_LT(dir.y, 0.9996f);
    EXPECT_GT(dir.y, 0.99f);
}

TEST(CameraControl, ZoomApproachesWithinLimits) {
    Camera c = kStart;
    float d = glm::length(c.pos - c.target);
    zoomCamera(c, 1);
    EXPECT_NEAR(glm::length(c.pos - c.target), d * 0.85f, 1e-4f);
    zoomCamera(c, 1000);
    EXPECT_NEAR(glm::length(c.pos - c.target), 0.05f, 1e-5f);
}

TEST(CameraControl, PanMovesCameraAndTargetTogether) {
    Camera c = kStart;
    panCamera(c, {100, 0}, 600);
    EXPECT_EQ(c.pos - c.target, kStart.pos - kStart.target);
    EXPECT_GT(c.pos.x, 0.0f);  // content follows the mouse right: the camera goes left (+x)
}

TEST(CameraControl, FlyForwardMovesAlongTheView) {
    Camera c = kStart;
    flyCamera(c, {0, 0, 1}, 0.5f);  // 4 m/s for half a second
    glm::vec3 forward = glm::normalize(kStart.target - kStart.pos);
    EXPECT_NEAR(glm::length(c.pos - (kStart.pos + 2.0f * forward)), 0.0f, 1e-5f);
    flyCamera(c, {0, 1, 0}, 1.0f);
    EXPECT_NEAR(c.target.y - c.pos.y, kStart.target.y - kStart.pos.y, 1e-5f);
}

TEST(Picking, GroundDragKeepsTheGrabOffset) {
    Scene s;
    s.camera = {{0, 5, -5}, {0, 0, 0}, 60};
    Object o;
    o.pos = {0, 0.5f, 0};
    s.objects.push_back(o);
    GroundDrag drag;
    glm::vec2 view(400, 300);
    ASSERT_TRUE(drag.begin(s, 0, {200, 150}, view));
    glm::vec3 pos;
    ASSERT_TRUE(drag.follow(s.camera, {200, 150}, view, &pos));
    EXPECT_NEAR(glm::length(pos - o.pos), 0.0f, 1e-4f);  // not moved yet: no jump
    ASSERT_TRUE(drag.follow(s.camera, {100, 150}, view, &pos));
    EXPECT_EQ(pos.y, 0.5f);
    EXPECT_GT(pos.x, 0.1f);  // left of the screen is +x for a camera looking along +z
}

TEST(Picking, PlaneBehindTheCameraMisses) {
    Camera c{{0, 2, 0}, {0, 3, 5}, 50};  // looking up
    glm::vec3 hit;
    EXPECT_FALSE(pixelOnPlane(c, {200, 150}, {400, 300}, 0.0f, &hit));
}

static constexpr float kWide = 16.0f / 9.0f;

TEST(CameraFraming, BallInViewOnlyWhenWhollyInside) {
    const Camera c{{0, 0, -10}, {0, 0, 0}, 90};  // tan(45°) = 1: the view is 10 m tall at z = 0
    EXPECT_TRUE(ballInView(c, {{0, 0, 0}, 1}, 1.0f));
    // At the top edge's plane y = z + 10 (45°), a ball of radius r needs its centre r·√2 below.
    const float r = 1.0f, edge = 10.0f - r * std::sqrt(2.0f);
    EXPECT_TRUE(ballInView(c, {{0, edge - 1e-3f, 0}, r}, 1.0f));
    EXPECT_FALSE(ballInView(c, {{0, edge + 1e-3f, 0}, r}, 1.0f));
    EXPECT_FALSE(ballInView(c, {{0, 0, -12}, 0.5f}, 1.0f));  // behind the eye
    EXPECT_TRUE(ballInView(c, {{12, 0, 10}, 1}, 2.0f));      // wide view: room across
    EXPECT_FALSE(ballInView(c, {{19.5f, 0, 10}, 1}, 1.0f));
}

TEST(CameraFraming, FrameAllFitsEveryBallFromTheSameDirection) {
    const std::vector<Ball> balls = {{{-3, 0.5f, 0}, 0.5f}, {{4, 2, 1}, 1}, {{0, 6, -2}, 0.3f}};
    for (float aspect : {kWide, 1.0f, 0.5f}) {
        Camera c = kStart;
        const glm::vec3 dir = glm::normalize(c.pos - c.target);
        frameBalls(c, balls, aspect);
        EXPECT_NEAR(glm::length(glm::normalize(c.pos - c.target) - dir), 0.0f, 1e-5f);
        for (const Ball& b : balls) EXPECT_TRUE(ballInView(c, b, aspect)) << aspect;
        // As close as that allows, with 2% to spare: 3% nearer, some ball is cut.
        Camera nearer = c;
        nearer.pos = c.target + (c.pos - c.target) * 0.97f;
        bool cut = false;
        for (const Ball& b : balls) cut |= !ballInView(nearer, b, aspect);
        EXPECT_TRUE(cut) << "aspect " << aspect;
    }
}

// Home with the Objects panel open put the dominoes under it: the balls go to the window beside
// the panel, its middle at theirs, and none is cut by the window's edges.
TEST(CameraFraming, FramingIntoAWindowFitsItAndCentresThere) {
    const std::vector<Ball> balls = {{{-3, 0.5f, 0}, 0.5f}, {{4, 2, 1}, 1}, {{0, 6, -2}, 0.3f}};
    const ViewWindow right(kWide, {-0.4f, -0.9f}, {1.0f, 0.95f});
    Camera c = kStart;
    const glm::vec3 dir = glm::normalize(c.pos - c.target);
    frameBalls(c, balls, right);
    EXPECT_NEAR(glm::length(glm::normalize(c.pos - c.target) - dir), 0.0f, 1e-5f);
    for (const Ball& b : balls) EXPECT_TRUE(ballInView(c, b, right));
    const ViewWindow leftOfIt(kWide, {-1.0f, -1.0f}, {-0.4f, 1.0f});
    for (const Ball& b : balls) EXPECT_FALSE(ballInView(c, b, leftOfIt));
    // The middle of the balls' box shows at the window's middle.
    const glm::vec3 middle(0.75f, 3.15f, -0.15f);  // of the box from (-3.5, 0, -2.3) to (5, 6.3, 2)
    const glm::vec3 ray = viewRay(c, kWide, right.middle());
    const glm::vec3 to = middle - c.pos;
    EXPECT_LT(glm::length(glm::cross(glm::normalize(ray), glm::normalize(to))), 1e-4f);
}

TEST(CameraFraming, NothingToFrameLeavesTheCamera) {
    Camera c = kStart;
    frameBalls(c, {}, kWide);
    EXPECT_EQ(c.pos, kStart.pos);
    EXPECT_EQ(c.target, kStart.target);
}
