// test_reference_render.cpp — the CPU reference alone, against closed forms of
// docs/shading-model.md: each expected colour below is worked out by hand from the model.
#include "marchbox/reference/reference_render.h"

#include "marchbox/scene/camera.h"
#include "marchbox/scene/sdf.h"

#include <gtest/gtest.h>
#include <cmath>
#include <glm/geometric.hpp>

using namespace mb;
using glm::dvec3;

namespace {

// Ground constants of the model (§3): checker albedo and the floor's Phong coefficients.
constexpr double kLight = 0.80, kDark = 0.35, kKa = 0.1, kKd = 0.8, kKs = 0.1, kC = 16.0;
const dvec3 kZenith(0.30, 0.50, 0.85), kHorizon(0.80, 0.86, 0.92);

// Ground only, one white light, no shadows, mirrors or fog: each test adds what it checks.
Scene openFloor(Light light) {
    Scene s;
    s.lights.push_back(light);
    s.render.shadows = 0;
    s.render.reflections = 0;
    return s;
}

Light sunFrom(dvec3 travel, float intensity = 1.0f) {
    return Light{true, glm::vec3(travel), glm::vec3(1.0f), intensity};
}

Light bulbAt(dvec3 pos, float intensity = 1.0f) {
    return Light{false, glm::vec3(pos), glm::vec3(1.0f), intensity};
}

// The shadow tests' scene: a default sphere (r = 0.5) 1 m above (0.5, 0, 0.5), the sun straight
// above.
Scene ballUnderSun(int shadows) {
    Scene s = openFloor(sunFrom(dvec3(0, -1, 0)));
    s.render.shadows = shadows;
    s.materials.push_back({});
    Object ball;
    ball.pos = glm::vec3(0.5f, 1.0f, 0.5f);
    s.objects.push_back(ball);
    return s;
}

// Phong on the floor (n = +y) for one white light towards l, seen along d, shadow factor s.
dvec3 floorPhong(double albedo, dvec3 l, dvec3 d, double intensity, double s = 1.0) {
    dvec3 n(0, 1, 0);
    double ndl = glm::dot(n, l);
    dvec3 r = 2.0 * ndl * n - l;
    double spec = std::pow(std::max(glm::dot(r, -d), 0.0), kC);
    return dvec3(kKa * albedo + intensity * s * (kKd * ndl * albedo + kKs * spec));
}

void expectColor(dvec3 actual, dvec3 expected, double tol, const char* what) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(actual[c], expected[c], tol) << what << ", channel " << c;
}

// A ray from `eye` that meets the floor at `p`.
ReferenceSample traceTo(const Scene& s, dvec3 eye, dvec3 p) {
    return traceReference(s, eye, glm::normalize(p - eye));
}

}  // namespace

TEST(ReferenceRender, LitFloorIsAmbientPlusDiffusePlusSpecular) {
    dvec3 travel(0.3, -1.0, 0.2), l = -glm::normalize(travel);
    Scene s = openFloor(sunFrom(travel, 0.9f));
    dvec3 eye(0, 2, -4);
    // The last point lies near the highlight, at (-0.6, 0, -4.4) where d mirrored about n is l.
    for (auto [p, albedo] :
         {std::pair{dvec3(0.5, 0, 0.5), kLight}, std::pair{dvec3(1.5, 0, 0.5), kDark},
          std::pair{dvec3(-0.5, 0, -0.5), kLight}, std::pair{dvec3(-0.5, 0, -1.5), kDark},
          std::pair{dvec3(-0.5, 0, -4.0), kDark}}) {
        ReferenceSample r = traceTo(s, eye, p);
        EXPECT_EQ(r.object, kHitGround);
        EXPECT_NEAR(r.t, glm::length(p - eye), 1e-9);
        expectColor(r.color, floorPhong(albedo, l, glm::normalize(p - eye), 0.9), 1e-6, "floor");
    }
}

