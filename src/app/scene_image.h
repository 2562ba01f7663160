// scene_image.h — the scene as a picture the window shows every frame. After a change it is
// drawn again a step at a time, as the refinement policy (marchbox/editor/refinement.h) asks:
// a preview at a reduced resolution, then full size and more samples per pixel in bands of
// rows, each step within the frame budget, so the window never waits for a whole raymarch.
#pragma once

#include "marchbox/editor/refinement.h"
#include "marchbox/gl/framebuffer.h"
#include "marchbox/gl/renderer.h"

#include <chrono>
#include <cstdint>
#include <string>

namespace mb {

// Everything the picture depends on: any difference starts it over from a preview.
struct PictureKey {
    uint64_t content = ~0ull;  // counts changes to the renderer's scene, options and program
    int selected = -1;         // the highlighted object
    int width = 0, height = 0;
    int aa = 1;              // the scene's samples per axis
    bool canAverage = true;  // false for the object-id view

    bool operator==(const PictureKey&) const = default;  // every field: no stale picture
};

// For the statistics overlay.
struct PictureStatus {
    std::string state = "no picture yet";  // "640x360 (1/2) preview", "1280x720 refining 2/4"
    double stepMs = 0.0;                   // the last draw of the scene
    double passMs = 0.0;     // the last whole full-size pass: its bands' draws added up
    double refinedMs = 0.0;  // the last change to done, on the clock, UI frames included
    bool done = false;       // refinedMs is this picture's
};

class SceneImage {
public:
    // Draws the picture's next step toward `key` if it is of kind `only` (a preview after a
    // change, or a band of refinement); returns whether it drew. Previews come from `draft`
    // where there is one (the same scene at draft quality), everything else from `r`. Needs the
    // renderers' context; leaves the window's framebuffer bound.
    bool update(Renderer& r, Renderer* draft, const PictureKey& key, StepKind only);
    // The frame's other work (the UI, showing the picture, the swap) took ms: the scene's steps
    // get what it leaves of the frame budget.
    void otherWork(double ms) { policy_.otherWork(ms); }
    void show(int width, int height) const;  // the newest picture, scaled over the window
    bool done() const { return policy_.done(); }
    const PictureStatus& status() const { return status_; }

private:
    using Clock = std::chrono::steady_clock;
    bool draw(Renderer& r, const ViewStep& s, double* ms);
    void report(const ViewStep& s, double ms);

    Refinement policy_;
    PictureKey key_;
    ColorTarget picture_;  // RGBA8, the preview's size or the window's
    bool valid_ = false;   // picture_ holds a drawn image
    Clock::time_point changedAt_;
    double passMs_ = 0.0;  // the bands of the pass under way, so far
    PictureStatus status_;
};

}  // namespace mb
