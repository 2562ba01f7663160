// golden.h — rendering a scene file and comparing it with its committed PNG.
#pragma once

#include "marchbox/gl/renderer.h"
#include "marchbox/gl/image.h"
#include "marchbox/reference/reference_render.h"
#include "marchbox/scene/scene.h"

#include <string>
#include <vector>

namespace mb::test {

constexpr int kGoldenWidth = 320, kGoldenHeight = 180;

inline RenderOptions options(RenderMode mode, bool uber = false) {
    RenderOptions o;
    o.mode = mode;
    o.uber = uber;
    return o;
}

std::string sourcePath(const std::string& relative);  // inside the source tree
std::string outputPath(const std::string& name);      // under build/test-output/

Scene loadSceneOrDie(const std::string& relative);  // fails the test on a load error
Scene parseSceneOrDie(const std::string& text);     // and on a parse error, at its line
Image renderOrDie(const Scene& scene, const RenderOptions& options = {}, int width = kGoldenWidth,
                  int height = kGoldenHeight);

std::vector<std::string> sceneNames();  // every scenes/*.txt, by stem, sorted

// Compares with tests/golden/NAME.png. On a mismatch writes NAME.actual.png and NAME.diff.png
// under build/test-output/. With MARCHBOX_UPDATE_GOLDEN=1 it rewrites the golden instead.
void expectMatchesGolden(const Image& actual, const std::string& name);

// Whether the GPU's ids and the reference see one object, and the reference one region
// (reference_render.h), in the whole 3x3 block about (x, row): no edge is near, so a sub-pixel
// shift between the two cannot show there.
bool interior(const Image& ids, const ReferenceImage& ref, int x, int row);

}  // namespace mb::test
