// editor_window.h — `marchbox [SCENE]` with a display: the editor window.
#pragma once

#include <string>

namespace mb {

constexpr int kNoWindow = -1;  // no window could be opened: the caller falls back to a PNG

// Opens SCENE in the editor and runs until the user quits. Returns the process exit status:
// 0 after a normal quit, 1 when SCENE does not load (its FILE:LINE errors on stderr), or
// kNoWindow.
int runEditorWindow(const std::string& scenePath);

}  // namespace mb
