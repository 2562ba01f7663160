// scene_file.cpp — scene files on disk (POSIX). loadScene reads a whole file with a size cap;
// saveScene replaces the file atomically (atomic_file.h).
#include "marchbox/scene/scene_io.h"

#include "marchbox/scene/atomic_file.h"
#include "marchbox/scene/printable.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <memory>
#include <sys/stat.h>
#include <unistd.h>

namespace mb {

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

// A name with a newline in it would make the one error two lines; its control bytes show as '?'.
std::string formatError(const std::string& path, const SceneError& e) {
    if (e.line == 0) return printable(path) + ": " + e.message;
    return printable(path) + ":" + std::to_string(e.line) + ": " + e.message;
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

static bool saveResult(const std::string& path, const std::string& why, std::string* error) {
    if (!why.empty() && error) *error = "cannot save '" + printable(path) + "': " + why;
    return why.empty();
}

bool saveScene(const std::string& path, const Scene& scene, std::string* error) {
    return saveResult(path, replaceFile(path, formatScene(scene)), error);
}

bool checkSaveScene(const std::string& path, std::string* error) {
    return saveResult(path, checkReplaceFile(path), error);
}

}  // namespace mb
