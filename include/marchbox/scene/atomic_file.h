// marchbox/scene/atomic_file.h — replacing a file so that a reader sees the old bytes or the new
// ones, never a part: a temporary file beside it, written, fsynced, closed, renamed over it.
#pragma once

#include <string>
#include <string_view>

namespace mb {

// Returns "" on success, else why it failed in a few words (strerror, or "is a directory").
// On failure the old file is whole and no temporary is left. A symbolic link at `path` is kept
// and the file it points to replaced; a device, pipe or folder is refused. The replaced file's
// permission bits carry over to the new one.
std::string replaceFile(const std::string& path, std::string_view bytes);

// Whether replaceFile(path, ...) would get as far as writing: "" or why not, in its words. It
// tries, making the temporary and removing it, so a missing or read-only folder shows before
// minutes of work, not after; what only the write meets (a full disk) still shows only then.
std::string checkReplaceFile(const std::string& path);

}  // namespace mb
