// marchbox/editor/refinement.h — what the editor's view draws next, so the window answers at
// display rate however slow the scene is to raymarch.
//
// After any change (scene, camera, render options, selection, window size) the view shows a
// preview at a reduced resolution chosen to fit the frame budget, drawn at draft quality where
// the view asks (restart's draftPreview); while nothing changes it refines, at the view's own
// quality: full resolution, then more samples per pixel, each pass in bands of rows that each
// fit the budget. The cost model is milliseconds per pixel, learnt from the draws: one figure
// for the passes, and one for draft previews, which cost less.
//
// Rules: sizes in pixels, times in milliseconds, rows counted from the bottom as GL does. No GL
// here: the window's SceneImage (src/app/scene_image.cpp) carries the steps out.
#pragma once

#include <glm/vec2.hpp>
#include <string>

namespace mb {

struct RefinementSettings {
    double frameBudgetMs = 50.0;  // a whole frame: the UI's share, measured, and the scene's
    double minSceneMs = 10.0;     // the scene's least share, however slow the UI
    int maxDivisor = 8;           // previews never coarser than 1/8 of the window per axis
    int jitterSamples = 4;        // samples per pixel, centre first, when the scene's aa is 1
    double learnRate = 0.3;       // weight of the newest figure in the running averages
};

enum class StepKind { None, Preview, Band };

// One piece of drawing. A Preview is a whole image of width × height (the window's size over
// `divisor`) at pixel centres; a Band is rows [y, y + rows) of the full-size image, adding
// sample number `sample` at `subpixel` with `weight`: target = target·(1 − w) + sample·w.
struct ViewStep {
    StepKind kind = StepKind::None;
    int width = 0, height = 0;  // the image this step draws into
    int divisor = 1;            // Preview: of the window's size
    int y = 0, rows = 0;        // Band
    int sample = 0;             // Band: 0 .. samples - 1
    glm::vec2 subpixel{0.5f};   // the sample's position inside its pixel, 0..1
    float weight = 1.0f;        // 1 / (sample + 1): after k samples the target is their mean
    bool startsFrame = false;   // the first draw into this image: its target starts over
    long pixels() const { return long(width) * (kind == StepKind::Band ? rows : height); }
};

// An exponential running average: value ← (1 − rate)·value + rate·sample; the first sample
// sets it. The scene's mix of sky and mirrors makes single draws noisy; the average still
// follows a camera moving into them within a few frames.
class RunningMean {
public:
    explicit RunningMean(double rate = 0.3) : rate_(rate) {}
    void add(double sample);
    bool known() const { return known_; }
    double value() const { return value_; }

private:
    double rate_;
    double value_ = 0.0;
    bool known_ = false;
};

// The preview's divisor d (its size is the window's over d per axis): the smallest whose
// estimated draw, width·height/d² pixels at msPerPixel, fits the budget, within 1..maxDivisor.
// `previous` (0 for none) is kept while its estimate stays within 0.5..1.25 of the budget, so
// the preview's sharpness does not flicker as the cost wobbles.
int previewDivisor(double msPerPixel, int width, int height, int previous, int maxDivisor,
                   double budgetMs);

// Rows of a band `width` pixels wide that fit the budget; at least 1, at most rowsLeft.
int bandRows(double msPerPixel, int width, int rowsLeft, double budgetMs);

// Band edges fall on multiples of this many rows (the first band also takes the height's
// remainder): llvmpipe runs the fragment shader on whole 4x4 blocks and GPUs on 2x2 quads, so
// a band whose edge cuts a block pays for rows it does not draw.
constexpr int kBandAlign = 4;

// Samples per pixel the view adds up: aa² for the scene's aa × aa grid; jitterSamples when aa
// is 1; 1 where samples must not be averaged (the object-id view).
int sampleCount(int aa, bool canAverage, const RefinementSettings& s);

// Where sample k falls inside a pixel. For aa > 1, the scene's own aa × aa grid (what `marchbox
// render` uses), nearest the centre first; else the centre, then Halton (2, 3) points.
glm::vec2 samplePosition(int k, int aa);

class Refinement {
public:
    explicit Refinement(const RefinementSettings& s = {})
        : s_(s), cost_(s.learnRate), draftCost_(s.learnRate), otherMs_(s.learnRate) {}

    // The picture is out of date: the next step is a preview of the whole width × height view.
    // Where a draft renderer is available and the view's own full-size frame does not fit the
    // budget, the preview is a draft: drawn at cheaper settings than the passes, so even a
    // full-size one is not the first pass (the bands draw that too).
    void restart(int width, int height, int aa, bool canAverage, bool draftAvailable = false);
    bool draftPreview() const { return draftPreview_; }  // the preview planned at the restart
    ViewStep next() const;                               // what to draw now; None once done
    void finished(const ViewStep& step, double ms);      // it was drawn, taking ms
    void otherWork(double ms);  // the rest of a frame (UI, showing the picture, the swap) took ms
    double budgetMs() const;    // the scene's share: the frame budget less the rest, measured

    bool done() const { return started_ && sample_ >= samples_; }
    bool previewing() const {
        return !previewed_ || ((divisor_ > 1 || draftPreview_) && sample_ == 0 && rowsDone_ == 0);
    }
    int pass() const { return sample_ + 1; }  // the full-size pass under way, 1-based
    int samples() const { return samples_; }
    int divisor() const { return divisor_; }             // of the last preview
    double msPerPixel() const { return cost_.value(); }  // of the passes
    // "160x90 (1/8) preview", "1280x720 (1/1) draft preview", "1280x720 refining 2/4",
    // "1280x720 done".
    std::string describe() const;

private:
    RefinementSettings s_;
    bool fullSizeFits() const;
    const RunningMean& previewCost() const;
    const RunningMean& passCost() const;

    RunningMean cost_;       // ms per pixel of the passes, and of previews at their settings
    RunningMean draftCost_;  // ms per pixel of draft previews
    RunningMean otherMs_;    // the frame's other work
    bool started_ = false, previewed_ = false, draftPreview_ = false;
    int width_ = 0, height_ = 0, aa_ = 1, samples_ = 1;
    int divisor_ = 0;   // of the last preview; kept across restarts for previewDivisor's hysteresis
    int sample_ = 0;    // the full-size pass being drawn: sample number
    int rowsDone_ = 0;  // of that pass, from the top down
    int lastRows_ = 0;  // of the last band; 0 before the first band after a restart
};

}  // namespace mb
