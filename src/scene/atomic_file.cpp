// atomic_file.cpp — the temporary-and-rename write. Every call goes through fileOps()
// (file_ops.h), so tests can make each one fail in turn.
#include "marchbox/scene/atomic_file.h"

#include "file_ops.h"

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <csignal>
#include <memory>
#include <mutex>
#include <optional>
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
        ::write,
        ::fsync,
        ::close,
        ::rename,
        ::unlink};
    return ops;
}

namespace {

// Creates a new, empty file beside `path` with a name no one else uses (pid + counter, and
// O_EXCL for anything left over). Returns the descriptor, or -1 with errno set.
int createTemp(const std::string& path, mode_t mode, std::string* tmp) {
    static std::atomic<unsigned> counter{0};
    for (int attempt = 0; attempt < 100; ++attempt) {
        std::string name =
            path + ".tmp" + std::to_string(::getpid()) + "." + std::to_string(counter++);
        int fd = fileOps().open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
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
// soon as it exists, so the caller can remove it whatever happens next. `keep`: the mode of
// the file it replaces, set past the umask, so a private (0600) or shared (0664) file stays so.
int writeTemp(const std::string& path, std::string_view text, std::optional<mode_t> keep,
              std::string* tmp) {
    int fd = createTemp(path, keep.value_or(0666), tmp);
    if (fd < 0) return errno;
    if (keep) ::fchmod(fd, *keep);  // best effort: some file systems have no modes to keep
    int err = writeAll(fd, text);
    if (err == 0 && fileOps().fsync(fd) != 0) err = errno;
    // Closed whatever happened, and checked: NFS may report a failed write only here.
    if (fileOps().close(fd) != 0 && err == 0) err = errno;
    return err;
}

// The file a save replaces: `path`, or the file a symbolic link there points to, so the link
// survives, and that file's permission bits in *mode. Returns "" or why `path` cannot be saved
// to. A device, pipe or folder is refused: the rename would replace it (as root, /dev/stdout
// itself) rather than write into it.
std::string saveTarget(const std::string& path, std::string* target, std::optional<mode_t>* mode) {
    *target = path;
    if (path.empty()) return "no file name";  // the temporary would go in the working folder
    struct stat st;
    if (::stat(path.c_str(), &st) != 0) return "";  // nothing there yet: the save creates it
    if (S_ISDIR(st.st_mode)) return "is a directory";
    if (!S_ISREG(st.st_mode)) return "not a regular file";
    *mode = st.st_mode & 0777;
    if (::lstat(path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return "";
    std::unique_ptr<char, decltype(&std::free)> real(::realpath(path.c_str(), nullptr), std::free);
    if (real) *target = real.get();
    return "";
}

// While a save runs, a Ctrl-C, hangup or kill waits for it to end: dying between the temporary
// and the rename would leave the temporary behind. Only signals whose action is the default
// (to end the process) are held; the first one is raised again once the save is over, so the
// process still ends, with the file whole and nothing beside it. The actions are the process's,
// whichever thread the signal lands on; one save holds them at a time.
class TerminationHeld {
public:
    TerminationHeld() : lock_(mutex()) {
        pending() = 0;
        struct sigaction hold {};
        hold.sa_handler = [](int sig) {
            if (!pending()) pending() = sig;
        };
        sigemptyset(&hold.sa_mask);
        for (int i = 0; i < kCount; ++i) {
            sigaction(kSignals[i], nullptr, &saved_[i]);
            held_[i] =
                saved_[i].sa_handler == SIG_DFL && sigaction(kSignals[i], &hold, nullptr) == 0;
        }
    }
    ~TerminationHeld() {
        for (int i = 0; i < kCount; ++i)
            if (held_[i]) sigaction(kSignals[i], &saved_[i], nullptr);
        if (pending()) raise(pending());
    }
    TerminationHeld(const TerminationHeld&) = delete;
    TerminationHeld& operator=(const TerminationHeld&) = delete;

private:
    static constexpr int kCount = 4;
    static constexpr int kSignals[kCount] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
    static std::mutex& mutex() {
        static std::mutex m;
        return m;
    }
    static volatile std::sig_atomic_t& pending() {
        static volatile std::sig_atomic_t sig = 0;
        return sig;
    }

    std::lock_guard<std::mutex> lock_;
    struct sigaction saved_[kCount];
    bool held_[kCount];
};

}  // namespace

// The directory is not fsynced after the rename: after a crash the rename may be lost, but
// the file left behind is then the old one, whole, which is the promise.
std::string replaceFile(const std::string& path, std::string_view bytes) {
    size_t failed = 0;
    return replaceFiles({{path, bytes}}, &failed);
}

std::string replaceFiles(const std::vector<FileBytes>& files, size_t* failed) {
    TerminationHeld held;
    std::vector<std::string> targets(files.size()), temps(files.size());
    auto fail = [&](size_t k, std::string why) {
        for (const std::string& tmp : temps)
            if (!tmp.empty()) fileOps().unlink(tmp.c_str());
        *failed = k;
        return why;
    };
    for (size_t k = 0; k < files.size(); ++k) {
        std::optional<mode_t> mode;
        if (std::string why = saveTarget(files[k].path, &targets[k], &mode); !why.empty())
            return fail(k, why);
        if (int err = writeTemp(targets[k], files[k].bytes, mode, &temps[k]))
            return fail(k, std::strerror(err));
    }
    for (size_t k = 0; k < files.size(); ++k) {
        if (fileOps().rename(temps[k].c_str(), targets[k].c_str()) != 0)
            return fail(k, std::strerror(errno));
        temps[k].clear();
    }
    return "";
}

std::string checkReplaceFile(const std::string& path) {
    TerminationHeld held;  // dying before the unlink would leave the temporary
    std::string target, tmp;
    std::optional<mode_t> mode;
    std::string why = saveTarget(path, &target, &mode);
    if (!why.empty()) return why;
    int fd = createTemp(target, 0600, &tmp);
    if (fd < 0) return std::strerror(errno);
    fileOps().close(fd);
    fileOps().unlink(tmp.c_str());
    return "";
}

}  // namespace mb
