// marchbox/editor/files.h — what counts as a scene file, the path Save As proposes, the scene
// the editor starts on, and noticing files that change.
#pragma once

#include "marchbox/scene/scene.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace mb {

bool hasSceneExtension(const std::string& path);  // ".txt", any case
// The same file by two names ("scene.txt" and "/home/me/scene.txt"); false if either is missing.
bool sameFile(const std::string& a, const std::string& b);

// Where Save As starts: the scene's own file `current`; for a scene without one, "untitled.txt"
// beside `lastUsed` (the last file opened or saved; the working folder when there is none),
// numbered "untitled-2.txt", ... past files that exist. Always absolute and normalised, so the
// dialog shows the whole of where it will write.
std::string proposeSavePath(const std::string& current, const std::string& lastUsed);

// What `marchbox [SCENE]` starts on, read into *scene with *file the path saves go to: SCENE
// itself; where no file SCENE exists yet but its folder does, an empty scene (emptyScene())
// to be saved as SCENE; with no SCENE (""), an untitled copy of `defaultScene` (*file ""), so
// that a save asks where rather than writing over the example. False with FILE:LINE errors
// when a file does not load.
bool startingScene(const std::string& scenePath, const std::string& defaultScene, Scene* scene,
                   std::string* file, std::vector<std::string>* errors);

// Polls the modification times of the files directly in one folder (the shaders).
class FolderWatch {
public:
    explicit FolderWatch(std::string folder);
    bool changed();  // true when a file appeared, vanished or was rewritten since the last call

private:
    std::map<std::string, std::filesystem::file_time_type> scan() const;
    std::string folder_;
    std::map<std::string, std::filesystem::file_time_type> stamps_;
};

}  // namespace mb
