// test_scene_save_faults.cpp — saving when things go wrong: each step of a save fails in turn
// (file_ops.h), the disk fills, the folder is missing or read-only, the process dies mid-save.
// Every time the old file stays whole, no temporary is left, and the error is one clear line.
#include "marchbox/scene/scene_io.h"

#include "marchbox/scene/atomic_file.h"

#include "file_ops.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string_view>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace mb;
namespace fs = std::filesystem;

namespace {

const char* kOld = "scene version:1\n# the user's work, which no failed save may touch\n";

const char* kNew = R"(camera pos:0,2.5,-7 target:0,0.8,0 fov:45
material name:red r:0.9 g:0.15 b:0.1
light pos:3,6,-4
object type:sphere material:0 pos:0,2,0 radius:0.5 mass:2 vel:1,0,0
)";

//-----------------------------------------------------------------------------
// A FileOps table that fails one step, counting descriptors so leaks show
//-----------------------------------------------------------------------------
enum class Step { None, Open, Write, ShortWrite, ZeroWrite, Fsync, Close, Rename };

struct Fault {
    Step step = Step::None;
    int err = EIO;
    int opened = 0, closed = 0;
    bool interruptNextWrite = false;  // one EINTR first, which a save must retry
} g;

int failWith(int err) {
    errno = err;
    return -1;
}

int fakeOpen(const char* path, int flags, mode_t mode) {
    if (g.step == Step::Open) return failWith(g.err);
    int fd = posixOps().open(path, flags, mode);
    g.opened += fd >= 0;
    return fd;
}

// ShortWrite takes half the bytes first, as a filling disk does, then fails.
ssize_t fakeWrite(int fd, const void* buf, size_t n) {
    if (g.interruptNextWrite) {
        g.interruptNextWrite = false;
        return failWith(EINTR);
    }
    if (g.step == Step::Write) return failWith(g.err);
    if (g.step == Step::ZeroWrite) return 0;
    if (g.step != Step::ShortWrite) return posixOps().write(fd, buf, n);
    g.step = Step::Write;
    return posixOps().write(fd, buf, n / 2);
}

int fakeFsync(int fd) { return g.step == Step::Fsync ? failWith(g.err) : posixOps().fsync(fd); }

// A failed close still releases the descriptor on Linux; so does this one.
int fakeClose(int fd) {
    ++g.closed;
    int rc = posixOps().close(fd);
    return g.step == Step::Close ? failWith(g.err) : rc;
}

int fakeRename(const char* from, const char* to) {
    return g.step == Step::Rename ? failWith(g.err) : posixOps().rename(from, to);
}

const FileOps kFaulty{fakeOpen, fakeWrite, fakeFsync, fakeClose, fakeRename, ::unlink};

