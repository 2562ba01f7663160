// marchbox/atomic_file.h — replacing a file so that a reader sees the old bytes or the new
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

}  // namespace mb
