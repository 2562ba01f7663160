// render_dialog.h — File > Render...: an image of any size drawn a tile at a time between the
// editor's frames, with a progress bar and Cancel, saved as PNG. What it writes is what
// `marchbox render SCENE --quality Q --size WxH` writes for the scene as it stands, byte for
// byte, with the View's debug view, fog and FXAA.
#pragma once

#include "ui.h"

#include "marchbox/gl/quality_preset.h"
#include "marchbox/gl/renderer.h"

#include <memory>
#include <optional>
#include <string>

namespace mb {

class RenderDialog {
public:
    void draw(UiContext& c);          // the window, while c.ui.showRender
    void work(double budgetSeconds);  // draws tiles until the budget is spent; needs the context
    bool running() const { return tiles_ != nullptr; }

private:
    void settings(UiContext& c, QualityPreset* preset, int* aa);
    bool ready();  // the size and the file allow a render now, else status_ says why
    void start(UiContext& c, QualityPreset preset, int aa);
    void finish();

    int width_ = 1920, height_ = 1080;
    std::string path_ = "render.png";
    // Chosen here; until then View > Quality's preset and the supersampling it gives the scene.
    std::optional<QualityPreset> preset_;
    std::optional<int> aa_;
    std::string replacePath_;  // warned once that this file exists: the next Render replaces it
    std::unique_ptr<Renderer> renderer_;  // its own: the window's keeps drawing meanwhile
    std::unique_ptr<TiledRender> tiles_;
    std::string status_;
    uint64_t scene_ = 0;  // Document::opened() the status is about
};

}  // namespace mb
