// recent.cpp — the recent-files list and the small file it lives in.
#include "marchbox/editor/recent.h"

#include "marchbox/scene/atomic_file.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace mb {

static constexpr size_t kMaxPathBytes = 4096;  // PATH_MAX: a longer line is not a path we wrote

std::string recentFilesPath() {
    fs::path base;
    const char* xdg = std::getenv("XDG_CONFIG_HOME");
    const char* home = std::getenv("HOME");
    if (xdg && fs::path(xdg).is_absolute()) base = xdg;
    else if (home && *home) base = fs::path(home) / ".config";
    else return "";
    return (base / "marchbox" / "recent.txt").string();
}

RecentFiles::RecentFiles(std::string file) : file_(std::move(file)) {
    std::ifstream in(file_);
    for (std::string line; paths_.size() < kMax && std::getline(in, line);) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || line.size() > kMaxPathBytes) continue;
        if (std::find(paths_.begin(), paths_.end(), line) == paths_.end()) paths_.push_back(line);
    }
}

std::string RecentFiles::add(const std::string& path) {
    if (path.empty() || path.find('\n') != std::string::npos) return "";  // not one line
    std::error_code ec;
    fs::path whole = fs::absolute(path, ec);
    std::string p = (ec ? fs::path(path) : whole).lexically_normal().string();
    paths_.erase(std::remove(paths_.begin(), paths_.end(), p), paths_.end());
    paths_.insert(paths_.begin(), p);
    if (paths_.size() > kMax) paths_.resize(kMax);
    return save();
}

std::string RecentFiles::clear() {
    paths_.clear();
    return save();
}

std::string RecentFiles::save() const {
    if (file_.empty()) return "";
    std::error_code ec;
    fs::create_directories(fs::path(file_).parent_path(), ec);
    std::string text;
    for (const std::string& p : paths_) text += p + '\n';
    std::string why = replaceFile(file_, text);
    return why.empty() ? "" : "cannot write the recent files list '" + file_ + "': " + why;
}

}  // namespace mb
