// test_file_browser.cpp — the folder File > Open and Save As browse.
#include "marchbox/editor/file_browser.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

#include "../fresh_dir.h"

using namespace mb;
namespace fs = std::filesystem;

static fs::path freshDir(const std::string& name) {
    return mb::test::freshDir("file-browser", name);
}

static std::vector<std::string> names(const FolderView& v) {
    std::vector<std::string> out;
    for (const FolderEntry& e : v.entries) out.push_back(e.name + (e.folder ? "/" : ""));
    return out;
}

TEST(FileBrowser, ListsFoldersThenSceneFilesByName) {
    fs::path dir = freshDir("list");
    std::ofstream(dir / "b.txt") << "\n";
    std::ofstream(dir / "A.TXT") << "\n";
    std::ofstream(dir / "notes.md") << "\n";
    std::ofstream(dir / ".hidden.txt") << "\n";
    fs::create_directories(dir / "zoo");
    fs::create_directories(dir / "art.txt");  // a folder, whatever its name
    fs::create_directories(dir / ".git");
    fs::create_symlink(dir / "gone.txt", dir / "broken.txt");
    FolderView view = readFolder(dir.string());
    EXPECT_EQ(view.error, "");
    EXPECT_EQ(view.folder, dir.lexically_normal().string());
    EXPECT_EQ(names(view), (std::vector<std::string>{"art.txt/", "zoo/", "A.TXT", "b.txt"}));
}

TEST(FileBrowser, UnreadableFolderSaysWhy) {
    FolderView view = readFolder("/nonexistent/folder");
    EXPECT_TRUE(view.entries.empty());
    EXPECT_NE(view.error, "");
}

TEST(FileBrowser, WalksUpAndIntoFolders) {
    fs::path dir = freshDir("walk");
    fs::create_directories(dir / "sub");
    const std::string sub = entryPath(dir.string(), "sub");
    EXPECT_EQ(sub, (dir / "sub").string());
    EXPECT_EQ(parentFolder(sub), dir.string());
    EXPECT_EQ(parentFolder(sub + "/"), dir.string());  // a typed trailing slash
    EXPECT_EQ(parentFolder("/"), "/");
    EXPECT_EQ(entryPath(sub, ".."), dir.string());
}

TEST(FileBrowser, TypedPathLeadsToItsFolder) {
    fs::path dir = freshDir("typed");
    fs::create_directories(dir / "sub");
    EXPECT_EQ(folderOf((dir / "sub").string()), (dir / "sub").string());
    EXPECT_EQ(folderOf((dir / "sub" / "new.txt").string()), (dir / "sub").string());
    EXPECT_EQ(folderOf("relative.txt"), fs::current_path().string());
    EXPECT_EQ(folderOf(""), fs::current_path().string());
}

// The places were unlabelled folder names: "scenes", "x1a2b", "me".
TEST(FileBrowser, PlacesAreNamedThenTheFoldersOfRecentFilesByPath) {
    fs::path dir = freshDir("places");
    for (const char* sub : {"home/me/work", "home/me/scenes", "examples", "b"})
        fs::create_directories(dir / sub);
    const fs::path home = dir / "home" / "me";
    const std::vector<std::string> recent = {
        (dir / "b" / "x.txt").string(), (home / "work" / "y.txt").string(),
        (dir / "b" / "z.txt").string(), (dir / "gone" / "w.txt").string(),
        (dir / "examples" / "v.txt").string()};
    auto places = placesToBrowse(recent, (dir / "examples").string(), home.string(),
                                 (home / "scenes").string());
    EXPECT_EQ(places, (std::vector<BrowsePlace>{{"Examples", (dir / "examples").string()},
                                                {"Home", home.string()},
                                                {"Working folder", (home / "scenes").string()},
                                                {(dir / "b").string(), (dir / "b").string()},
                                                {"~/work", (home / "work").string()}}));
    EXPECT_EQ(placesToBrowse({}, "", "", (dir / "none").string()), std::vector<BrowsePlace>{});
}
