// editor_window.h — `marchbox [SCENE]` with a display: the editor window.
#pragma once

#include "marchbox/scene/scene.h"

#include <string>

namespace mb {

constexpr int kNoWindow = -1;  // no window could be opened: the caller falls back to a PNG

// Opens `scene` in the editor, saving to `file` ("" for an untitled scene), and runs until the
// user quits. Returns the process exit status: 0 after a normal quit, or kNoWindow.
int runEditorWindow(const Scene& scene, const std::string& file);

}  // namespace mb
