// scene_view.h — the scene as the window shows it: the raymarching renderer kept in step with
// the editor, the selection highlighted, shaders reloaded when they change on disk.
#pragma once

#include "marchbox/editor/files.h"
#include "marchbox/gl/renderer.h"

#include <memory>
#include <string>

namespace mb {

class SceneView {
public:
    SceneView();
    bool init(const Scene& scene, std::string* error);  // needs the window's context current

    // Uploads the scene when its version or the options changed since the last call.
    void sync(const Scene& scene, uint64_t version, const RenderOptions& options, double now);
    void draw(int width, int height, int selectedObject);

    // Twice a second, looks at shaders/; on a change builds a fresh renderer and swaps it in
    // only when the new program compiles and links, so a broken edit keeps the last good one.
    void pollShaders(const Scene& scene, double now);
    const std::string& shaderLog() const { return log_; }  // the last failure, empty when fine

private:
    bool reload(const Scene& scene);

    std::unique_ptr<Renderer> renderer_;
    FolderWatch shaders_;
    RenderOptions options_;
    uint64_t version_ = ~0ull;
    double nextPoll_ = 0.0, retryAt_ = 0.0;
    std::string log_;
};

// Reads the back buffer (after the UI is drawn, before the swap) and writes it as a PNG in
// `folder` under the first free name marchbox-NNNN.png.
bool saveScreenshot(int width, int height, const std::string& folder, std::string* path,
                    std::string* error);

}  // namespace mb
