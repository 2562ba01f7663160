// marchbox/editor/recent.h — the scene files opened or saved lately, for File > Open Recent.
//
// Kept newest first in a small text file, one absolute path a line, at
// $XDG_CONFIG_HOME/marchbox/recent.txt, or ~/.config/marchbox/recent.txt when XDG_CONFIG_HOME
// is unset or not absolute (the XDG base directory rules). Every change is written at once, so
// two editors open side by side each keep what the other added before them. The list is a
// convenience: a file that cannot be read or written only means an empty or unsaved list.
#pragma once

#include <string>
#include <vector>

namespace mb {

// Where the list lives by the rules above; "" when neither variable gives a folder.
std::string recentFilesPath();

class RecentFiles {
public:
    static constexpr size_t kMax = 10;

    RecentFiles() = default;                 // in memory only: nothing read or written
    explicit RecentFiles(std::string file);  // reads `file` when it exists

    const std::vector<std::string>& paths() const { return paths_; }  // newest first
    // Puts `path` first, made absolute, once (an older mention goes), at most kMax kept; then
    // writes the list. Returns "" or why it could not be written.
    std::string add(const std::string& path);
    std::string clear();
    const std::string& file() const { return file_; }

private:
    std::string save() const;

    std::string file_;
    std::vector<std::string> paths_;
};

}  // namespace mb
