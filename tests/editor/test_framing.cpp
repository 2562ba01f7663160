// test_framing.cpp — Frame selected and Frame all, and the default scene's first view.
#include "marchbox/editor/camera_control.h"
#include "marchbox/editor/editor.h"
#include "marchbox/scene/scene_io.h"
#include "marchbox/scene/sdf.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

using namespace mb;

static constexpr float kWide = 16.0f / 9.0f;

static Ball ballOf(const Object& o) { return {o.pos, boundingRadius(o)}; }

static Editor editorOn(const Scene& scene) {
    Editor e;
    e.start(scene, "");
    return e;
}

static Scene threeThings() {
    Scene s;
    s.camera = {{0, 2, -6}, {0, 1, 0}, 50};
    s.objects.resize(2);
    s.objects[0].pos = {-8, 0.5f, 3};
    s.objects[1].pos = {5, 6, 9};
    s.objects[1].radius = 2;
    s.lights.resize(2);
    s.lights[0].vec = {1, 9, 1};
    s.lights[1].directional = true;
    return s;
}

TEST(Framing, FrameSelectedLooksAtTheSelectedObjectOnly) {
    Editor e = editorOn(threeThings());
    const Camera before = e.scene().camera;
    EXPECT_FALSE(e.frameSelected(kWide));  // nothing selected: nothing moves
    EXPECT_EQ(e.scene().camera.pos, before.pos);
    e.select(ItemKind::Object, 1);
    EXPECT_TRUE(e.frameSelected(kWide));
    const Camera& c = e.scene().camera;
    EXPECT_NEAR(glm::length(c.target - e.scene().objects[1].pos), 0.0f, 1e-5f);
    EXPECT_TRUE(ballInView(c, ballOf(e.scene().objects[1]), kWide));
    EXPECT_FALSE(ballInView(c, ballOf(e.scene().objects[0]), kWide));
    EXPECT_FALSE(e.document().dirty());  // a view, not an edit
}

TEST(Framing, FrameSelectedLooksAtAPointLightNotADirection) {
    Editor e = editorOn(threeThings());
    e.select(ItemKind::Light, 0);
    EXPECT_TRUE(e.frameSelected(kWide));
    EXPECT_NEAR(glm::length(e.scene().camera.target - e.scene().lights[0].vec), 0.0f, 1e-5f);
    e.select(ItemKind::Light, 1);
    const Camera before = e.scene().camera;
    EXPECT_FALSE(e.frameSelected(kWide));
    EXPECT_EQ(e.scene().camera.pos, before.pos);
}

TEST(Framing, FrameAllShowsEveryObject) {
    Editor e = editorOn(threeThings());
    EXPECT_TRUE(e.frameAll(kWide));
    for (const Object& o : e.scene().objects)
        EXPECT_TRUE(ballInView(e.scene().camera, ballOf(o), kWide));
    EXPECT_FALSE(editorOn(Scene{}).frameAll(kWide));
}

// The editor opens on the default scene at 16:9 (1280x720): its first frame shows every object
// whole, the falling spheres at the top included.
TEST(Framing, TheDefaultSceneShowsEveryObject) {
    Scene s;
    std::vector<std::string> errors;
    ASSERT_TRUE(loadScene(std::string(MARCHBOX_SOURCE_DIR) + "/scenes/default.txt", &s, &errors));
    for (size_t i = 0; i < s.objects.size(); ++i)
        EXPECT_TRUE(ballInView(s.camera, ballOf(s.objects[i]), kWide)) << "object " << i;
}

// A view from inside a solid is black or a shell's inside: the overlay says what holds the eye.
TEST(Framing, TheEyeInsideASolidIsNamed) {
    Scene s;
    std::vector<std::string> errors;
    ASSERT_TRUE(loadScene(std::string(MARCHBOX_SOURCE_DIR) + "/scenes/inside.txt", &s, &errors));
    EXPECT_EQ(solidAroundEye(s, s.camera.pos), 0);
    ASSERT_TRUE(loadScene(std::string(MARCHBOX_SOURCE_DIR) + "/scenes/default.txt", &s, &errors));
    EXPECT_EQ(solidAroundEye(s, s.camera.pos), kHitNone);
    EXPECT_EQ(solidAroundEye(s, {0, -1, -8}), kHitGround);
    EXPECT_EQ(solidAroundEye(s, s.objects[3].pos), 3);  // the mirror ball's centre
}

// Add with the Objects panel open put a new capsule under it: the spot is found in the window
// beside the panel.
TEST(Framing, AddPutsTheNewObjectInTheWindowNoPanelCovers) {
    Editor e = editorOn(Scene{});
    const ViewWindow right(kWide, {0.2f, -1.0f}, {1.0f, 1.0f});  // the middle of the view is covered
    std::string why;
    ASSERT_TRUE(e.add(ItemKind::Object, &why, ShapeType::Capsule, right)) << why;
    const Object& o = e.scene().objects.back();
    EXPECT_TRUE(ballInView(e.scene().camera, ballOf(o), right));
    EXPECT_FALSE(ballInView(e.scene().camera, ballOf(o), ViewWindow(kWide, {-1, -1}, {0.2f, 1})));
}
