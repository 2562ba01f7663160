// files.cpp — scene file listing and folder polling, with std::filesystem, never throwing.
#include "marchbox/editor/files.h"

#include "marchbox/editor/scene_edit.h"
#include "marchbox/scene/scene_io.h"

#include <algorithm>
#include <cctype>

namespace fs = std::filesystem;

namespace mb {

bool hasSceneExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    return ext == ".txt";
}

bool sameFile(const std::string& a, const std::string& b) {
    std::error_code ec;
    return a == b || (!a.empty() && !b.empty() && fs::equivalent(a, b, ec));
}

// fs::absolute and current_path may throw (no working folder); with an error code they do not.
static fs::path wholePath(const fs::path& p) {
    std::error_code ec;
    fs::path a = fs::absolute(p, ec);
    return (ec ? p : a).lexically_normal();
}

std::string proposeSavePath(const std::string& current, const std::string& lastUsed) {
    if (!current.empty()) return wholePath(current).string();
    fs::path folder = lastUsed.empty() ? fs::path(".") : wholePath(lastUsed).parent_path();
    fs::path path = wholePath(folder / "untitled.txt");
    std::error_code ec;
    for (int n = 2; fs::exists(path, ec) && n < 1000; ++n)
        path = wholePath(folder / ("untitled-" + std::to_string(n) + ".txt"));
    return path.string();
}

bool startingScene(const std::string& scenePath, const std::string& defaultScene, Scene* scene,
                   std::string* file, std::vector<std::string>* errors) {
    *file = scenePath;
    if (scenePath.empty()) return loadScene(defaultScene, scene, errors);
    std::error_code ec;
    const fs::path folder = fs::path(scenePath).parent_path();
    if (!fs::exists(scenePath, ec) && !ec && fs::is_directory(folder.empty() ? "." : folder, ec)) {
        *scene = emptyScene();
        return true;
    }
    return loadScene(scenePath, scene, errors);  // says why: unreadable, a folder, no folder
}

FolderWatch::FolderWatch(std::string folder) : folder_(std::move(folder)), stamps_(scan()) {}

std::map<std::string, fs::file_time_type> FolderWatch::scan() const {
    std::map<std::string, fs::file_time_type> stamps;
    std::error_code ec;
    for (fs::directory_iterator it(folder_, ec), end; !ec && it != end; it.increment(ec)) {
        auto t = it->last_write_time(ec);
        if (!ec) stamps[it->path().string()] = t;
    }
    return stamps;
}

bool FolderWatch::changed() {
    auto now = scan();
    if (now == stamps_) return false;
    stamps_ = std::move(now);
    return true;
}

}  // namespace mb
