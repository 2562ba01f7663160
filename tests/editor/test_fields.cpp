// test_fields.cpp — typed values are checked against SCENE_FORMAT.md's ranges.
#include "marchbox/editor/fields.h"
#include "marchbox/scene/scene_io.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

using namespace mb;

TEST(Fields, RangesFromTheFormat) {
    std::string why;
    EXPECT_TRUE(validateField(Field::Restitution, 0.0, &why));
    EXPECT_TRUE(validateField(Field::Restitution, 1.0, &why));
    EXPECT_FALSE(validateField(Field::Restitution, 1.01, &why));
    EXPECT_EQ(why, "restitution must be between 0 and 1");
    EXPECT_FALSE(validateField(Field::Fov, 0.5, &why));
    EXPECT_TRUE(validateField(Field::Fov, 179, &why));
    EXPECT_FALSE(validateField(Field::Gravity, -1, &why));
    EXPECT_TRUE(validateField(Field::Mass, 0, &why));
    EXPECT_TRUE(validateField(Field::Rolling, 0.0, &why));
    EXPECT_TRUE(
        validateField(Field::Rolling, 5.0, &why));  // >= 0; the editor caps it at 100, as friction
    EXPECT_FALSE(validateField(Field::Rolling, -0.001, &why));
    EXPECT_EQ(why, "rolling must be between 0 and 100");
    EXPECT_STREQ(fieldSpec(Field::Rolling).name, "rolling");
}

TEST(Fields, ExclusiveMinimum) {
    std::string why;
    EXPECT_FALSE(validateField(Field::Radius, 0.0, &why));
    EXPECT_EQ(why, "radius must be above 0 and at most 10000 m");
    EXPECT_TRUE(validateField(Field::Radius, 1e-6, &why));
    EXPECT_FALSE(validateField(Field::Epsilon, 0.0, &why));
    EXPECT_FALSE(validateField(Field::Shininess, 0.0, &why));
}

TEST(Fields, NonFiniteIsRefusedEverywhere) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    std::string why;
    for (int f = 0; f < int(Field::Count); ++f) {
        EXPECT_FALSE(validateField(Field(f), nan, &why)) << fieldSpec(Field(f)).name;
        EXPECT_FALSE(validateField(Field(f), inf, &why)) << fieldSpec(Field(f)).name;
        EXPECT_FALSE(validateField(Field(f), -inf, &why)) << fieldSpec(Field(f)).name;
    }
    EXPECT_EQ(why, "spacing must be above 0 and at most 10000 m");  // the last field
    EXPECT_FALSE(validateField(Field::Position, 1e39, &why));  // finite double, infinite float
    EXPECT_FALSE(validateField(Field::Radius, nan, &why));
    EXPECT_EQ(why, "radius must be a number");
}

// 1e40 said "must be a finite number" and 1e9 passed without a word. Every
// field now has a finite range inside the format's, and a refusal names the value kept.
TEST(Fields, EveryFieldHasAFiniteRangeInsideTheFormats) {
    std::string why;
    for (int f = 0; f < int(Field::Count); ++f) {
        const FieldSpec& s = fieldSpec(Field(f));
        EXPECT_TRUE(std::isfinite(s.min) && std::isfinite(s.max)) << s.name;
        EXPECT_FALSE(validateField(Field(f), 1e9, &why)) << s.name;
        EXPECT_FALSE(validateField(Field(f), -1e9, &why)) << s.name;
        EXPECT_EQ(why, std::string(s.name) + " must be " + fieldRangeText(Field(f)));
    }
}

TEST(Fields, ARefusalKeepsTheOldValueAndSaysSo) {
    std::string why;
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(acceptField(Field::Radius, 1e9, 0.5, &why));
    EXPECT_EQ(why, "radius must be above 0 and at most 10000 m: 1e+09 refused, 0.5 kept");
    EXPECT_FALSE(acceptField(Field::Radius, float(1e40), 0.5, &why));  // what ImGui reads
    EXPECT_EQ(why, "radius must be above 0 and at most 10000 m: inf refused, 0.5 kept");
    EXPECT_FALSE(acceptField(Field::Radius, -inf, 0.5, &why));
    EXPECT_FALSE(acceptField(Field::Steps, 64.5, 256, &why));
    EXPECT_EQ(why, "steps must be a whole number between 1 and 4096: 64.5 refused, 256 kept");
    EXPECT_TRUE(acceptField(Field::Radius, 2, 0.5, &why));
    EXPECT_TRUE(acceptField(Field::Restitution, 1, 0.5, &why));
}

