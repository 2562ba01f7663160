// render_dialog.cpp — large renders from the editor.
#include "render_dialog.h"

#include "args.h"
#include "marchbox/editor/events.h"
#include "marchbox/gl/gl.h"
#include "widgets.h"

#include <GLFW/glfw3.h>
#include <algorithm>
#include <filesystem>
#include <imgui.h>
#include <imgui_stdlib.h>

namespace mb {

static const char* const kSupersampling[] = {"1x1", "2x2", "3x3", "4x4"};  // the scene's aa 1..4

// A radio button marked "PREFIX/LABEL"; true when clicked.
static bool choice(const char* prefix, const char* label, bool active) {
    ImGui::SameLine();
    bool clicked = ImGui::RadioButton(label, active);
    markItem(std::string(prefix) + "/" + label);
    return clicked;
}

// Chosen here, or else View > Quality's preset and the supersampling it makes of the scene's
// own `aa`.
void RenderChoice::resolve(const UiContext& c, QualityPreset* p, int* samples) const {
    *p = preset.value_or(c.ui.quality);
    RenderSettings render = c.editor.scene().render;
    RenderOptions unused;
    applyQualityPreset(*p, &render, &unused);
    *samples = aa.value_or(render.aa);
}

bool RenderChoice::draw(UiContext& c, const char* prefix) {
    const std::string at = std::string(prefix) + "/";
    ImGui::InputInt("width", &width);
    markItem(at + "width");
    ImGui::InputInt("height", &height);
    markItem(at + "height");
    QualityPreset shown;
    int samples;
    resolve(c, &shown, &samples);
    ImGui::TextUnformatted("quality");
    for (int p = 0; p < kQualityPresetCount; ++p)
        if (choice(prefix, qualityPresetName(QualityPreset(p)), int(shown) == p))
            preset = QualityPreset(p);
    itemTooltip(at + "quality", "As marchbox render --quality; at first View > Quality's.");
    ImGui::TextUnformatted("supersampling");
    for (int n = 1; n <= 4; ++n)
        if (choice(prefix, kSupersampling[n - 1], samples == n)) aa = n;
    itemTooltip(at + "supersampling",
                "Samples per pixel along each side, as the scene's aa; at first what the\n"
                "quality preset makes of it.");
    ImGui::TextDisabled("Debug view, fog and FXAA follow the View settings.");
    const bool start = ImGui::Button("Render");
    markItem(at + "start");
    return start;
}

bool RenderChoice::sizeValid(std::string* status) const {
    if (validImageSize(width, height)) return true;
    *status = "bad size " + std::to_string(width) + "x" + std::to_string(height) + ": expected " +
              kImageSizeRule;
    emitEvent("refuse " + *status);
    return false;
}

Scene RenderChoice::scene(const UiContext& c, RenderOptions* options) const {
    QualityPreset p;
    int samples;
    resolve(c, &p, &samples);
    Scene scene = c.editor.scene();
    *options = c.ui.render;
    options->outline = false;  // a rendered picture shows no selection
    applyQualityPreset(p, &scene.render, options);
    scene.render.aa = samples;
    return scene;
}

// The size within the command line's limit, the file writable (a missing or read-only folder
// is found now, not after the render; the save still meets what only the write can, a full
// disk), and a file already there replaced only by a second Render.
bool RenderDialog::ready() {
    std::string error;
    if (!choice_.sizeValid(&status_)) return false;
    if (!checkSavePng(path_, &error)) {
        status_ = error;
        emitEvent(status_);
        return false;
    }
    std::error_code ec;
    if (std::filesystem::exists(path_, ec) && replacePath_ != path_) {
        replacePath_ = path_;
        status_ = path_ + " exists: Render again to replace it.";
        emitEvent("confirm replace " + path_);
        return false;
    }
    return true;
}

void RenderDialog::start(UiContext& c) {
    if (!ready()) return;
    replacePath_.clear();
    RenderOptions options;
    const Scene scene = choice_.scene(c, &options);
    std::string error;
    renderer_ = std::make_unique<Renderer>();
    if (!renderer_->init(&error) || !renderer_->setScene(scene, options, &error)) {
        status_ = "cannot render: " + error.substr(0, error.find('\n'));
        renderer_.reset();
        return;
    }
    tiles_ = std::make_unique<TiledRender>(*renderer_, choice_.width, choice_.height);
    if (!tiles_->start(&error)) {
        status_ = "cannot render: " + error;
        tiles_.reset();
        return;
    }
    status_.clear();
    emitEvent("render started " + std::to_string(choice_.width) + "x" +
              std::to_string(choice_.height));
}

void RenderDialog::finish() {
    Image img = tiles_->finish();
    std::string error;
    std::error_code ec;
    const std::filesystem::path whole = std::filesystem::absolute(path_, ec).lexically_normal();
    if (GLenum e = glGetError()) status_ = "cannot render: OpenGL error " + std::to_string(e);
    else status_ = savePng(path_, img, &error) ? "saved " + whole.string() : error;
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
    // What was said about the last scene (saved, refused) goes when another opens.
    if (scene_ != c.editor.document().opened() && !running()) {
        scene_ = c.editor.document().opened();
        status_.clear();
        replacePath_.clear();
    }
    if (!c.ui.showRender) return;
    if (beginPanel(c, Panel::Render, "Render", &c.ui.showRender)) {
        ImGui::BeginDisabled(running());
        ImGui::InputText("PNG file", &path_);
        markItem("render/file");
        if (choice_.draw(c, "render")) start(c);
        ImGui::EndDisabled();
        if (running()) {
            ImGui::ProgressBar(tiles_->progress());
            if (ImGui::Button("Cancel")) {
                tiles_.reset();
                renderer_.reset();
                status_ = "cancelled";
            }
        }
        statusLine(status_, &shownStatus_, "render/status");
    }
    ImGui::End();
}

}  // namespace mb
