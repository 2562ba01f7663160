// animation_dialog.cpp — frame sequences and video from the editor.
#include "animation_dialog.h"

#include "marchbox/editor/events.h"
#include "marchbox/gl/gl.h"
#include "widgets.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_stdlib.h>

namespace mb {

// The fields as render --frames options, read by the command line's own parser and checks,
// so a bad range, fps or PATTERN is refused in its words.
bool AnimationDialog::options(Args* a, FramePattern* pattern) {
    if (!choice_.sizeValid(&status_)) return false;
    const std::string size = std::to_string(choice_.width) + "x" + std::to_string(choice_.height);
    std::vector<std::string> words = {"-o",    path_, "--frames", frames_,
                                      "--fps", fps_,  "--size",   size};
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    if (!parseArgs(int(argv.size()), argv.data(), 0, a, &status_) ||
        !(status_ = framesError(*a, pattern)).empty()) {
        emitEvent("refuse " + status_);
        return false;
    }
    return true;
}

void AnimationDialog::start(UiContext& c) {
    Args a;
    FramePattern pattern;
    if (!options(&a, &pattern)) return;
    first_ = frame_ = a.frameRange->first;
    last_ = a.frameRange->last;
    const Scene scene = choice_.scene(c, &options_);
    renderer_ = std::make_unique<Renderer>();
    std::string error;
    if (!renderer_->init(&error)) return stop("cannot render: " + error);
    ring_ = std::make_unique<FrameReadback>();
    out_ = openFrames(a.output, pattern, first_, a.width, a.height, *a.fps, false, &error);
    if (!out_) return stop(error);
    sequence_ = std::make_unique<FrameSequence>(scene, PhysicsSettings{}, *a.fps);
    startedAt_ = glfwGetTime();
    status_.clear();
    emitEvent("animation started " + frames_ + " at " + fps_ + " fps, " + a.output);
}

// Ends the run, saying why. A video not finished is removed; every PNG written is whole
// (savePng renames a temporary file), so a stop leaves only whole frames.
void AnimationDialog::stop(const std::string& status) {
    if (out_) out_->abandon();
    status_ = status;
    emitEvent(status_);
    tiles_.reset();
    ring_.reset();
    out_.reset();
    sequence_.reset();
    renderer_.reset();
}

// Simulates to the frame, then draws its tiles, each until `until`; a drawn frame goes back to
// memory while the next ones are drawn, and is written a few frames later, in order.
bool AnimationDialog::nextFrame(double until) {
    const auto late = [until] { return glfwGetTime() >= until; };
    std::string error;
    if (!tiles_) {
        if (!sequence_->reach(frame_, late)) return false;
        if (ring_->full() && !handOver()) return false;
        if (!renderer_->setScene(sequence_->scene(frame_), options_, &error))
            return stop("cannot render: " + error.substr(0, error.find('\n'))), false;
        tiles_ = std::make_unique<TiledRender>(*renderer_, choice_.width, choice_.height);
        if (!tiles_->start(&error)) return stop("cannot render: " + error), false;
    }
    while (!tiles_->done() && !late()) tiles_->step();
    if (!tiles_->done()) return false;
    const bool queued = tiles_->finish(*ring_, frame_, &error);
    tiles_.reset();
    if (!queued) return stop("cannot render: " + error), false;
    if (GLenum e = glGetError())
        return stop("cannot render: OpenGL error " + std::to_string(e)), false;
    if (++frame_ <= last_) return true;
    while (!ring_->empty())
        if (!handOver()) return false;
    return stop(out_->finish(&error) ? "saved frames " + frames_ + " to " + path_ : error), false;
}

bool AnimationDialog::handOver() {
    ReadFrame f;
    std::string error;
    if (!ring_->take(&f, &error)) return stop("cannot render: " + error), false;
    if (!out_->write(f.frame, f.image, &error)) return stop(error), false;
    emitEvent("animation frame " + std::to_string(f.frame));
    return true;
}

void AnimationDialog::work(double budgetSeconds) {
    if (!running()) return;
    renderer_->rebind();  // the window's renderer binds its scene to the same points meanwhile
    const double until = glfwGetTime() + budgetSeconds;
    while (nextFrame(until)) {
    }
}

// Frame i of N and the time left at the pace so far.
void AnimationDialog::progress() const {
    const int done = frame_ - first_, total = last_ - first_ + 1;
    const double part = done + (tiles_ ? tiles_->progress() : 0.0);
    const double elapsed = glfwGetTime() - startedAt_;
    const int left = part > 0 ? int(elapsed * (total - part) / part + 0.5) : 0;
    char text[64];
    std::snprintf(text, sizeof text, "frame %d of %d, %d:%02d left", done + 1, total, left / 60,
                  left % 60);
    ImGui::ProgressBar(float(part / total), ImVec2(-1, 0), text);
    markItem("animation/progress");
}

void AnimationDialog::draw(UiContext& c) {
    if (!c.ui.showAnimation) return;
    if (beginPanel(c, Panel::Render, "Render Animation", &c.ui.showAnimation)) {
        ImGui::BeginDisabled(running());
        ImGui::InputText("PNG pattern or .mp4", &path_);
        markItem("animation/file");
        ImGui::InputText("frames", &frames_);
        markItem("animation/frames");
        ImGui::InputText("fps", &fps_);
        markItem("animation/fps");
        if (choice_.draw(c, "animation")) start(c);
        ImGui::EndDisabled();
        if (running()) {
            progress();
            if (ImGui::Button("Cancel")) stop("cancelled at frame " + std::to_string(frame_));
            markItem("animation/cancel");
        }
        statusLine(status_, &shownStatus_, "animation/status");
    }
    ImGui::End();
}

}  // namespace mb
