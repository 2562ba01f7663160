// disk_file.cpp — stat first, read and hash only when the stamp moved; never throwing.
#include "marchbox/editor/disk_file.h"

#include <fstream>
#include <iterator>

namespace fs = std::filesystem;

namespace mb {

// FNV-1a over the bytes; a missing or unreadable file hashes as 0, like an unknown one.
static uint64_t textHash(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return 0;
    uint64_t h = 1469598103934665603ull;
    for (std::istreambuf_iterator<char> it(in), end; it != end; ++it)
        h = (h ^ uint64_t(static_cast<unsigned char>(*it))) * 1099511628211ull;
    return h | 1;  // never 0: an empty file is a text
}

void DiskFile::track(const std::string& path) {
    path_ = path;
    time_ = {};
    size_ = 0;
    seen_ = 0;
    look();
    known_ = told_ = seen_;
}

void DiskFile::look() {
    if (path_.empty()) return;
    std::error_code ec;
    const fs::file_time_type time = fs::last_write_time(path_, ec);
    const uintmax_t size = ec ? 0 : fs::file_size(path_, ec);
    if (ec) return;  // gone for now: nothing to compare
    if (time == time_ && size == size_ && seen_ != 0) return;
    time_ = time;
    size_ = size;
    if (const uint64_t h = textHash(path_)) seen_ = h;
}

bool DiskFile::changedElsewhere() {
    look();
    if (seen_ == told_) return false;
    told_ = seen_;
    return seen_ != known_;
}

bool DiskFile::differs() {
    look();
    return seen_ != known_;
}

}  // namespace mb
