// scene_image.cpp — the view's picture: budgeted steps drawn into a texture, shown every frame.
#include "scene_image.h"

#include "marchbox/editor/events.h"

#include <cmath>

namespace mb {

static double msSince(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

bool SceneImage::update(Renderer& r, Renderer* draft, const PictureKey& key, StepKind only) {
    if (key != key_) {
        key_ = key;
        policy_.restart(key.width, key.height, key.aa, key.canAverage, draft != nullptr);
        changedAt_ = Clock::now();
        passMs_ = 0.0;
    }
    ViewStep step = policy_.next();
    if (step.kind == StepKind::None || step.kind != only) return false;
    double ms = 0.0;
    // A draft renderer ready only since the restart must not draw what the policy takes for a pass.
    const bool drafted = step.kind == StepKind::Preview && policy_.draftPreview() && draft;
    if (draw(drafted ? *draft : r, step, &ms)) {
        policy_.finished(step, ms);
        report(step, ms);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return true;
}

// outline.glsl rings object uHighlight - 1; 0 rings nothing.
static void highlight(const Renderer& r, int selected) {
    if (const Program* p = r.program()) {
        glUseProgram(p->id());
        glUniform1i(p->uniform("uHighlight"), selected + 1);
    }
}

bool SceneImage::draw(Renderer& r, const ViewStep& s, double* ms) {
    std::string error;
    if (s.startsFrame) {
        if (!r.beginFrame(s.width, s.height, true, &error)) {
            status_.state = "cannot draw: " + error;
            return false;
        }
        // Until the bands reach them, pixels show the preview scaled up.
        if (s.kind == StepKind::Band && valid_) r.seedFrame(picture_);
    }
    if (!picture_.resize(s.width, s.height, GL_RGBA8)) {
        status_.state = "cannot create a " + std::to_string(s.width) + "x" +
                        std::to_string(s.height) + " picture";
        return false;
    }
    r.rebind();  // File > Render...'s renderer binds its own scene to the same points
    r.resumeFrame();
    highlight(r, key_.selected);
    const bool band = s.kind == StepKind::Band;
    const int y = band ? s.y : 0, rows = band ? s.rows : s.height;
    glFinish();  // the UI's drawing still queued is not the scene's cost
    Clock::time_point start = Clock::now();
    r.drawSample(0, y, s.width, rows, s.subpixel, s.weight);
    glFinish();  // llvmpipe draws when flushed: only now is the time the draw's
    *ms = msSince(start);
    // A new frame may have a new size: all of it; else only the band (and FXAA's reach).
    r.resolveFrame(picture_, 0, s.startsFrame ? 0 : y, s.width, s.startsFrame ? s.height : rows);
    valid_ = true;
    return true;
}

static std::string whole(double ms) { return std::to_string(std::lround(ms)); }

// Event log lines, for scripts and the e2e tests: "scene-frame 160x90 preview 72" (its draw,
// ms), "scene-frame 1280x720 pass 1/4 5230" (the pass's bands added up, ms) and
// "scene-frame 1280x720 done 31840" (from the change, on the clock).
void SceneImage::report(const ViewStep& s, double ms) {
    status_.stepMs = ms;
    status_.state = policy_.describe();
    status_.done = policy_.done();
    const std::string head =
        "scene-frame " + std::to_string(s.width) + "x" + std::to_string(s.height);
    if (s.kind == StepKind::Preview && policy_.previewing()) {  // not a full-size first pass
        emitEvent(head + " preview " + whole(ms));
    } else {
        passMs_ += ms;
        // A full-size preview is a whole pass; bands run top down, so y 0 ends one.
        if (s.kind == StepKind::Preview || s.y == 0) {
            const int pass = s.kind == StepKind::Preview ? 1 : s.sample + 1;
            emitEvent(head + " pass " + std::to_string(pass) + "/" +
                      std::to_string(policy_.samples()) + " " + whole(passMs_));
            if (pass == 1) status_.passMs = passMs_;
            passMs_ = 0.0;
        }
    }
    if (policy_.done()) {
        status_.refinedMs = msSince(changedAt_);
        emitEvent(head + " done " + whole(status_.refinedMs));
    }
}

void SceneImage::show(int width, int height) const {
    if (!valid_) return;
    // A preview is smaller than the window: smoothed as it is scaled up. Full size copies.
    const bool exact = picture_.width() == width && picture_.height() == height;
    picture_.blitTo(nullptr, width, height, exact ? GL_NEAREST : GL_LINEAR);
}

}  // namespace mb
