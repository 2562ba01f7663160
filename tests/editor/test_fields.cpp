// test_fields.cpp — typed values are checked against SCENE_FORMAT.md's ranges.
#include "marchbox/editor/fields.h"

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
    EXPECT_TRUE(validateField(Field::Rolling, 5.0, &why));  // >= 0, no upper bound
    EXPECT_FALSE(validateField(Field::Rolling, -0.001, &why));
    EXPECT_EQ(why, "rolling must be >= 0");
    EXPECT_STREQ(fieldSpec(Field::Rolling).name, "rolling");
}

TEST(Fields, ExclusiveMinimum) {
    std::string why;
    EXPECT_FALSE(validateField(Field::Radius, 0.0, &why));
    EXPECT_EQ(why, "radius must be > 0");
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
    EXPECT_NE(why.find("finite"), std::string::npos);
    EXPECT_FALSE(validateField(Field::Position, 1e39, &why));  // finite double, infinite float
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
    EXPECT_FALSE(validateVec(Field::Position, {0, std::numeric_limits<float>::quiet_NaN(), 0}, &why));
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
