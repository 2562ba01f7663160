// marchbox/editor/file_browser.h — the folder File > Open and Save As browse: its folders and
// scene files, where a typed path leads, and the places to jump to. Pure std::filesystem, never
// throwing: a folder that cannot be read is shown empty with the reason.
#pragma once

#include <string>
#include <vector>

namespace mb {

struct FolderEntry {
    std::string name;  // the last part of the path only
    bool folder = false;
};

struct FolderView {
    std::string folder;                // absolute and normalised, with no trailing separator
    std::vector<FolderEntry> entries;  // folders, then .txt files, each sorted by name
    std::string error;                 // why the folder could not be listed; "" when it was
};

// The entries of `folder`, with hidden ones (a leading dot) left out, as file managers do.
FolderView readFolder(const std::string& folder);

// The folder above `folder`; the root is its own parent.
std::string parentFolder(const std::string& folder);

// The folder a path field's text points into: the text itself when it names a folder, else the
// folder it would be written in. Relative text is taken from the working folder.
std::string folderOf(const std::string& path);

// `folder` joined with `name`, normalised: the path a click on an entry puts in the field.
std::string entryPath(const std::string& folder, const std::string& name);

// A place beside the listing: a folder and what the dialog calls it.
struct BrowsePlace {
    std::string label;   // "Examples", "Home", "Working folder", or the folder's path
    std::string folder;  // absolute and normalised
    bool operator==(const BrowsePlace&) const = default;
};

// The places beside the listing: the shipped examples, home and the working folder by name,
// then the folders of `recentFiles` (newest first), the ones the user opened or saved in, by
// their paths (home as ~). Each folder once, under its first label, and only where it exists.
std::vector<BrowsePlace> placesToBrowse(const std::vector<std::string>& recentFiles,
                                        const std::string& examples, const std::string& home,
                                        const std::string& working);

}  // namespace mb
