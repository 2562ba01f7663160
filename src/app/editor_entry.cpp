// editor_entry.cpp — `marchbox [SCENE]`: the editor window, or a PNG when there is no display.
#include "commands.h"
#include "editor_window.h"

#include "marchbox/editor/files.h"
#include "marchbox/gl/renderer.h"
#include "marchbox/physics/physics.h"
#include "marchbox/scene/scene_io.h"

#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace mb {

// scenes/default.txt from the working directory, else from the source tree.
static std::string defaultScenePath() {
    const std::string local = "scenes/default.txt";
    if (std::filesystem::exists(local)) return local;
    return std::string(MARCHBOX_SOURCE_DIR) + "/" + local;
}

static bool haveDisplay() {
    const char* x = std::getenv("DISPLAY");
    const char* wl = std::getenv("WAYLAND_DISPLAY");
    return (x && *x) || (wl && *wl);
}

// No display: the scene the editor would have opened, as a PNG in the working folder (where a
// person looks first; beside the executable it was lost in build/).
static int renderPreview(const Scene& scene, const std::string& name) {
    std::error_code ec;
    std::filesystem::path out = std::filesystem::absolute(name + "-preview.png", ec);
    if (ec) out = name + "-preview.png";
    std::string error;
    std::cout << "no display: the editor needs one; rendering the scene to " << out.string()
              << " instead\n";
    Image img;
    if (!renderOffscreen(scene, RenderOptions{}, 640, 360, &img, &error))
        return glFailure("render", error);
    if (!savePng(out.string(), img, &error)) {
        std::cerr << error << '\n';
        return kExitBadInput;
    }
    return kExitOk;
}

int runEditor(const Args& a) {
    if (a.positional.size() > 1) {
        std::cerr << "marchbox: unknown command '" << a.positional[0]
                  << "' (see marchbox --help)\n";
        return kExitUsage;
    }
    const std::string path = a.positional.empty() ? "" : a.positional[0];
    Scene scene;
    std::string file;
    std::vector<std::string> errors;
    if (!startingScene(path, defaultScenePath(), &scene, &file, &errors)) {
        for (const std::string& e : errors) std::cerr << e << '\n';
        return kExitBadInput;
    }
    const std::string name = std::filesystem::path(path.empty() ? defaultScenePath() : path).stem();
    if (!haveDisplay()) return renderPreview(scene, name);
    int status = runEditorWindow(scene, file);
    return status == kNoWindow ? renderPreview(scene, name) : status;
}

}  // namespace mb
