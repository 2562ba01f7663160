// scene_file.cpp — scene files on disk (POSIX). loadScene reads a whole file with a size cap;
// saveScene writes a temporary file beside the target, fsyncs it and renames it over the
// target, so a reader sees either the old file or the new one, never a part. Every call a
// save makes goes through fileOps() (file_ops.h), so tests can make each one fail in turn.
#include "marchbox/scene_io.h"

#include "file_ops.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <memory>
#include <sys/stat.h>
#include <unistd.h>

namespace mb {

FileOps& fileOps() {
    static FileOps ops = posixOps();
    return ops;
}

const FileOps& posixOps() {
    // ::open is variadic; the table's fixed signature needs a wrapper.
    static const FileOps ops{
        [](const char* path, int flags, mode_t mode) { return ::open(path, flags, mode); },
        ::write, ::fsync, ::close, ::rename, ::unlink};
    return ops;
}

namespace {

constexpr size_t kMaxFileBytes = size_t(64) << 20;  // scenes are kilobytes; refuse the absurd

struct FileCloser {
    int fd;
    ~FileCloser() { ::close(fd); }  // read-only: a failed close loses nothing
};

// Reads all of an open file into *text. Returns "" or what went wrong. The size is checked
// as it grows too, since pipes and devices have no size to check up front.
std::string readAll(int fd, std::string* text) {
    struct stat st;
    if (::fstat(fd, &st) != 0) return std::string("cannot read: ") + std::strerror(errno);
    if (S_ISDIR(st.st_mode)) return "is a directory";
    const char* tooLarge = "larger than 64 MiB";
    if (st.st_size > off_t(kMaxFileBytes)) return tooLarge;
    text->reserve(size_t(std::max<off_t>(st.st_size, 0)));
    char buf[1 << 16];
    for (;;) {
        ssize_t n = ::read(fd, buf, sizeof buf);
        if (n == 0) return "";
        if (n < 0 && errno != EINTR) return std::string("cannot read: ") + std::strerror(errno);
        if (n > 0) text->append(buf, size_t(n));
        if (text->size() > kMaxFileBytes) return tooLarge;
    }
}

std::string readFile(const std::string& path, std::string* text) {
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return std::string("cannot open: ") + std::strerror(errno);
    FileCloser closer{fd};
    return readAll(fd, text);
}

std::string formatError(const std::string& path, const SceneError& e) {
    if (e.line == 0) return path + ": " + e.message;
    return path + ":" + std::to_string(e.line) + ": " + e.message;
}

// Creates a new, empty file beside `path` with a name no one else uses (pid + counter, and
// O_EXCL for anything left over). Returns the descriptor, or -1 with errno set.
int createTemp(const std::string& path, std::string* tmp) {
    static std::atomic<unsigned> counter{0};
    for (int attempt = 0; attempt < 100; ++attempt) {
        std::string name = path + ".tmp" + std::to_string(::getpid()) + "." +
                           std::to_string(counter++);
        int fd = fileOps().open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) *tmp = name;
        if (fd >= 0 || errno != EEXIST) return fd;
    }
    errno = EEXIST;
    return -1;
}

// Returns 0 or an errno. A write that takes nothing would loop for ever, so it is an error.
int writeAll(int fd, std::string_view text) {
    while (!text.empty()) {
        ssize_t n = fileOps().write(fd, text.data(), text.size());
        if (n == 0) return EIO;
        if (n < 0 && errno != EINTR) return errno;
        if (n > 0) text.remove_prefix(size_t(n));
    }
    return 0;
}

// Writes `text` to a new temporary file beside `path` and flushes it to disk; no stdio
// buffer is involved, so fsync is the flush. Returns 0 or an errno. *tmp names the file as
// soon as it exists, so the caller can remove it whatever happens next.
int writeTemp(const std::string& path, std::string_view text, std::string* tmp) {
    int fd = createTemp(path, tmp);
    if (fd < 0) return errno;
    int err = writeAll(fd, text);
    if (err == 0 && fileOps().fsync(fd) != 0) err = errno;
    // Closed whatever happened, and checked: NFS may report a failed write only here.
    if (fileOps().close(fd) != 0 && err == 0) err = errno;
    return err;
}

// The file a save replaces: `path`, or the file a symbolic link there points to, so the link
// survives. Returns "" or why `path` cannot be saved to. A device, pipe or folder is refused:
// the rename would replace it (as root, /dev/stdout itself) rather than write into it.
std::string saveTarget(const std::string& path, std::string* target) {
    *target = path;
    struct stat st;
    if (::stat(path.c_str(), &st) != 0) return "";  // nothing there yet: the save creates it
    if (S_ISDIR(st.st_mode)) return "is a directory";
    if (!S_ISREG(st.st_mode)) return "not a regular file";
    if (::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return "";
    std::unique_ptr<char, decltype(&std::free)> real(::realpath(path.c_str(), nullptr), std::free);
    if (real) *target = real.get();
    return "";
}

}  // namespace

bool loadScene(const std::string& path, Scene* out, std::vector<std::string>* errors) {
    std::string text;
    std::vector<SceneError> found;
    std::string why = readFile(path, &text);
    if (!why.empty()) found.push_back({0, why});
    bool ok = why.empty() && parseScene(text, out, &found);
    if (errors) {
        errors->clear();
        for (const SceneError& e : found) errors->push_back(formatError(path, e));
    }
    return ok;
}

// The directory is not fsynced after the rename: after a crash the rename may be lost, but
// the file left behind is then the old one, whole, which is the promise.
bool saveScene(const std::string& path, const Scene& scene, std::string* error) {
    std::string target, tmp;
    std::string why = saveTarget(path, &target);
    if (why.empty()) {
        int err = writeTemp(target, formatScene(scene), &tmp);
        if (err == 0 && fileOps().rename(tmp.c_str(), target.c_str()) != 0) err = errno;
        if (err == 0) return true;
        why = std::strerror(err);
    }
    if (!tmp.empty()) fileOps().unlink(tmp.c_str());
    if (error) *error = "cannot save '" + path + "': " + why;
    return false;
}

}  // namespace mb
