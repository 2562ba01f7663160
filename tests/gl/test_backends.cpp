// test_backends.cpp — the EGL path draws what the OSMesa path draws (on one machine, one driver).
#include "golden.h"

#include <gtest/gtest.h>

using namespace mb;

TEST(Backends, EglDrawsWhatOsMesaDraws) {
    Scene s = test::loadSceneOrDie("scenes/csg.txt");
    Image osmesa = test::renderOrDie(s, {}, 160, 90), egl;
    std::string error;
    OffscreenRun run;
    run.backend = OffscreenBackend::Egl;
    if (!renderOffscreen(s, {}, 160, 90, &egl, &error, run))
        GTEST_SKIP() << "no EGL here: " << error;
    ImageDiff d = diffImages(osmesa, egl);
    // Both are llvmpipe on this machine; on a GPU the shaders' rounding would differ more.
    EXPECT_LE(d.meanAbs, 0.5);
    EXPECT_LE(d.p99, 4.0);
}
