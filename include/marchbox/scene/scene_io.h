// marchbox/scene/scene_io.h — reading and writing scene files (docs/scene-format.md).
//
// Loading parses into a fresh Scene and hands it over only when the whole file is valid, so a
// failed load never touches the scene the caller already has. Saving is canonical: every key,
// fixed record order, shortest round-trip floats; the same scene always gives the same bytes.
// Comment and blank lines are kept with the record below them and written above it again,
// wherever the canonical order puts it; those below the last record stay at the end
// (SceneComments). Their trailing blanks and CRs are dropped.
#pragma once

#include "marchbox/scene/scene.h"

#include <string>
#include <string_view>
#include <vector>

namespace mb {

struct SceneError {
    int line = 0;         // 1-based; 0 when the error is about the whole file (e.g. unreadable)
    std::string message;  // what is wrong, without file or line
};

// Parses scene text. On success writes *out and returns true; otherwise fills *errors (at least
// one entry, in line order) and leaves *out untouched.
bool parseScene(std::string_view text, Scene* out, std::vector<SceneError>* errors);

// Reads and parses a file. Errors come back formatted "FILE:LINE: message", one per entry, each
// one line: FILE with its control bytes shown as '?' (printable.h).
bool loadScene(const std::string& path, Scene* out, std::vector<std::string>* errors);

// The canonical text of a scene, its comments where they belong.
std::string formatScene(const Scene& scene);

// Writes formatScene() to a temporary file beside `path`, flushes it and renames it over `path`.
// On failure the old file is whole, the temporary is removed and *error says why in one line.
bool saveScene(const std::string& path, const Scene& scene, std::string* error);
// Whether saveScene could write `path` (checkReplaceFile), *error in its words: before a long run.
bool checkSaveScene(const std::string& path, std::string* error);

// Shortest decimal text that reads back to the same float ("0.1", "1e-05", "-2").
std::string formatFloat(float v);

bool operator==(const Scene& a, const Scene& b);  // field-by-field, comments too; floats exactly
inline bool operator!=(const Scene& a, const Scene& b) { return !(a == b); }

}  // namespace mb
