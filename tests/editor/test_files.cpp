// test_files.cpp — Save As's proposal, the starting scene and the shader folder watch.
#include "marchbox/editor/files.h"
#include "marchbox/scene/scene_io.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

#include "../fresh_dir.h"

using namespace mb;
namespace fs = std::filesystem;

static fs::path freshDir(const std::string& name) {
    return mb::test::freshDir("editor-files", name);
}

TEST(Files, WatchNoticesRewrites) {
    fs::path dir = freshDir("watch");
    std::ofstream(dir / "a.glsl") << "one\n";
    FolderWatch watch(dir.string());
    EXPECT_FALSE(watch.changed());
    fs::last_write_time(dir / "a.glsl",
                        fs::last_write_time(dir / "a.glsl") + std::chrono::seconds(2));
    EXPECT_TRUE(watch.changed());
    EXPECT_FALSE(watch.changed());
    std::ofstream(dir / "b.glsl") << "two\n";
    EXPECT_TRUE(watch.changed());
}

// A new scene's Save As proposed "scenes/untitled.txt", relative to the working
// folder, which fails outside the source tree.
TEST(Files, SaveAsProposesAWholePathBesideTheLastFile) {
    fs::path dir = freshDir("propose");
    const std::string last = (dir / "sub" / ".." / "mine.txt").string();
    EXPECT_EQ(proposeSavePath("", last), (dir / "untitled.txt").string());
    std::ofstream(dir / "untitled.txt") << "\n";
    std::ofstream(dir / "untitled-2.txt") << "\n";
    EXPECT_EQ(proposeSavePath("", last), (dir / "untitled-3.txt").string());  // never over a file
    EXPECT_EQ(proposeSavePath((dir / "a.txt").string(), last), (dir / "a.txt").string());
    const std::string none = proposeSavePath("", "");
    EXPECT_TRUE(fs::path(none).is_absolute()) << none;
    EXPECT_EQ(fs::path(none).parent_path(), fs::current_path());
    EXPECT_TRUE(fs::path(proposeSavePath("relative/b.txt", "")).is_absolute());
}

TEST(Files, StartingWithNoFileGivesAnUntitledCopyOfTheDefault) {
    const std::string example = std::string(MARCHBOX_SOURCE_DIR) + "/scenes/default.txt";
    Scene scene, expected;
    std::string file = "unset";
    std::vector<std::string> errors;
    ASSERT_TRUE(startingScene("", example, &scene, &file, &errors));
    ASSERT_TRUE(loadScene(example, &expected, &errors));
    EXPECT_EQ(file, "");  // Save asks where: never over the example
    EXPECT_EQ(scene.objects.size(), expected.objects.size());
}

TEST(Files, StartingOnAFileNotYetThereGivesAnEmptySceneToSaveThere) {
    fs::path dir = freshDir("start");
    const std::string path = (dir / "new.txt").string();
    Scene scene;
    std::string file;
    std::vector<std::string> errors;
    ASSERT_TRUE(startingScene(path, "/no/default.txt", &scene, &file, &errors));
    EXPECT_EQ(file, path);
    EXPECT_TRUE(scene.objects.empty());
    EXPECT_EQ(scene.lights.size(), 1u);
    EXPECT_TRUE(scene.world.ground);
    EXPECT_FALSE(fs::exists(path));  // written by the first Save only

    // In a folder that does not exist it is an error, saying so, as any file that cannot be read.
    const std::string nowhere = (dir / "missing" / "new.txt").string();
    EXPECT_FALSE(startingScene(nowhere, "/no/default.txt", &scene, &file, &errors));
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0], nowhere + ": cannot open: No such file or directory");
}
