// test_file_on_disk.cpp — the open scene's file changed elsewhere: reloaded, asked about, and
// never saved over unasked.
#include "editor_session.h"

#include "marchbox/editor/disk_file.h"

#include <chrono>

using namespace mb;
using namespace mb::test;
namespace fs = std::filesystem;

// The same scene with a blue material: what `sed -i s/r:1 g:0 b:0/r:0 g:0 b:1/` makes of it.
static const char* kBlue =
    "material r:0 g:0 b:1\n"
    "object type:sphere pos:0,3,0 radius:0.5\n"
    "object type:box pos:3,0.5,0 static:1\n";

// Written elsewhere: a second later by the file's clock, as an edit a moment after the load is
// (two writes within one kernel tick can share a time).
static void editElsewhere(const std::string& path, const std::string& text) {
    const auto before = fs::last_write_time(path);
    std::ofstream(path, std::ios::trunc) << text;
    fs::last_write_time(path, before + std::chrono::seconds(1));
}

static DiskFile tracking(const std::string& path) {
    DiskFile f;
    f.track(path);
    return f;
}

TEST(DiskFile, ASameTextRewrittenIsNoChange) {
    const std::string path = writeFile("same.txt", kScene);
    DiskFile f = tracking(path);
    editElsewhere(path, kScene);
    EXPECT_FALSE(f.changedElsewhere());
    EXPECT_FALSE(f.differs());
}

TEST(DiskFile, ANewTextIsToldOnceAndDiffersUntilAccepted) {
    const std::string path = writeFile("new.txt", kScene);
    DiskFile f = tracking(path);
    editElsewhere(path, kBlue);
    EXPECT_TRUE(f.changedElsewhere());
    EXPECT_FALSE(f.changedElsewhere());  // told already
    EXPECT_TRUE(f.differs());
    f.accept();
    EXPECT_FALSE(f.differs());
    editElsewhere(path, kScene);  // and back: new again
    EXPECT_TRUE(f.changedElsewhere());
}

TEST(DiskFile, AFileGoneIsNoChangeToActOn) {
    const std::string path = writeFile("gone.txt", kScene);
    DiskFile f = tracking(path);
    fs::remove(path);
    EXPECT_FALSE(f.changedElsewhere());
    EXPECT_FALSE(f.differs());
}

static glm::vec3 colour(const Editor& e) { return e.scene().materials[0].color; }

TEST(FileOnDisk, AChangeElsewhereReloadsACleanSceneAsOneUndoStep) {
    const std::string path = writeFile("clean.txt", kScene);
    Editor e = openEditor(path);
    std::vector<std::string> errors;
    e.watchFile(&errors);
    EXPECT_EQ(colour(e), glm::vec3(1, 0, 0));  // nothing changed yet
    editElsewhere(path, kBlue);
    e.watchFile(&errors);
    EXPECT_TRUE(errors.empty());
    EXPECT_FALSE(e.diskChanged());
    EXPECT_EQ(colour(e), glm::vec3(0, 0, 1));
    EXPECT_FALSE(e.document().dirty());
    EXPECT_EQ(e.document().history().undoLabel(), "Reload from disk");
    ASSERT_TRUE(e.undo());
    EXPECT_EQ(colour(e), glm::vec3(1, 0, 0));
    EXPECT_TRUE(e.document().dirty());  // the file holds blue now
}

TEST(FileOnDisk, AChangeElsewhereAsksWhenTheSceneHasEdits) {
    const std::string path = writeFile("dirty.txt", kScene);
    Editor e = openEditor(path);
    e.edit("Move", [](Scene& s) { s.objects[0].pos.x = 1; });
    editElsewhere(path, kBlue);
    std::vector<std::string> errors;
    e.watchFile(&errors);
    ASSERT_TRUE(e.diskChanged());
    EXPECT_EQ(colour(e), glm::vec3(1, 0, 0));  // nothing lost while it asks
    EXPECT_EQ(e.scene().objects[0].pos.x, 1.0f);
    ASSERT_TRUE(e.loadTheirs(&errors));
    EXPECT_FALSE(e.diskChanged());
    EXPECT_EQ(colour(e), glm::vec3(0, 0, 1));
    EXPECT_EQ(e.scene().objects[0].pos.x, 0.0f);
    ASSERT_TRUE(e.undo());  // the edit comes back
    EXPECT_EQ(e.scene().objects[0].pos.x, 1.0f);
    EXPECT_EQ(colour(e), glm::vec3(1, 0, 0));
}

// The text editor's change had not been seen when Save came: it refuses, asks, and writes
// only once the user keeps their own.
TEST(FileOnDisk, SaveNeverWritesOverAChangeItWasNotToldOf) {
    const std::string path = writeFile("save.txt", kScene);
    Editor e = openEditor(path);
    e.edit("Move", [](Scene& s) { s.objects[0].pos.x = 1; });
    editElsewhere(path, kBlue);
    std::string error;
    EXPECT_FALSE(e.save(&error));
    EXPECT_EQ(error, "save.txt changed on disk since it was opened or saved: keep yours, or "
                     "load theirs");
    EXPECT_TRUE(e.diskChanged());
    EXPECT_EQ(readText(path), kBlue);
    ASSERT_TRUE(e.keepMine(&error)) << error;
    EXPECT_FALSE(e.diskChanged());
    EXPECT_EQ(saved(path).objects[0].pos.x, 1.0f);
    EXPECT_EQ(saved(path).materials[0].color, glm::vec3(1, 0, 0));
    EXPECT_FALSE(e.document().dirty());
}

TEST(FileOnDisk, AChangeThatDoesNotLoadLeavesTheSceneAndSaysWhere) {
    const std::string path = writeFile("broken.txt", kScene);
    Editor e = openEditor(path);
    editElsewhere(path, "object type:sphere pos:0,1\n");
    std::vector<std::string> errors;
    e.watchFile(&errors);
    ASSERT_FALSE(errors.empty());
    EXPECT_EQ(errors[0].rfind(path + ":1:", 0), 0u) << errors[0];
    EXPECT_EQ(e.scene().objects.size(), 2u);
    errors.clear();
    e.watchFile(&errors);  // said once
    EXPECT_TRUE(errors.empty());
    editElsewhere(path, kBlue);  // mended: loads
    e.watchFile(&errors);
    EXPECT_EQ(colour(e), glm::vec3(0, 0, 1));
}

TEST(FileOnDisk, AReloadAtALaterTimeGoesBackToTheNewStart) {
    const std::string path = writeFile("later.txt", kScene);
    Editor e = openEditor(path);
    run(e, 30);
    editElsewhere(path, kBlue);
    std::vector<std::string> errors;
    e.watchFile(&errors);
    EXPECT_EQ(e.document().time(), 0.0);
    EXPECT_EQ(e.scene().objects[0].pos, glm::vec3(0, 3, 0));
    EXPECT_EQ(colour(e), glm::vec3(0, 0, 1));
    ASSERT_TRUE(e.undo());  // back to the run, where it was
    EXPECT_NEAR(e.document().time(), 0.5, 1e-9);
}

TEST(FileOnDisk, OwnSavesAreNoChange) {
    const std::string path = writeFile("own.txt", kScene);
    Editor e = openEditor(path);
    e.edit("Move", [](Scene& s) { s.objects[0].pos.x = 1; });
    std::string error;
    ASSERT_TRUE(e.save(&error)) << error;
    std::vector<std::string> errors;
    e.watchFile(&errors);
    EXPECT_FALSE(e.diskChanged());
    EXPECT_EQ(e.document().history().undoLabel(), "Move");
}