// A pixel sees the floor's checkers averaged over its sample's footprint (§3). A 1x1 picture
// looking straight down from 1 m has one sample, whose footprint is 2·tan(fov/2) m square: with
// fov 90° that is a whole period along x and along z, grey (0.80 + 0.35)/2 wherever it lies;
// with tan(fov/2) = ½ it is one square's size, the light square's or the dark one's colour when
// centred on it and the mean when centred on an edge.
TEST(ReferenceRender, APixelSeesTheFloorAveragedOverItsFootprint) {
    Scene s = openFloor(sunFrom(dvec3(0, -1, 0)));
    const double mean = (kLight + kDark) / 2, squareFov = 2.0 * std::atan(0.5) * 180.0 / M_PI;
    struct Case {
        double fov, x, z, albedo;
    };
    for (Case c :
         {Case{90, 0.3, 0.2, mean}, Case{90, -7.77, 3.1, mean}, Case{squareFov, 0.5, 0.5, kLight},
          Case{squareFov, 1.5, 0.5, kDark}, Case{squareFov, 1.0, 0.5, mean}}) {
        s.camera.pos = glm::vec3(float(c.x), 1.0f, float(c.z));
        s.camera.target = glm::vec3(float(c.x), 0.0f, float(c.z));
        s.camera.fov = float(c.fov);
        ReferenceImage img = renderReference(s, 1, 1);
        dvec3 down(0, -1, 0), expected = floorPhong(c.albedo, -down, down, 1.0);
        expectColor(dvec3(img.color(0, 0)), expected, 1e-4, "floor under the pixel");
    }
}

TEST(ReferenceRender, SpecularPeaksAlongTheMirrorDirection) {
    // Light straight above a bulb-lit point, eye on the mirror ray: (r·v)^C = 1.
    dvec3 p(0.5, 0, 0.5), bulb(0.5, 4, 0.5);
    Scene s = openFloor(bulbAt(bulb));
    ReferenceSample r = traceTo(s, p + dvec3(0, 3, 0), p);
    expectColor(r.color, dvec3(kKa * kLight + kKd * kLight + kKs), 1e-6, "highlight");
}

TEST(ReferenceRender, HardShadowLeavesOnlyAmbientUnderASphere) {
    Scene s = ballUnderSun(1);
    dvec3 eye(0, 3, -4);
    expectColor(traceTo(s, eye, dvec3(0.6, 0, 0.4)).color, dvec3(kKa * kLight), 1e-6,
                "under the ball");
    dvec3 open(2.5, 0, 0.5);  // light square, straight-down light: n·l = 1
    expectColor(traceTo(s, eye, open).color,
                floorPhong(kLight, dvec3(0, 1, 0), glm::normalize(open - eye), 1.0), 1e-6,
                "in the open");
}

// Light straight up from (x, 0, z) past a ball of radius R centred h above (x0, z0): the field
// along the ray is |(dx, y - h, dz)| - R, so the penumbra term min k·f(t)/t has a closed form
// to sample on a fine grid here, independently of the renderer's march.
TEST(ReferenceRender, SoftShadowIsSmoothstepOfTheLeastPenumbraTerm) {
    Scene s = ballUnderSun(2);
    const double k = ReferenceOptions{}.softness, lift = 2.0 * s.render.epsilon;
    dvec3 eye(0.5, 3, -3);
    for (double dx : {0.52, 0.56, 0.62, 0.75}) {
        double least = 1.0;
        for (double t = 1e-4; t < 100.0; t += 1e-4)
            least = std::min(least, k * (std::hypot(dx, lift + t - 1.0) - 0.5) / t);
        double x = std::clamp(least, 0.0, 1.0), vis = x * x * (3.0 - 2.0 * x);
        dvec3 p(0.5 + dx, 0, 0.5);  // in the dark square [1, 2) x [0, 1)
        dvec3 expected = floorPhong(kDark, dvec3(0, 1, 0), glm::normalize(p - eye), 1.0, vis);
        expectColor(traceTo(s, eye, p).color, expected, 2e-3, "penumbra");
    }
}

