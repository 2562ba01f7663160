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

// What File > Render... and File > Render Animation... both ask: the size, the quality preset
// and the supersampling, each item marked "PREFIX/..." for the e2e tests.
struct RenderChoice {
    int width = 1920, height = 1080;
    // Chosen here; until then View > Quality's preset and the supersampling it gives the scene.
    std::optional<QualityPreset> preset;
    std::optional<int> aa;

    bool draw(UiContext& c, const char* prefix);  // the fields, then Render: true when clicked
    bool sizeValid(std::string* status) const;    // else *status says why, and an event
    // The scene and options as `marchbox render --quality Q` reads them from the file, with the
    // supersampling chosen, and the View's debug view, fog and FXAA.
    Scene scene(const UiContext& c, RenderOptions* options) const;

private:
    void resolve(const UiContext& c, QualityPreset* p, int* samples) const;
};

class RenderDialog {
public:
    void draw(UiContext& c);          // the window, while c.ui.showRender
    void work(double budgetSeconds);  // draws tiles until the budget is spent; needs the context
    bool running() const { return tiles_ != nullptr; }

private:
    bool ready();  // the size and the file allow a render now, else status_ says why
    void start(UiContext& c);
    void finish();

    RenderChoice choice_;
    std::string path_ = "render.png";
    std::string replacePath_;  // warned once that this file exists: the next Render replaces it
    std::unique_ptr<Renderer> renderer_;  // its own: the window's keeps drawing meanwhile
    std::unique_ptr<TiledRender> tiles_;
    std::string status_;
    std::string shownStatus_;  // status_ as last drawn
    uint64_t scene_ = 0;  // Document::opened() the status is about
};

}  // namespace mb