TEST(Fields, AVectorIsCheckedWhereItChanged) {
    std::string why;
    // A file may hold positions past the editor's range: the other components stay editable.
    EXPECT_TRUE(acceptVec(Field::Position, {1, 2e4f, 0}, {0, 2e4f, 0}, &why));
    EXPECT_FALSE(acceptVec(Field::Position, {1, 3e4f, 0}, {1, 2e4f, 0}, &why));
    EXPECT_EQ(why, "pos.y must be between -10000 and 10000 m: 30000 refused, 20000 kept");
    EXPECT_FALSE(acceptVec(Field::ColorChannel, {1, -1, 1}, {1, 1, 1}, &why));
    EXPECT_EQ(why, "color.g must be between 0 and 100: -1 refused, 1 kept");
    EXPECT_FALSE(acceptVec(Field::LightDirection, {0, 0, 0}, {0, -1, 0}, &why));
    EXPECT_EQ(why, "a light direction must not be zero: 0,0,0 refused, 0,-1,0 kept");
}

TEST(Fields, EveryTooltipGivesTheUnitAndTheRange) {
    for (int f = 0; f < int(Field::Count); ++f) {
        const FieldSpec& s = fieldSpec(Field(f));
        const std::string tip = fieldTooltip(Field(f));
        EXPECT_NE(tip.find(s.meaning), std::string::npos) << tip;
        EXPECT_NE(tip.find("Range: " + fieldRangeText(Field(f)) + "."), std::string::npos) << tip;
        EXPECT_NE(tip.find(*s.unit ? "Unit: " + std::string(s.unit) + "." : "No unit."),
                  std::string::npos)
            << tip;
    }
    EXPECT_EQ(fieldTooltip(Field::Radius),
              "Radius of a sphere, torus ring, capsule or cylinder, or a cone's base.\n"
              "Unit: m. Range: above 0 and at most 10000 m.\n"
              "Click to type a value, or drag.");
}

TEST(Fields, IntegersMustBeWhole) {
    std::string why;
    EXPECT_TRUE(validateField(Field::Steps, 64, &why));
    EXPECT_FALSE(validateField(Field::Steps, 64.5, &why));
    EXPECT_FALSE(validateField(Field::Steps, 5000, &why));
    EXPECT_FALSE(validateField(Field::Shadows, 3, &why));
    EXPECT_FALSE(validateField(Field::Aa, 0, &why));
}

TEST(Fields, VectorsAndDirections) {
    std::string why;
    EXPECT_TRUE(validateVec(Field::HalfExtent, {1, 2, 3}, &why));
    EXPECT_FALSE(validateVec(Field::HalfExtent, {1, 0, 3}, &why));
    EXPECT_FALSE(validateVec(Field::LightDirection, {0, 0, 0}, &why));
    EXPECT_TRUE(validateVec(Field::LightDirection, {0, -1, 0}, &why));
    EXPECT_FALSE(
        validateVec(Field::Position, {0, std::numeric_limits<float>::quiet_NaN(), 0}, &why));
}

TEST(Fields, DragRangesLieInsideTheAllowedRange) {
    std::string why;
    for (int f = 0; f < int(Field::Count); ++f) {
        const FieldSpec& s = fieldSpec(Field(f));
        EXPECT_LT(s.dragMin, s.dragMax) << s.name;
        EXPECT_TRUE(validateField(Field(f), s.dragMin, &why)) << s.name << ": " << why;
        EXPECT_TRUE(validateField(Field(f), s.dragMax, &why)) << s.name << ": " << why;
    }
}

TEST(Fields, MaterialNames) {
    std::string why;
    EXPECT_TRUE(validateName("red_1.b-2", &why));
    EXPECT_FALSE(validateName("", &why));
    EXPECT_FALSE(validateName("two words", &why));
    EXPECT_FALSE(validateName("r:1", &why));
}

// A name the editor takes must save to a file that loads: lines stop at 4096 bytes.
TEST(Fields, MaterialNamesTakenSaveToALoadableFile) {
    std::string why;
    for (size_t length : {size_t(1), kMaxNameBytes, size_t(kMaxLineBytes)}) {
        Scene scene;
        scene.materials.push_back(Material{});
        scene.materials[0].name = std::string(length, 'a');
        std::vector<SceneError> errors;
        bool taken = validateName(scene.materials[0].name, &why);
        EXPECT_EQ(taken, length <= kMaxNameBytes) << length;
        if (taken) {
            EXPECT_TRUE(parseScene(formatScene(scene), nullptr, &errors)) << length;
        }
    }
    EXPECT_FALSE(validateName(std::string(kMaxNameBytes + 1, 'a'), &why));
    EXPECT_EQ(why, "a name is letters, digits, '_', '.' or '-', 1 to 256");
}