TEST(ReferenceRender, FogMixesTowardsTheHorizonByExpSquared) {
    Scene s = openFloor(sunFrom(dvec3(0, -1, 0)));  // the ray looks down: no sun glow in the fog
    dvec3 eye(0, 2, -4), p(0.5, 0, 6.5);
    dvec3 clear = traceTo(s, eye, p).color;
    for (float density : {0.02f, 0.08f}) {
        s.render.fog = density;
        double t = glm::length(p - eye), kept = std::exp(-(density * t) * (density * t));
        expectColor(traceTo(s, eye, p).color, kept * clear + (1.0 - kept) * kHorizon, 1e-6, "fog");
    }
}

TEST(ReferenceRender, SkyIsAGradientWithASunDisc) {
    dvec3 travel(0.2, -0.5, 1.0), towards = -glm::normalize(travel);
    Scene s = openFloor(sunFrom(travel, 0.5f));
    s.world.ground = false;
    dvec3 up(0, 1, 0);
    double glowUp = 0.25 * std::pow(std::max(glm::dot(up, towards), 0.0), 64.0);
    expectColor(traceReference(s, dvec3(0), up).color, kZenith + 0.5 * glowUp, 1e-6, "zenith");
    double e = towards.y;
    dvec3 gradient = kHorizon + (kZenith - kHorizon) * std::sqrt(e);
    expectColor(traceReference(s, dvec3(0), towards).color, gradient + 0.5 * (4.0 + 0.25), 1e-6,
                "sun");
    EXPECT_EQ(traceReference(s, dvec3(0), towards).object, kHitNone);
}

TEST(ReferenceRender, SkyTakesAThirdOfTheBrightestLightsHue) {
    Scene s = openFloor(Light{false, {0, 5, 0}, {1.0f, 0.5f, 0.25f}, 2.0f});
    s.lights.push_back(Light{false, {0, 5, 0}, {0.2f, 0.9f, 0.2f}, 1.0f});  // dimmer
    s.world.ground = false;
    dvec3 tint(1.0, 0.5, 0.25);
    dvec3 horizon = kHorizon * (0.65 + 0.35 * tint);
    expectColor(traceReference(s, dvec3(0), dvec3(1, 0, 0)).color, horizon, 1e-6, "horizon");
}

TEST(ReferenceRender, MirrorSphereReflectsTheSkyAndTheFloor) {
    Scene s = openFloor(bulbAt(dvec3(3, 6, -3)));
    s.render.reflections = 2;
    Material mirror;
    mirror.Ka = mirror.Kd = mirror.Ks = 0.0f;
    mirror.Kr = 1.0f;
    s.materials.push_back(mirror);
    Object ball;
    ball.pos = glm::vec3(0.5f, 1.0f, 0.0f);  // x = 0.5: away from the checker lines
    s.objects.push_back(ball);
    dvec3 centre(0.5, 1, 0), down(0, -1, 0);
    // Hit where the normal leans 30° towards -z: the mirror ray (0, 0.5, -0.866) climbs to the sky.
    dvec3 n30(0, std::cos(M_PI / 6), -std::sin(M_PI / 6)), hit30 = centre + 0.5 * n30;
    ReferenceSample sky = traceReference(s, hit30 - 2.0 * down, down);
    dvec3 skyThere = kHorizon + (kZenith - kHorizon) * std::sqrt(0.5);
    EXPECT_EQ(sky.object, 0);
    expectColor(sky.color, skyThere, 2e-3, "sky in the mirror");
    // Half a mirror keeps half of its own colour (Ka = 1, nothing else: the albedo itself).
    Scene half = s;
    half.materials[0] = Material{"half", {0.2f, 0.4f, 0.6f}, 1.0f, 0.0f, 0.0f, 32.0f, 0.5f};
    expectColor(traceReference(half, hit30 - 2.0 * down, down).color,
                0.5 * dvec3(0.2, 0.4, 0.6) + 0.5 * skyThere, 2e-3, "half a mirror");
    // At 60° the mirror ray (0, -0.5, -0.866) meets the floor 2.5 m on, in a dark square.
    dvec3 n60(0, 0.5, -std::sin(M_PI / 3)), hit60 = centre + 0.5 * n60;
    dvec3 bounce = down - 2.0 * glm::dot(down, n60) * n60, floorPoint = hit60 + 2.5 * bounce;
    ASSERT_NEAR(floorPoint.y, 0.0, 1e-12);
    dvec3 l = glm::normalize(dvec3(3, 6, -3) - floorPoint);
    expectColor(traceReference(s, hit60 - 2.0 * down, down).color,
                floorPhong(kDark, l, bounce, 1.0), 2e-3, "floor in the mirror");
}

