// editor_session.h — an Editor on a scene file of the test's own, played like a user plays it.
#pragma once

#include "marchbox/editor/editor.h"
#include "marchbox/scene/scene_io.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <string>
#include <vector>

namespace mb::test {

// A folder per test: CTest runs the tests as processes side by side, and a file name two tests
// share (playedFor's) was read by one while the other rewrote it.
inline std::string tempPath(const std::string& name) {
    const auto* test = testing::UnitTest::GetInstance()->current_test_info();
    std::filesystem::path dir =
        std::filesystem::path(MARCHBOX_BINARY_DIR) / "test-output" / "editor" / test->name();
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

inline std::string writeFile(const std::string& name, const std::string& text) {
    std::string path = tempPath(name);
    std::ofstream(path) << text;
    return path;
}

inline std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// A sphere falling onto the ground beside a static box.
inline const char* const kScene =
    "material r:1 g:0 b:0\n"
    "object type:sphere pos:0,3,0 radius:0.5\n"
    "object type:box pos:3,0.5,0 static:1\n";

inline Editor openEditor(const std::string& path) {
    Editor e;
    std::vector<std::string> errors;
    EXPECT_TRUE(e.request(Leave::Open, path, &errors));
    return e;
}

// Play for `frames` frames of 1/60 s, then pause.
inline void run(Editor& e, int frames) {
    e.togglePlay();
    for (int i = 0; i < frames; ++i) e.frame(1.0 / 60);
    e.togglePlay();
}

// The scene a fresh editor on kScene shows after `frames` frames of play, to compare with.
inline Scene playedFor(int frames) {
    Editor e = openEditor(writeFile("played.txt", kScene));
    run(e, frames);
    return e.scene();
}

inline Scene saved(const std::string& path) {
    Scene s;
    std::vector<std::string> errors;
    EXPECT_TRUE(loadScene(path, &s, &errors));
    return s;
}

}  // namespace mb::test
