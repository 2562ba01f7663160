// marchbox/scene/atomic_file.h — replacing a file so that a reader sees the old bytes or the new
// ones, never a part: a temporary file beside it, written, fsynced, closed, renamed over it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace mb {

// Returns "" on success, else why it failed in a few words (strerror, or "is a directory").
// On failure the old file is whole and no temporary is left. A symbolic link at `path` is kept
// and the file it points to replaced; a device, pipe or folder is refused. The replaced file's
// permission bits carry over to the new one.
std::string replaceFile(const std::string& path, std::string_view bytes);

// Files that go together (an OBJ and the MTL it names), replaced together: each is written
// beside its path first, and only once every one is written are they renamed over theirs, so a
// write that fails (a full disk) leaves every old file whole. Returns "" or why the first that
// failed did, its index in *failed. A rename that fails after another's succeeded (rare: the
// temporaries lie beside their files) leaves the earlier ones replaced.
struct FileBytes {
    std::string path;
    std::string_view bytes;
};
std::string replaceFiles(const std::vector<FileBytes>& files, size_t* failed);

// Whether replaceFile(path, ...) would get as far as writing: "" or why not, in its words. It
// tries, making the temporary and removing it, so a missing or read-only folder shows before
// minutes of work, not after; what only the write meets (a full disk) still shows only then.
std::string checkReplaceFile(const std::string& path);

}  // namespace mb
