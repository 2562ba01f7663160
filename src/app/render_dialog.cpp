// render_dialog.cpp — large renders from the editor.
#include "render_dialog.h"

#include "marchbox/editor/events.h"
#include "widgets.h"

#include <GLFW/glfw3.h>
#include <algorithm>
#include <imgui.h>
#include <imgui_stdlib.h>

namespace mb {

// A folder that is missing or read-only is found before the render, not after it. The save at
// the end still checks what only the write can meet (a full disk).
void RenderDialog::start(UiContext& c) {
    width_ = std::clamp(width_, 1, 16384);
    height_ = std::clamp(height_, 1, 16384);
    std::string error;
    if (!checkSavePng(path_, &error)) {
        status_ = error;
        emitEvent(status_);
        return;
    }
    renderer_ = std::make_unique<Renderer>();
    RenderOptions options = c.ui.render;
    options.outline = false;  // a still shows no selection
    if (!renderer_->init(&error) || !renderer_->setScene(c.editor.scene(), options, &error)) {
        status_ = "cannot render: " + error.substr(0, error.find('\n'));
        renderer_.reset();
        return;
    }
    tiles_ = std::make_unique<TiledRender>(*renderer_, width_, height_);
    if (!tiles_->start(&error)) {
        status_ = "cannot render: " + error;
        tiles_.reset();
        return;
    }
    status_.clear();
    emitEvent("render started " + std::to_string(width_) + "x" + std::to_string(height_));
}

void RenderDialog::finish() {
    Image img = tiles_->finish();
    std::string error;
    status_ = savePng(path_, img, &error) ? "saved " + path_ : error;
    emitEvent(status_);
    tiles_.reset();
    renderer_.reset();
}

void RenderDialog::work(double budgetSeconds) {
    if (!running()) return;
    renderer_->rebind();  // the window's renderer binds its scene to the same points between tiles
    double until = glfwGetTime() + budgetSeconds;
    while (!tiles_->done() && glfwGetTime() < until) tiles_->step();
    if (tiles_->done()) finish();
}

void RenderDialog::draw(UiContext& c) {
    if (!c.ui.showRender) return;
    if (beginPanel(c, Panel::Render, "Render", &c.ui.showRender)) {
        ImGui::BeginDisabled(running());
        ImGui::InputInt("width", &width_);
        markItem("render/width");
        ImGui::InputInt("height", &height_);
        markItem("render/height");
        ImGui::InputText("PNG file", &path_);
        markItem("render/file");
        ImGui::TextDisabled("Debug view, fog and FXAA follow the View settings.");
        if (ImGui::Button("Render")) start(c);
        markItem("render/start");
        ImGui::EndDisabled();
        if (running()) {
            ImGui::ProgressBar(tiles_->progress());
            if (ImGui::Button("Cancel")) {
                tiles_.reset();
                renderer_.reset();
                status_ = "cancelled";
            }
        }
        if (!status_.empty()) {
            ImGui::TextWrapped("%s", status_.c_str());
            markItem("render/status");
        }
    }
    ImGui::End();
}

}  // namespace mb