TEST(ReferenceRender, AmbientOcclusionBesideAWall) {
    // A wall 0.05 m beside the floor point: the probes at 1..13 cm see min(h, 0.05).
    Scene s = openFloor(sunFrom(dvec3(0, -1, 0)));
    s.render.ao = true;
    s.materials.push_back({});
    Object wall;
    wall.type = ShapeType::Box;
    wall.pos = glm::vec3(2.05f, 1.0f, 0.5f);
    wall.size = glm::vec3(0.5f, 1.0f, 3.0f);  // its face at x = 1.55
    s.objects.push_back(wall);
    double missing = 0.0, w = 1.0;
    for (int i = 0; i < 5; ++i, w *= 0.95) missing += w * std::max(0.01 + 0.03 * i - 0.05, 0.0);
    double ao = 1.0 - 3.0 * missing;
    dvec3 eye(0, 1, -3), p(1.5, 0, 0.5), d = glm::normalize(p - eye);
    dvec3 r(0, 1, 0);  // straight-down light: mirror direction is up
    double spec = std::pow(std::max(glm::dot(r, -d), 0.0), kC);
    dvec3 expected(kKa * kDark * ao + (kKd * kDark + kKs * spec) * (0.5 + 0.5 * ao));
    expectColor(traceTo(s, eye, p).color, expected, 1e-5, "occluded floor");
}

TEST(ReferenceRender, ARayThatStartsInsideStopsAtOnce) {
    Scene s = openFloor(bulbAt(dvec3(0, 5, 0)));
    s.materials.push_back({});
    Object ball;
    ball.pos = glm::vec3(0, 1, 0);
    ball.radius = 2.0f;
    s.objects.push_back(ball);
    ReferenceSample r = traceReference(s, dvec3(0, 1, 0), dvec3(0, 0, 1));
    EXPECT_EQ(r.object, 0);
    EXPECT_EQ(r.t, 0.0);
}

TEST(ReferenceRender, PixelsFollowTheCameraRayAndTopRowFirst) {
    Scene s = openFloor(sunFrom(dvec3(0.3, -1, 0.2)));
    s.materials.push_back({});
    Object ball;
    ball.pos = glm::vec3(0, 1, 0);
    s.objects.push_back(ball);
    const int w = 16, h = 9;
    ReferenceImage img = renderReference(s, w, h);
    ASSERT_EQ(img.rgb.size(), size_t(w * h));
    EXPECT_EQ(img.objectAt(0, 0), kHitNone);        // top row: sky
    EXPECT_EQ(img.objectAt(0, h - 1), kHitGround);  // bottom row: floor
    EXPECT_EQ(img.objectAt(w / 2, h / 2), 0);       // the camera looks at the ball
    CameraBasis basis = cameraBasis(s.camera);
    for (auto [x, row] : {std::pair{3, 7}, std::pair{8, 4}, std::pair{12, 1}}) {
        glm::vec3 dir = cameraRay(basis, glm::vec2(x + 0.5f, h - 1 - row + 0.5f), glm::vec2(w, h));
        ReferenceSample r = traceReference(s, dvec3(basis.pos), dvec3(dir));
        EXPECT_EQ(img.objectAt(x, row), r.object);
        // A pixel averages the floor's squares over its footprint, which a lone ray has not.
        if (r.object == kHitGround) continue;
        // cameraRay is float, the reference's own rays double: a few 1e-5 apart.
        expectColor(dvec3(img.color(x, row)), glm::clamp(r.color, 0.0, 1.0), 1e-3, "pixel");
    }
}

