// file_ops.h — the POSIX calls saveScene makes, behind a table tests can swap (private to core).
//
// Fault-injection tests replace an entry (say `fsync`) with one that fails, save, and check the
// old file is whole. Production code never changes the table; ScopedFileOps restores it.
#pragma once

#include <sys/types.h>

namespace mb {

struct FileOps {
    int (*open)(const char* path, int flags, mode_t mode);
    ssize_t (*write)(int fd, const void* buf, size_t n);
    int (*fsync)(int fd);
    int (*close)(int fd);
    int (*rename)(const char* from, const char* to);
    int (*unlink)(const char* path);
};

FileOps& fileOps();         // the table saveScene calls through
const FileOps& posixOps();  // the real calls, for a test's fake to forward to

// Swaps in `ops` for one scope: tests cannot leave a broken table behind for the next test.
class ScopedFileOps {
public:
    explicit ScopedFileOps(const FileOps& ops) : saved_(fileOps()) { fileOps() = ops; }
    ~ScopedFileOps() { fileOps() = saved_; }
    ScopedFileOps(const ScopedFileOps&) = delete;
    ScopedFileOps& operator=(const ScopedFileOps&) = delete;

private:
    FileOps saved_;
};

}  // namespace mb
