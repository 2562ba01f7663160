// test_std140.cpp — the C++ structs of gpu_scene.h against the offsets the driver reports.
#include "golden.h"
#include "marchbox/gl/gpu_scene.h"
#include "marchbox/gl/offscreen_context.h"
#include "marchbox/gl/renderer.h"

#include <gtest/gtest.h>
#include <cstddef>

using namespace mb;

namespace {

// Byte offset of a uniform inside its block, as glGetActiveUniformsiv reports it.
GLint blockOffset(GLuint program, const char* name) {
    GLuint index = GL_INVALID_INDEX;
    glGetUniformIndices(program, 1, &name, &index);
    if (index == GL_INVALID_INDEX) return -1;
    GLint offset = -1;
    glGetActiveUniformsiv(program, 1, &index, GL_UNIFORM_OFFSET, &offset);
    return offset;
}

class Std140 : public ::testing::Test {
protected:
    void SetUp() override {
        std::string error;
        ASSERT_TRUE(context.create(8, 8, &error)) << error;
        ASSERT_TRUE(renderer.init(&error)) << error;
        Scene s;  // the uber program declares every field of every block
        ASSERT_TRUE(renderer.setScene(s, test::options(RenderMode::Shaded, true), &error)) << error;
        program = renderer.program()->id();
    }
    OffscreenContext context;
    Renderer renderer;
    GLuint program = 0;
};

}  // namespace

TEST_F(Std140, ObjectOffsetsMatchGpuObject) {
    EXPECT_EQ(blockOffset(program, "uObjects[0].posBound"), GLint(offsetof(GpuObject, posBound)));
    EXPECT_EQ(blockOffset(program, "uObjects[0].sizeMinor"), GLint(offsetof(GpuObject, sizeMinor)));
    EXPECT_EQ(blockOffset(program, "uObjects[0].shape"), GLint(offsetof(GpuObject, shape)));
    EXPECT_EQ(blockOffset(program, "uObjects[0].info"), GLint(offsetof(GpuObject, info)));
    EXPECT_EQ(blockOffset(program, "uObjects[0].detail"), GLint(offsetof(GpuObject, detail)));
    EXPECT_EQ(blockOffset(program, "uObjects[0].toLocal"), GLint(offsetof(GpuObject, toLocal)));
    EXPECT_EQ(blockOffset(program, "uObjects[1].posBound"), GLint(sizeof(GpuObject)));
}

// The Groups block exists only in a compiled scene with groups: two here, one in the other.
TEST_F(Std140, GroupOffsetsMatchGpuGroup) {
    Scene s;
    s.materials.push_back({});
    Group outer, inner;
    outer.name = "outer";
    inner.name = "inner", inner.parent = 0, inner.first = 1;
    s.groups = {outer, inner};
    for (int g : {0, 1}) {
        Object o;
        o.group = g;
        o.op = g ? CsgOp::Subtract : CsgOp::Union;
        s.objects.push_back(o);
    }
    std::string error;
    ASSERT_TRUE(renderer.setScene(s, test::options(RenderMode::Shaded), &error)) << error;
    ASSERT_NE(renderer.features(), nullptr);
    ASSERT_EQ(renderer.features()->groups, 2);
    GLuint compiled = renderer.program()->id();
    EXPECT_EQ(blockOffset(compiled, "uGroups[0].posBound"), GLint(offsetof(GpuGroup, posBound)));
    EXPECT_EQ(blockOffset(compiled, "uGroups[0].spacing"), GLint(offsetof(GpuGroup, spacing)));
    EXPECT_EQ(blockOffset(compiled, "uGroups[0].blend"), GLint(offsetof(GpuGroup, blend)));
    EXPECT_EQ(blockOffset(compiled, "uGroups[0].toLocal"), GLint(offsetof(GpuGroup, toLocal)));
    EXPECT_EQ(blockOffset(compiled, "uGroups[1].posBound"), GLint(sizeof(GpuGroup)));
}

TEST_F(Std140, MaterialAndLightOffsetsMatch) {
    EXPECT_EQ(blockOffset(program, "uMaterials[0].color"), GLint(offsetof(GpuMaterial, color)));
    EXPECT_EQ(blockOffset(program, "uMaterials[0].coeffs"), GLint(offsetof(GpuMaterial, coeffs)));
    EXPECT_EQ(blockOffset(program, "uMaterials[1].color"), GLint(sizeof(GpuMaterial)));
    EXPECT_EQ(blockOffset(program, "uLights[0].vec"), GLint(offsetof(GpuLight, vec)));
    EXPECT_EQ(blockOffset(program, "uLights[0].color"), GLint(offsetof(GpuLight, color)));
    EXPECT_EQ(blockOffset(program, "uLights[1].vec"), GLint(sizeof(GpuLight)));
}

TEST_F(Std140, MatrixColumnsAreSixteenBytesApart) {
    GLuint index = GL_INVALID_INDEX;
    const char* name = "uObjects[0].toLocal";
    glGetUniformIndices(program, 1, &name, &index);
    ASSERT_NE(index, GL_INVALID_INDEX);
    GLint stride = 0, rowMajor = 1;
    glGetActiveUniformsiv(program, 1, &index, GL_UNIFORM_MATRIX_STRIDE, &stride);
    glGetActiveUniformsiv(program, 1, &index, GL_UNIFORM_IS_ROW_MAJOR, &rowMajor);
    EXPECT_EQ(stride, GLint(sizeof(GpuObject::toLocal[0])));
    EXPECT_EQ(rowMajor, 0);
}