namespace {

// A static cup at the origin: a cylinder (radius 0.5, y 0 to 1) less a taller one (radius 0.4,
// from y 0.1 up past the rim), and `before` standing ahead of it in the file.
Scene cupAfter(const std::string& before) {
    Scene s = openFloor(bulbAt(dvec3(0, 5, 0)));
    s.materials.push_back({});
    Object ball;
    ball.pos = glm::vec3(0, 0.6f, 0);
    ball.radius = 0.15f;
    ball.isStatic = true;
    if (before == "ball") s.objects.push_back(ball);
    Group cup;
    cup.name = "cup";
    cup.pos = glm::vec3(0, 0.5f, 0);
    cup.isStatic = true;
    cup.first = int(s.objects.size());
    s.groups.push_back(cup);
    Object wall, hollow;
    wall.type = hollow.type = ShapeType::Cylinder;
    wall.group = hollow.group = 0;
    wall.radius = 0.5f, wall.height = 1.0f;
    hollow.radius = 0.4f, hollow.height = 1.0f, hollow.pos = glm::vec3(0, 0.1f, 0);
    hollow.op = CsgOp::Subtract;
    s.objects.push_back(wall);
    s.objects.push_back(hollow);
    return s;
}

}  // namespace

// The cup's subtract hollows the cup alone: straight down, a ray meets the cup's floor at
// y = 0.1, and with a ball standing inside the hollow (outside the group, before it in the
// file) the ball's top at y = 0.75. Flattened into one chain, the subtract would carve the ball.
TEST(ReferenceRender, AGroupsSubtractCarvesItsGroupAlone) {
    ReferenceSample empty = traceReference(cupAfter("nothing"), dvec3(0.2, 3, 0), dvec3(0, -1, 0));
    EXPECT_EQ(empty.object, 1) << "a carved face is the carving object's";
    EXPECT_NEAR(empty.t, 2.9, 1e-4);
    ReferenceSample ball = traceReference(cupAfter("ball"), dvec3(0, 3, 0), dvec3(0, -1, 0));
    EXPECT_EQ(ball.object, 0) << "the ball, whole";
    EXPECT_NEAR(ball.t, 2.25, 1e-4);
}

// Five copies of a ball 2 m apart along x (at -4 to 4). A ray from the side, aimed at the far
// copy, passes no nearer copy: it must march past every object's own bound about the modelled
// ball to reach it, at |(4, 0, 3)| − 0.3 = 4.7.
TEST(ReferenceRender, RaysMeetTheFarCopiesOfARepeatedGroup) {
    Scene s = openFloor(bulbAt(dvec3(0, 5, 0)));
    s.materials.push_back({});
    Group row;
    row.name = "row";
    row.pos = glm::vec3(0, 0.5f, 0);
    row.isStatic = true;
    row.repeat = glm::ivec3(5, 1, 1);
    row.spacing = glm::vec3(2.0f, 1.0f, 1.0f);
    s.groups.push_back(row);
    Object ball;
    ball.group = 0;
    ball.radius = 0.3f;
    s.objects.push_back(ball);
    ReferenceSample r = traceReference(s, dvec3(0, 0.5, -3), glm::normalize(dvec3(4, 0, 3)));
    EXPECT_EQ(r.object, 0);
    EXPECT_NEAR(r.t, 4.7, 1e-4);
}
