// test_recent.cpp — File > Open Recent's list: where it lives, its order, and its file.
#include "marchbox/editor/recent.h"

#include "../scoped_env.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

#include "../fresh_dir.h"

using namespace mb;
using mb::test::ScopedEnv;
namespace fs = std::filesystem;

static fs::path freshDir(const std::string& name) {
    return mb::test::freshDir("editor-recent", name);
}

TEST(RecentFiles, LivesUnderXdgConfigHomeElseDotConfig) {
    ScopedEnv home("HOME", "/home/someone");
    {
        ScopedEnv xdg("XDG_CONFIG_HOME", "/etc/xdg-here");
        EXPECT_EQ(recentFilesPath(), "/etc/xdg-here/marchbox/recent.txt");
    }
    {
        ScopedEnv xdg("XDG_CONFIG_HOME", "relative/config");  // not absolute: ignored
        EXPECT_EQ(recentFilesPath(), "/home/someone/.config/marchbox/recent.txt");
    }
    ScopedEnv xdg("XDG_CONFIG_HOME", nullptr);
    EXPECT_EQ(recentFilesPath(), "/home/someone/.config/marchbox/recent.txt");
    ScopedEnv noHome("HOME", nullptr);
    EXPECT_EQ(recentFilesPath(), "");
}

TEST(RecentFiles, NewestFirstOnceAtMostTenAndKeptInTheFile) {
    fs::path dir = freshDir("order");
    const std::string file = (dir / "config" / "marchbox" / "recent.txt").string();
    RecentFiles r(file);  // no file yet: an empty list
    EXPECT_TRUE(r.paths().empty());
    for (int i = 0; i < 12; ++i)
        EXPECT_EQ(r.add((dir / ("s" + std::to_string(i) + ".txt")).string()), "");
    EXPECT_EQ(r.add((dir / "sub" / ".." / "s5.txt").string()), "");  // the same file again
    ASSERT_EQ(r.paths().size(), RecentFiles::kMax);
    EXPECT_EQ(r.paths()[0], (dir / "s5.txt").string());
    EXPECT_EQ(r.paths()[1], (dir / "s11.txt").string());
    EXPECT_EQ(std::count(r.paths().begin(), r.paths().end(), (dir / "s5.txt").string()), 1);
    EXPECT_EQ(r.paths().back(), (dir / "s2.txt").string());  // s0 and s1 fell off the end

    RecentFiles again(file);  // another session reads what this one wrote
    EXPECT_EQ(again.paths(), r.paths());
    EXPECT_EQ(again.clear(), "");
    EXPECT_TRUE(RecentFiles(file).paths().empty());
}

TEST(RecentFiles, PathsAreMadeWhole) {
    RecentFiles r;  // in memory: nothing written
    EXPECT_EQ(r.add("scenes/a.txt"), "");
    ASSERT_EQ(r.paths().size(), 1u);
    EXPECT_EQ(r.paths()[0], (fs::current_path() / "scenes" / "a.txt").string());
    EXPECT_EQ(r.add("two\nlines.txt"), "");
    EXPECT_EQ(r.paths().size(), 1u);
}

TEST(RecentFiles, AFileThatCannotBeWrittenSaysWhyAndKeepsTheList) {
    fs::path dir = freshDir("unwritable");
    std::ofstream(dir / "blocker") << "a file where the folder should be\n";
    RecentFiles r((dir / "blocker" / "recent.txt").string());
    std::string why = r.add((dir / "a.txt").string());
    EXPECT_NE(why.find("cannot write the recent files list"), std::string::npos) << why;
    EXPECT_EQ(r.paths().size(), 1u);
}

TEST(RecentFiles, ReadsOnlySensibleLines) {
    fs::path dir = freshDir("read");
    const std::string file = (dir / "recent.txt").string();
    std::ofstream(file) << "/a.txt\r\n\n/b.txt\n/a.txt\n" << std::string(5000, 'x') << "\n";
    RecentFiles r(file);
    EXPECT_EQ(r.paths(), (std::vector<std::string>{"/a.txt", "/b.txt"}));
}
