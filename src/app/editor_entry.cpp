// editor_entry.cpp — `marchbox [SCENE]`: the editor window, or a PNG when there is no display.
#include "commands.h"
#include "editor_window.h"

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

static int renderPreview(const std::string& scenePath) {
    std::vector<std::string> errors;
    Scene scene;
    if (!loadScene(scenePath, &scene, &errors)) {
        for (const std::string& e : errors) std::cerr << e << '\n';
        return kExitBadInput;
    }
    // Beside the executable (build/), so a preview never litters the scene's folder.
    std::filesystem::path dir = std::filesystem::read_symlink("/proc/self/exe").parent_path();
    std::string out =
        (dir / (std::filesystem::path(scenePath).stem().string() + "-preview.png")).string();
    std::string error;
    std::cout << "no display: rendering " << scenePath << " to " << out << " instead\n";
    Image img;
    if (!renderOffscreen(scene, RenderOptions{}, 640, 360, &img, &error))
        return glFailure("render", error);
    if (!savePng(out, img, &error)) {
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
    std::string path = a.positional.empty() ? defaultScenePath() : a.positional[0];
    if (!haveDisplay()) return renderPreview(path);
    int status = runEditorWindow(path);
    return status == kNoWindow ? renderPreview(path) : status;
}

}  // namespace mb