//-----------------------------------------------------------------------------
// A temporary folder holding the old file
//-----------------------------------------------------------------------------
class SaveFaults : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("marchbox_faults_" + std::to_string(getpid()));
        fs::create_directories(dir_);
        std::ofstream(target(), std::ios::binary) << kOld;
        ASSERT_TRUE(parseScene(kNew, &scene_, nullptr));
        g = Fault{};
    }
    void TearDown() override {
        fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add);
        fs::remove_all(dir_);
    }
    std::string target() const { return (dir_ / "scene.txt").string(); }
    std::string oldBytes() const {
        std::ifstream in(target(), std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    }
    size_t fileCount() const {
        return size_t(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
    }
    // The promise of every failed save: one line naming the file, old file whole, no temporary,
    // the scene in memory unchanged, no descriptor left open.
    void expectFailedSaveKeptEverything(const std::string& why) {
        const Scene before = scene_;
        std::string error;
        EXPECT_FALSE(saveScene(target(), scene_, &error));
        EXPECT_EQ(error, "cannot save '" + target() + "': " + why);
        EXPECT_EQ(error.find('\n'), std::string::npos);
        EXPECT_EQ(oldBytes(), kOld);
        EXPECT_EQ(fileCount(), 1u) << "a temporary was left beside the target";
        EXPECT_EQ(scene_, before);
        EXPECT_EQ(g.opened, g.closed) << "a descriptor leaked";
    }

    fs::path dir_;
    Scene scene_;
};

// Runs `body` in a child process and returns its exit status: for changes a test must not
// leave behind in the test runner (user id, file-size limit) and for dying mid-save.
int inChild(const std::function<int()>& body) {
    pid_t pid = fork();
    if (pid == 0) _exit(body());
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

//-----------------------------------------------------------------------------
// Each step of a save fails
//-----------------------------------------------------------------------------
struct StepCase {
    Step step;
    int err;
    const char* name;
};

// Names the case in CTest's list instead of a dump of the struct's bytes.
void PrintTo(const StepCase& c, std::ostream* os) { *os << c.name; }

class EachStepFails : public SaveFaults, public ::testing::WithParamInterface<StepCase> {};

TEST_P(EachStepFails, OldFileWholeSceneIntactOneLineError) {
    g.step = GetParam().step;
    g.err = GetParam().err;
    ScopedFileOps faulty(kFaulty);
    expectFailedSaveKeptEverything(std::strerror(GetParam().err));
}

INSTANTIATE_TEST_SUITE_P(Save, EachStepFails,
                         ::testing::Values(StepCase{Step::Open, EACCES, "Open"},
                                           StepCase{Step::Open, EMFILE, "OpenNoDescriptors"},
                                           StepCase{Step::Write, EIO, "Write"},
                                           StepCase{Step::ShortWrite, ENOSPC, "DiskFillsMidWrite"},
                                           StepCase{Step::ZeroWrite, EIO, "WriteTakesNothing"},
                                           StepCase{Step::Fsync, EIO, "Fsync"},
                                           StepCase{Step::Close, EDQUOT, "Close"},
                                           StepCase{Step::Rename, EXDEV, "Rename"}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST_F(SaveFaults, InterruptedWriteIsRetriedAndTheSaveSucceeds) {
    g.interruptNextWrite = true;
    ScopedFileOps faulty(kFaulty);
    std::string error;
    ASSERT_TRUE(saveScene(target(), scene_, &error)) << error;
    EXPECT_EQ(oldBytes(), formatScene(scene_));
    EXPECT_EQ(fileCount(), 1u);
    EXPECT_EQ(g.opened, g.closed);
}

// An OBJ and the MTL it names go together: the second file's write fails (a full disk), and the
// first, already written beside its own, is not renamed over it either; with no fault both are
// replaced. Planted: each file renamed as soon as it was written (the MTL was replaced and the
// OBJ not, a pair that did not match).
TEST_F(SaveFaults, FilesThatGoTogetherAreReplacedTogetherOrNotAtAll) {
    const std::string mtl = (dir_ / "solids.mtl").string();
    std::ofstream(mtl, std::ios::binary) << "old mtl\n";
    auto read = [](const std::string& path) {
        std::ifstream in(path, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    FileOps ops = posixOps();
    ops.open = [](const char* path, int flags, mode_t mode) {
        return std::string_view(path).find("scene.txt") != std::string_view::npos
                   ? failWith(ENOSPC)
                   : posixOps().open(path, flags, mode);
    };
    size_t failed = 0;
    {
        ScopedFileOps full(ops);
        EXPECT_EQ(replaceFiles({{mtl, "new mtl\n"}, {target(), "new obj\n"}}, &failed),
                  std::strerror(ENOSPC));
    }
    EXPECT_EQ(failed, 1u);
    EXPECT_EQ(read(mtl), "old mtl\n");
    EXPECT_EQ(oldBytes(), kOld);
    EXPECT_EQ(fileCount(), 2u) << "a temporary was left beside a file";
    EXPECT_EQ(replaceFiles({{mtl, "new mtl\n"}, {target(), "new obj\n"}}, &failed), "");
    EXPECT_EQ(read(mtl), "new mtl\n");
    EXPECT_EQ(oldBytes(), "new obj\n");
    EXPECT_EQ(fileCount(), 2u);
}

TEST_F(SaveFaults, TableIsRestoredAfterEachTest) {
    std::string error;
    EXPECT_TRUE(saveScene(target(), scene_, &error)) << error;
    EXPECT_EQ(fileOps().write, posixOps().write);
}

//-----------------------------------------------------------------------------
// Real failures from the kernel
//-----------------------------------------------------------------------------
// /dev/full takes the place of the temporary: every write is a real ENOSPC.
TEST_F(SaveFaults, FullDiskFromDevFull) {
    FileOps ops = posixOps();
    ops.open = [](const char*, int, mode_t) { return ::open("/dev/full", O_WRONLY | O_CLOEXEC); };
    ScopedFileOps full(ops);
    expectFailedSaveKeptEverything(std::strerror(ENOSPC));
}

// A file-size limit makes the kernel refuse the write past it (EFBIG) with no root and no
// small file system; in a child, so the test runner keeps its own limits.
TEST_F(SaveFaults, FileSizeLimitFailsTheWrite) {
    int code = inChild([&] {
        std::signal(SIGXFSZ, SIG_IGN);  // else the kernel kills the writer instead of failing
        rlimit limit{16, 16};
        if (setrlimit(RLIMIT_FSIZE, &limit) != 0) return 2;
        std::string error;
        if (saveScene(target(), scene_, &error)) return 3;
        return error == "cannot save '" + target() + "': " + std::strerror(EFBIG) ? 0 : 4;
    });
    EXPECT_EQ(code, 0);
    EXPECT_EQ(oldBytes(), kOld);
    EXPECT_EQ(fileCount(), 1u);
}

// Dying between the write and the rename (a laptop closed, a kill) leaves the old file whole.
TEST_F(SaveFaults, DyingBeforeTheRenameLeavesTheOldFileWhole) {
    int code = inChild([&] {
        FileOps ops = posixOps();
        ops.rename = [](const char*, const char*) -> int { _exit(42); };
        fileOps() = ops;
        saveScene(target(), scene_, nullptr);
        return 0;
    });
    ASSERT_EQ(code, 42);
    EXPECT_EQ(oldBytes(), kOld);
}

// A Ctrl-C in the middle of a save (here, just before the rename) waits for the save to end:
// the process still dies of it, but after the new file is in place, with no temporary beside it.
TEST_F(SaveFaults, CtrlCMidSaveEndsTheProcessAfterTheSave) {
    int code = inChild([&] {
        std::signal(SIGINT, SIG_DFL);  // a shell's background job starts with it ignored
        FileOps ops = posixOps();
        ops.rename = [](const char* from, const char* to) {
            kill(getpid(), SIGINT);
            return posixOps().rename(from, to);
        };
        fileOps() = ops;
        saveScene(target(), scene_, nullptr);
        return 0;
    });
    ASSERT_EQ(code, 128 + SIGINT);
    EXPECT_EQ(oldBytes(), formatScene(scene_));
    EXPECT_EQ(fileCount(), 1u) << "a temporary was left beside the target";
}

// After a save every signal's action is what it was: the default ends the process again, and
// an action the program chose (here, ignoring hangups) was never touched.
TEST_F(SaveFaults, SignalActionsAreAsBeforeAfterASave) {
    int code = inChild([&] {
        std::signal(SIGINT, SIG_DFL);  // whatever the test was started with
        std::signal(SIGHUP, SIG_IGN);
        std::string error;
        if (!saveScene(target(), scene_, &error)) return 3;
        struct sigaction interrupt {
        }, hangup{};
        sigaction(SIGINT, nullptr, &interrupt);
        sigaction(SIGHUP, nullptr, &hangup);
        return interrupt.sa_handler == SIG_DFL && hangup.sa_handler == SIG_IGN ? 0 : 4;
    });
    EXPECT_EQ(code, 0);
}

//-----------------------------------------------------------------------------
// Places a scene cannot be saved
//-----------------------------------------------------------------------------
TEST_F(SaveFaults, MissingFolderIsOneClearError) {
    std::string path = (dir_ / "no_such_folder" / "scene.txt").string(), error;
    EXPECT_FALSE(saveScene(path, scene_, &error));
    EXPECT_EQ(error, "cannot save '" + path + "': No such file or directory");
    EXPECT_EQ(fileCount(), 1u);
}

TEST_F(SaveFaults, FileInPlaceOfAFolderIsOneClearError) {
    std::string path = target() + "/scene.txt", error;
    EXPECT_FALSE(saveScene(path, scene_, &error));
    EXPECT_EQ(error, "cannot save '" + path + "': Not a directory");
    EXPECT_EQ(oldBytes(), kOld);
}

// Root ignores folder permissions, so as root the save runs as `nobody` in a child process.
TEST_F(SaveFaults, ReadOnlyFolderIsOneClearError) {
    fs::permissions(dir_, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                              fs::perms::group_exec | fs::perms::others_read |
                              fs::perms::others_exec);
    int code = inChild([&] {
        const uid_t nobody = 65534;
        if (geteuid() == 0 && (setgid(nobody) != 0 || setuid(nobody) != 0)) return 2;
        std::string error;
        if (checkReplaceFile(target()) != "Permission denied") return 5;
        if (saveScene(target(), scene_, &error)) return 3;
        return error == "cannot save '" + target() + "': Permission denied" ? 0 : 4;
    });
    EXPECT_EQ(code, 0) << "2: cannot become nobody, 3: saved anyway, 4: another message, "
                          "5: the check before saving missed it";
    EXPECT_EQ(oldBytes(), kOld);
    EXPECT_EQ(fileCount(), 1u);
}

TEST_F(SaveFaults, FolderAsTargetIsRefused) {
    std::string error;
    EXPECT_FALSE(saveScene(dir_.string(), scene_, &error));
    EXPECT_EQ(error, "cannot save '" + dir_.string() + "': is a directory");
    EXPECT_EQ(fileCount(), 1u);
}

// A rename would replace the device node itself (as root, for every program on the machine).
TEST_F(SaveFaults, DeviceAsTargetIsRefusedAndLeftAlone) {
    std::string error;
    EXPECT_FALSE(saveScene("/dev/null", scene_, &error));
    EXPECT_EQ(error, "cannot save '/dev/null': not a regular file");
    struct stat st;
    ASSERT_EQ(stat("/dev/null", &st), 0);
    EXPECT_TRUE(S_ISCHR(st.st_mode));
}

// File > Render checks before minutes of work: each place above is found, in the save's words,
// and the check writes nothing, where it fails or not.
TEST_F(SaveFaults, TheCheckBeforeSavingFindsEachPlaceAndWritesNothing) {
    const std::string places[] = {(dir_ / "no_such_folder" / "scene.txt").string(),
                                  target() + "/scene.txt", dir_.string(), "/dev/null", ""};
    for (const std::string& path : places) {
        std::string error;
        EXPECT_FALSE(saveScene(path, scene_, &error));
        EXPECT_EQ("cannot save '" + path + "': " + checkReplaceFile(path), error);
    }
    EXPECT_EQ(checkReplaceFile((dir_ / "new.txt").string()), "");
    EXPECT_EQ(checkReplaceFile(target()), "");
    EXPECT_EQ(oldBytes(), kOld);
    EXPECT_EQ(fileCount(), 1u);
}

// The rename puts a new file in place: it must not trade a private file's mode for the umask's.
TEST_F(SaveFaults, TheReplacedFilesModeIsKept) {
    for (fs::perms mode : {fs::perms(0600), fs::perms(0664), fs::perms(0640)}) {
        fs::permissions(target(), mode);
        std::string error;
        ASSERT_TRUE(saveScene(target(), scene_, &error)) << error;
        EXPECT_EQ(int(fs::status(target()).permissions()), int(mode)) << "modes in decimal";
    }
}

TEST_F(SaveFaults, SymlinkSurvivesAndItsFileIsSaved) {
    fs::create_symlink(target(), dir_ / "link.txt");
    std::string error;
    ASSERT_TRUE(saveScene((dir_ / "link.txt").string(), scene_, &error)) << error;
    EXPECT_TRUE(fs::is_symlink(dir_ / "link.txt"));
    EXPECT_EQ(oldBytes(), formatScene(scene_));
    EXPECT_EQ(fileCount(), 2u);
}
