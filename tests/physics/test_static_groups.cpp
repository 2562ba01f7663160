// test_static_groups.cpp — static groups (format version 3) collide as what is drawn: their
// members' CSG carves only the group, in the group's frame, mirrored and repeated.
#include "marchbox/physics/physics.h"
#include "marchbox/scene/scene_io.h"
#include "physics_test_util.h"

#include <gtest/gtest.h>

using namespace mb;

namespace {

// A static cup group at x = -1: a cylinder (radius 0.5, height 0.8, standing on the ground)
// less a taller one raised 0.06, so its floor is at y = 0.06 and its subtractor pokes above
// the rim. A sphere before the group sits where the subtractor would carve it in a flat chain.
// A ball of radius 0.2 is dropped over the cup's axis.
const char* kCup = R"(scene version:3
world restitution:0.2 rolling:0.05
material r:1 g:1 b:1
object type:sphere pos:-1,2.2,0 radius:0.2 mass:1
object type:box pos:-1,0.7,0 size:0.1,0.1,0.1 static:1
group name:cup pos:-1,0.4,0 rot:0,30,0 static:1
object in:cup type:cylinder pos:0,0,0 radius:0.5 height:0.8
object in:cup type:cylinder pos:0,0.06,0 radius:0.44 height:0.8 op:subtract
)";

Scene parse(const std::string& text) {
    Scene s;
    std::vector<SceneError> errors;
    EXPECT_TRUE(parseScene(text, &s, &errors)) << (errors.empty() ? "" : errors[0].message);
    return s;
}

// The resting overlap the solver leaves alone (slopFor in physics_world.cpp).
double restSlop(const PhysicsSettings& s, double radius) {
    return std::min(s.linearSlop, 0.05 * radius);
}

double restingHeight(const std::string& text, double seconds) {
    PhysicsWorld w(parse(text));
    for (int i = 0; i < stepsFor(seconds, w.settings()); ++i) w.step();
    return w.body(0).pos.y;
}

}  // namespace

// The group's subtract carves the cup only: the small box before the group stays whole, so the
// ball lands on it (its top at 0.8) and not on the floor. Without it the ball rests on the floor.
TEST(StaticGroups, ACupGroupCatchesABallOnWhatItsMembersLeave) {
    PhysicsWorld w(parse(kCup));
    const double slop = restSlop(w.settings(), 0.2);
    const double onBox = restingHeight(kCup, 4.0);
    EXPECT_NEAR(onBox, 0.8 + 0.2, slop + 1e-6) << "the box inside the cup is whole";
    std::string noBox = kCup;
    noBox.erase(noBox.find("object type:box"),
                noBox.find("group name") - noBox.find("object type:box"));
    const double onFloor = restingHeight(noBox, 4.0);
    EXPECT_NEAR(onFloor, 0.06 + 0.2, slop + 1e-6) << "on the cup's inner floor";
}

// A repeated group of posts: a ball dropped over the third copy lands on its top, and one
// dropped between copies falls to the ground; a mirrored post stands where the mirror puts it.
TEST(StaticGroups, RepeatedAndMirroredCopiesStandWhereTheContractPutsThem) {
    const std::string head = "scene version:3\nworld restitution:0\nmaterial r:1 g:1 b:1\n";
    const std::string posts =
        "group name:posts pos:0,0,0 static:1 repeat:3,1,1 spacing:1,1,1\n"
        "object in:posts type:box pos:0,0.5,0 size:0.2,0.5,0.2\n"
        "group name:pair pos:0,0,3 static:1 mirror:x\n"
        "object in:pair type:box pos:1,0.25,0 size:0.2,0.25,0.2\n";
    const double r = 0.1;
    PhysicsWorld settings(parse(head + posts));
    const double slop = restSlop(settings.settings(), r);
    auto drop = [&](const char* at) {
        return restingHeight(head + "object type:sphere pos:" + at + " radius:0.1 mass:1\n" + posts,
                             3.0);
    };
    EXPECT_NEAR(drop("1,2,0"), 1.0 + r, slop + 1e-6) << "on the copy at x = 1";
    EXPECT_NEAR(drop("-1,2,0"), 1.0 + r, slop + 1e-6) << "on the copy at x = -1";
    EXPECT_NEAR(drop("0.5,2,0"), r, slop + 1e-6) << "between copies, to the ground";
    EXPECT_NEAR(drop("-1,2,3"), 0.5 + r, slop + 1e-6) << "on the mirrored post";
}
