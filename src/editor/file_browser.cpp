// file_browser.cpp — listing a folder for the Open and Save As dialogs.
#include "marchbox/editor/file_browser.h"

#include "marchbox/editor/files.h"

#include <algorithm>
#include <filesystem>

namespace fs = std::filesystem;

namespace mb {

// Absolute and normalised, without the trailing separator lexically_normal leaves on "a/b/..".
static fs::path tidy(const fs::path& p) {
    std::error_code ec;
    fs::path a = fs::absolute(p.empty() ? fs::path(".") : p, ec);
    fs::path n = (ec ? p : a).lexically_normal();
    if (n.has_relative_path() && !n.has_filename()) n = n.parent_path();
    return n;
}

static bool byName(const FolderEntry& a, const FolderEntry& b) {
    if (a.folder != b.folder) return a.folder;
    return a.name < b.name;
}

FolderView readFolder(const std::string& folder) {
    FolderView view;
    view.folder = tidy(folder).string();
    std::error_code ec;
    fs::directory_iterator it(view.folder, ec), end;
    if (ec) view.error = ec.message();
    for (; !ec && it != end; it.increment(ec)) {
        std::string name = it->path().filename().string();
        if (name.empty() || name[0] == '.') continue;
        std::error_code ignored;  // a broken link is neither, and is left out
        bool isFolder = it->is_directory(ignored);
        if (isFolder || (it->is_regular_file(ignored) && hasSceneExtension(name)))
            view.entries.push_back({name, isFolder});
    }
    std::sort(view.entries.begin(), view.entries.end(), byName);
    return view;
}

std::string parentFolder(const std::string& folder) {
    return tidy(tidy(folder).parent_path()).string();
}

std::string folderOf(const std::string& path) {
    std::error_code ec;
    if (!path.empty() && fs::is_directory(path, ec)) return tidy(path).string();
    return tidy(fs::path(path).parent_path()).string();
}

std::string entryPath(const std::string& folder, const std::string& name) {
    return tidy(fs::path(folder) / name).string();
}

// The path as a label: under home, from "~".
static std::string pathLabel(const std::string& folder, const std::string& home) {
    if (home.empty() || home == "/") return folder;
    const fs::path rel = fs::path(folder).lexically_relative(tidy(home));
    if (rel.empty() || *rel.begin() == "..") return folder;
    return rel == "." ? "~" : (fs::path("~") / rel).string();
}

std::vector<BrowsePlace> placesToBrowse(const std::vector<std::string>& recentFiles,
                                        const std::string& examples, const std::string& home,
                                        const std::string& working) {
    std::vector<BrowsePlace> places;
    auto add = [&](const std::string& label, const std::string& folder) {
        std::error_code ec;
        if (folder.empty() || !fs::is_directory(folder, ec)) return;
        const std::string f = tidy(folder).string();
        for (const BrowsePlace& p : places)
            if (p.folder == f) return;
        places.push_back({label.empty() ? pathLabel(f, home) : label, f});
    };
    add("Examples", examples);
    add("Home", home);
    add("Working folder", working);
    for (const std::string& file : recentFiles) add("", fs::path(file).parent_path().string());
    return places;
}

}  // namespace mb
