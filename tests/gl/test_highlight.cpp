// test_highlight.cpp — the editor's selection tint: the selected object drawn as if its
// albedo were mixed 60% towards orange, and nothing else changed.
#include "golden.h"

#include "marchbox/gl/offscreen_context.h"

#include <glm/common.hpp>
#include <gtest/gtest.h>

using namespace mb;

namespace {

constexpr int kW = 160, kH = 90;

// Draws `s` with object `selected` highlighted (-1: none), the way the editor's view does.
Image drawSelected(const Scene& s, int selected) {
    OffscreenContext context;
    Renderer r;
    ColorTarget target;
    std::string error;
    EXPECT_TRUE(context.create(1, 1, &error) && r.init(&error) && r.setScene(s, {}, &error)) << error;
    EXPECT_TRUE(target.resize(kW, kH, GL_RGBA8));
    target.bind();
    glUseProgram(r.program()->id());
    glUniform1i(r.program()->uniform("uHighlight"), selected + 1);
    r.draw(kW, kH);
    return readFramebuffer(kW, kH);
}

}  // namespace

TEST(Highlight, TheSelectionTintsTheAlbedoAndNothingElse) {
    Scene s = test::loadSceneOrDie("scenes/primitives.txt");
    s.render.reflections = 0;  // one material may be shared: a reflection would show the tint twice
    int selected = 1;
    Image tinted = drawSelected(s, selected);

    Scene painted = s;  // the same picture, with the tint painted into a material of its own
    Material m = s.materials[size_t(s.objects[size_t(selected)].material)];
    m.color = glm::mix(m.color, glm::vec3(1.0f, 0.6f, 0.1f), 0.6f);
    painted.materials.push_back(m);
    painted.objects[size_t(selected)].material = int(painted.materials.size()) - 1;
    Image expected = drawSelected(painted, -1);

    ImageDiff d = diffImages(tinted, expected);
    EXPECT_LE(d.maxAbs, 1.0) << "the tint is a 60% mix of the albedo towards orange";
    EXPECT_GT(diffImages(tinted, drawSelected(s, -1)).maxAbs, 50.0) << "the selected object must show it";
}
