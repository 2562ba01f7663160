// render_dialog.h — File > Render...: an image of any size drawn a tile at a time between the
// editor's frames, with a progress bar and Cancel, saved as PNG.
#pragma once

#include "ui.h"

#include "marchbox/gl/renderer.h"

#include <memory>
#include <string>

namespace mb {

class RenderDialog {
public:
    void draw(UiContext& c);          // the window, while c.ui.showRender
    void work(double budgetSeconds);  // draws tiles until the budget is spent; needs the context
    bool running() const { return tiles_ != nullptr; }

private:
    void start(UiContext& c);
    void finish();

    int width_ = 1920, height_ = 1080;
    std::string path_ = "render.png";
    std::unique_ptr<Renderer> renderer_;  // its own: the window's keeps drawing meanwhile
    std::unique_ptr<TiledRender> tiles_;
    std::string status_;
};

}  // namespace mb
