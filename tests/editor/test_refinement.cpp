// test_refinement.cpp — the view's drawing policy: previews fit the budget, bands cover every
// row once per pass, samples add up to the scene's own pattern.
#include "marchbox/editor/refinement.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <utility>
#include <vector>

using namespace mb;

// 1280x720 on llvmpipe: the default scene's full frame takes about 5 s, 5.4 µs a pixel.
constexpr double kSlow = 5.4e-3;
constexpr double kFast = 2e-5;  // a GPU: the whole frame in 18 ms

// Draws every step the policy asks for, each taking exactly pixels × msPerPixel.
static std::vector<ViewStep> drawAll(Refinement& r, double msPerPixel, int limit = 100000) {
    std::vector<ViewStep> steps;
    for (ViewStep s = r.next(); s.kind != StepKind::None && limit-- > 0; s = r.next()) {
        steps.push_back(s);
        r.finished(s, double(s.pixels()) * msPerPixel);
    }
    return steps;
}

TEST(RunningMean, FirstSampleSetsItThenAverages) {
    RunningMean m(0.25);
    EXPECT_FALSE(m.known());
    m.add(0.1);
    EXPECT_DOUBLE_EQ(m.value(), 0.1);
    m.add(0.5);  // a quarter of the way there
    EXPECT_DOUBLE_EQ(m.value(), 0.2);
}

constexpr double kBudget = 40.0;

TEST(PreviewDivisor, SmallestThatFitsTheBudget) {
    for (double cost : {3e-5, 1e-4, 3e-4, 1e-3}) {
        int d = previewDivisor(cost, 1280, 720, 0, 8, kBudget);
        EXPECT_LE(cost * 1280 * 720 / (d * d), kBudget) << cost;
        if (d > 1) {
            EXPECT_GT(cost * 1280 * 720 / ((d - 1) * (d - 1)), kBudget) << cost;
        }
    }
}

TEST(PreviewDivisor, WithinOneAndTheMinimum) {
    EXPECT_EQ(previewDivisor(kFast, 1280, 720, 0, 8, kBudget), 1);
    EXPECT_EQ(previewDivisor(kSlow, 1280, 720, 0, 8, kBudget), 8);  // 78 ms at 1/8: never coarser
    EXPECT_EQ(previewDivisor(1.0, 1280, 720, 0, 8, kBudget), 8);
}

TEST(PreviewDivisor, KeepsThePreviousWhileNearTheBudget) {
    // 1280x720 at 1/3 is 102,400 pixels: 35 ms at this cost, 0.875 of the budget.
    const double cost = 35.0 / 102400;
    EXPECT_EQ(previewDivisor(cost, 1280, 720, 0, 8, kBudget), 3);
    EXPECT_EQ(previewDivisor(cost * 1.3, 1280, 720, 3, 8, kBudget),
              3);  // 46 ms: within 1.25 × budget
    EXPECT_EQ(previewDivisor(cost * 1.6, 1280, 720, 3, 8, kBudget), 4);  // 56 ms: too slow, coarser
    EXPECT_EQ(previewDivisor(cost * 0.6, 1280, 720, 3, 8, kBudget), 3);  // 21 ms: still over half
    EXPECT_EQ(previewDivisor(cost * 0.5, 1280, 720, 3, 8, kBudget), 2);  // 17.5 ms: sharper
}

TEST(Refinement, TheSceneGetsWhatTheRestOfTheFrameLeaves) {
    RefinementSettings s;
    Refinement r(s);
    EXPECT_DOUBLE_EQ(r.budgetMs(), s.frameBudgetMs);  // nothing measured yet
    r.otherWork(20.0);
    EXPECT_DOUBLE_EQ(r.budgetMs(), s.frameBudgetMs - 20.0);
    for (int i = 0; i < 50; ++i) r.otherWork(200.0);  // a crawling UI
    EXPECT_DOUBLE_EQ(r.budgetMs(), s.minSceneMs);
    // The smaller share makes a coarser preview.
    r.restart(1280, 720, 1, true);
    r.finished(r.next(), 160 * 90 * 2e-4);
    r.restart(1280, 720, 1, true);
    EXPECT_EQ(r.next().divisor, 5);  // 184 ms in full; 7.4 ms at 1/5 fits 10, 11.5 at 1/4 not
}

TEST(BandRows, FitTheBudgetAndTheRowsLeft) {
    EXPECT_EQ(bandRows(1e-3, 1000, 720, 40.0), 40);
    EXPECT_EQ(bandRows(1e-3, 1000, 25, 40.0), 25);
    EXPECT_EQ(bandRows(1.0, 1000, 720, 40.0), 1);    // even one row is over: one row
    EXPECT_EQ(bandRows(0.0, 1000, 720, 40.0), 720);  // nothing known: all of it
    EXPECT_EQ(bandRows(1e-3, 1000, 0, 40.0), 0);
}

TEST(Samples, CountFollowsTheScene) {
    RefinementSettings s;
    EXPECT_EQ(sampleCount(3, true, s), 9);
    EXPECT_EQ(sampleCount(1, true, s), s.jitterSamples);
    EXPECT_EQ(sampleCount(3, false, s), 1);  // object ids do not average
}

TEST(Samples, TheScenesGridNearestTheCentreFirst) {
    for (int aa = 2; aa <= 4; ++aa) {
        std::set<std::pair<float, float>> seen, grid;
        for (int j = 0; j < aa; ++j)
            for (int i = 0; i < aa; ++i)
                grid.insert({(i + 0.5f) / aa, (j + 0.5f) / aa});  // render_passes.cpp
        float lastDistance = 0.0f;
        for (int k = 0; k < aa * aa; ++k) {
            glm::vec2 p = samplePosition(k, aa);
            seen.insert({p.x, p.y});
            float d = (p.x - 0.5f) * (p.x - 0.5f) + (p.y - 0.5f) * (p.y - 0.5f);
            EXPECT_GE(d, lastDistance) << "aa " << aa << " sample " << k;
            lastDistance = d;
        }
        EXPECT_EQ(seen, grid) << "aa " << aa;
    }
    EXPECT_EQ(samplePosition(0, 3), glm::vec2(0.5f));
}

TEST(Samples, JitterStartsAtTheCentreAndSpreads) {
    EXPECT_EQ(samplePosition(0, 1), glm::vec2(0.5f));
    std::set<std::pair<float, float>> seen;
    glm::vec2 mean(0.0f);
    for (int k = 0; k < 8; ++k) {
        glm::vec2 p = samplePosition(k, 1);
        EXPECT_GT(p.x, 0.0f);
        EXPECT_LT(p.x, 1.0f);
        EXPECT_GT(p.y, 0.0f);
        EXPECT_LT(p.y, 1.0f);
        seen.insert({p.x, p.y});
        mean += p / 8.0f;
    }
    EXPECT_EQ(seen.size(), 8u);
    EXPECT_NEAR(mean.x, 0.5f, 0.1f);  // no drift: the picture does not shift as it refines
    EXPECT_NEAR(mean.y, 0.5f, 0.1f);
}

TEST(Refinement, FirstAPreviewAtTheCoarsestWhileTheCostIsUnknown) {
    Refinement r;
    EXPECT_EQ(r.next().kind, StepKind::None);
    r.restart(1280, 720, 1, true);
    ViewStep s = r.next();
    EXPECT_EQ(s.kind, StepKind::Preview);
    EXPECT_EQ(s.divisor, 8);
    EXPECT_EQ(s.width, 160);
    EXPECT_EQ(s.height, 90);
    EXPECT_TRUE(s.startsFrame);
    EXPECT_EQ(r.describe(), "160x90 (1/8) preview");
}

TEST(Refinement, EveryStepFitsTheBudget) {
    RefinementSettings s;
    for (double cost : {kSlow, 2e-4, kFast}) {
        Refinement r(s);
        r.otherWork(12.0);
        r.restart(1280, 720, 1, true);
        r.finished(r.next(), 160 * 90 * cost);  // the first preview teaches the cost
        r.restart(1280, 720, 1, true);
        for (const ViewStep& step : drawAll(r, cost)) {
            bool smallest = step.kind == StepKind::Preview ? step.divisor == s.maxDivisor
                                                           : step.rows <= kBandAlign;
            if (!smallest) {
                EXPECT_LE(double(step.pixels()) * cost, s.frameBudgetMs - 12.0) << cost;
            }
        }
    }
}

TEST(Refinement, BandsCoverEveryRowOncePerSample) {
    Refinement r;
    r.restart(640, 400, 2, true);
    std::vector<ViewStep> steps = drawAll(r, 1e-3);
    ASSERT_EQ(steps.front().kind, StepKind::Preview);
    std::vector<std::vector<int>> covered(4, std::vector<int>(400, 0));
    int lastSample = 0;
    for (size_t i = 1; i < steps.size(); ++i) {
        const ViewStep& b = steps[i];
        ASSERT_EQ(b.kind, StepKind::Band);
        EXPECT_GE(b.sample, lastSample);  // one pass at a time
        lastSample = b.sample;
        EXPECT_FLOAT_EQ(b.weight, 1.0f / float(b.sample + 1));
        EXPECT_EQ(b.subpixel, samplePosition(b.sample, 2));
        EXPECT_EQ(b.startsFrame, i == 1);
        for (int y = b.y; y < b.y + b.rows; ++y) covered[size_t(b.sample)][size_t(y)]++;
    }
    for (const std::vector<int>& rows : covered)
        for (int n : rows) EXPECT_EQ(n, 1);
    EXPECT_TRUE(r.done());
    EXPECT_EQ(r.describe(), "640x400 done");
}

TEST(Refinement, BandEdgesFallOnWholeBlocks) {
    for (int height : {400, 403}) {
        Refinement r;
        r.restart(640, height, 1, true);
        std::vector<ViewStep> steps = drawAll(r, 3e-3);  // bands of about 20 rows
        for (size_t i = 1; i < steps.size(); ++i) {
            EXPECT_EQ(steps[i].y % kBandAlign, 0) << "height " << height << " band " << i;
            if (steps[i].y + steps[i].rows != height) {
                EXPECT_EQ(steps[i].rows % kBandAlign, 0) << "height " << height << " band " << i;
            }
        }
    }
}

TEST(Refinement, BandsGoTopDownAndGrowAtMostTwofold) {
    RefinementSettings s;
    s.learnRate = 1.0;  // the cost is the last draw's: the limit alone keeps bands from leaping
    Refinement r(s);
    r.restart(1000, 720, 1, true);
    r.finished(r.next(), 125 * 90 * 1e-2);  // an expensive preview: 10 µs a pixel
    int top = 720, last = 0;
    for (int i = 0; i < 6; ++i) {
        ViewStep b = r.next();
        EXPECT_EQ(b.y + b.rows, top);
        if (last) {
            EXPECT_LE(b.rows, 2 * last);
        }
        top = b.y;
        last = b.rows;
        r.finished(b, 0.01);  // the sky: nearly free, so the cost falls fast
    }
}

TEST(Refinement, AFullSizePreviewIsTheFirstPass) {
    Refinement r;
    r.restart(640, 360, 1, true);
    r.finished(r.next(), 0.1);  // 80x45 in 0.1 ms: full size fits easily
    r.restart(640, 360, 1, true);
    ViewStep p = r.next();
    ASSERT_EQ(p.divisor, 1);
    r.finished(p, 10.0);
    EXPECT_EQ(r.describe(), "640x360 refining 2/4");
    ViewStep b = r.next();
    EXPECT_EQ(b.kind, StepKind::Band);
    EXPECT_EQ(b.sample, 1);
    EXPECT_FALSE(b.startsFrame);  // it adds to the preview's image
}

// The preview at draft settings only stands in: every pass, the first included, is drawn at the
// view's own settings over it.
TEST(Refinement, ADraftPreviewIsNotTheFirstPass) {
    Refinement r;
    r.restart(640, 360, 1, true, true);
    r.finished(r.next(), 0.1);  // 80x45 in 0.1 ms: full size fits easily
    r.restart(640, 360, 1, true, true);
    ViewStep p = r.next();
    ASSERT_EQ(p.divisor, 1);
    EXPECT_EQ(r.describe(), "640x360 (1/1) draft preview");
    r.finished(p, 10.0);
    EXPECT_TRUE(r.previewing());
    ViewStep b = r.next();
    EXPECT_EQ(b.kind, StepKind::Band);
    EXPECT_EQ(b.sample, 0);
    EXPECT_TRUE(b.startsFrame);  // the pass replaces the preview, not adds to it
    std::vector<ViewStep> steps = drawAll(r, 1e-5);
    EXPECT_EQ(steps.back().sample, r.samples() - 1);
    EXPECT_TRUE(r.done());
}

// Draft previews cost less than the passes: each is sized by its own figure, so a cheap preview
// does not make the bands after it overrun the budget.
TEST(Refinement, DraftPreviewsAndPassesLearnTheirCostsApart) {
    Refinement r;
    r.restart(1280, 720, 1, true);
    r.finished(r.next(), 160 * 90 * kSlow);  // a preview at the passes' settings: 5.4 µs a pixel
    r.restart(1280, 720, 1, true, true);
    ViewStep p = r.next();  // no draft drawn yet: sized by the passes' cost, an overestimate
    EXPECT_EQ(p.divisor, previewDivisor(kSlow, 1280, 720, 8, 8, r.budgetMs()));
    r.finished(p, double(p.pixels()) * kSlow / 4);  // the draft: 4 times cheaper
    ViewStep b = r.next();
    EXPECT_EQ(b.rows, bandRows(kSlow, 1280, 720, r.budgetMs()) / kBandAlign * kBandAlign);
    r.restart(1280, 720, 1, true, true);
    EXPECT_EQ(r.next().divisor, previewDivisor(kSlow / 4, 1280, 720, p.divisor, 8, r.budgetMs()));
    EXPECT_DOUBLE_EQ(r.msPerPixel(), kSlow);
}

TEST(Refinement, ARestartGoesBackToAPreview) {
    Refinement r;
    r.restart(640, 360, 1, true);
    drawAll(r, kSlow, 5);
    EXPECT_EQ(r.describe(), "640x360 refining 1/4");
    r.restart(640, 360, 1, true);
    EXPECT_EQ(r.next().kind, StepKind::Preview);
    EXPECT_FALSE(r.done());
}

TEST(Refinement, ObjectIdsTakeOneSampleAtTheCentre) {
    Refinement r;
    r.restart(320, 180, 3, false);
    std::vector<ViewStep> steps = drawAll(r, 1e-3);
    for (size_t i = 1; i < steps.size(); ++i) {
        EXPECT_EQ(steps[i].sample, 0);
        EXPECT_EQ(steps[i].subpixel, glm::vec2(0.5f));
    }
    EXPECT_EQ(r.samples(), 1);
    EXPECT_TRUE(r.done());
}

//-----------------------------------------------------------------------------
// [SECTION] Frame-time series: a camera orbiting (a restart every frame), then still
//-----------------------------------------------------------------------------

// Full-size frame times measured at 1920x1080: on an NVIDIA H100 through EGL (medians of 20
// frames), pile.txt 6.6 ms and mixed_pile.txt 23.1 ms; on llvmpipe here, default.txt at 1280x720
// about 5 s (kSlow). Each draw below takes its pixels at the scene's cost times a wobble of
// ±30% (sky, mirrors and shadows coming and going as the camera turns), and the UI 4 ms.
namespace {

constexpr int kHdW = 1920, kHdH = 1080;
constexpr double kPileH100 = 6.6 / (kHdW * kHdH), kMixedPileH100 = 23.1 / (kHdW * kHdH);
constexpr double kUiMs = 4.0;

double wobble(int frame) { return 1.0 + 0.3 * std::sin(1.7 * double(frame)); }

struct Orbit {
    std::vector<ViewStep> previews;  // one a frame
    std::vector<double> ms;          // what each took
    std::vector<bool> drafts;        // drawn by the draft renderer
};

// `frames` frames of orbiting: each restarts the view and draws its preview, with a draft
// renderer available as in the editor.
Orbit orbit(Refinement& r, int width, int height, double msPerPixel, int frames) {
    Orbit o;
    for (int f = 0; f < frames; ++f) {
        r.restart(width, height, 1, true, true);
        const ViewStep p = r.next();
        const double draftCheaper = r.draftPreview() ? 0.25 : 1.0;
        const double ms = double(p.pixels()) * msPerPixel * draftCheaper * wobble(f);
        r.finished(p, ms);
        r.otherWork(kUiMs);
        o.previews.push_back(p), o.ms.push_back(ms), o.drafts.push_back(r.draftPreview());
    }
    return o;
}

// Still: every step drawn, the wobble still on; the frames it took (one step a frame).
int refine(Refinement& r, double msPerPixel, std::vector<double>* ms) {
    int frames = 0;
    for (ViewStep s = r.next(); s.kind != StepKind::None && frames < 10000;
         s = r.next(), ++frames) {
        ms->push_back(double(s.pixels()) * msPerPixel * wobble(frames));
        r.finished(s, ms->back());
        r.otherWork(kUiMs);
    }
    return frames;
}

}  // namespace

// On a GPU the view moves at full size and at its own quality: once the passes' cost is known
// (the scene's first still picture), every frame of an orbit is the whole 1920x1080 frame, the
// first pass itself, not a draft, and none falls back under the ±30% wobble. Planted: restart
// taking the draft whenever one is available (every preview a draft, as before this policy).
TEST(RefinementSeries, OnAGpuTheViewMovesAtFullSizeAndQuality) {
    for (double cost : {kPileH100, kMixedPileH100}) {
        Refinement r;
        r.restart(kHdW, kHdH, 1, true, true);
        std::vector<double> ms;
        refine(r, cost, &ms);  // the picture as opened, refined while still
        ASSERT_TRUE(r.done());
        const Orbit o = orbit(r, kHdW, kHdH, cost, 120);
        for (size_t f = 0; f < o.previews.size(); ++f) {
            ASSERT_EQ(o.previews[f].divisor, 1) << "frame " << f << " at " << cost;
            ASSERT_FALSE(o.drafts[f]) << "frame " << f << " at " << cost;
        }
        EXPECT_EQ(r.describe(), "1920x1080 refining 2/4");  // the frame shown is the first pass
    }
}

// On llvmpipe a 5 s frame degrades gracefully: while the camera moves every frame is a draft
// preview (a quarter of the cost), 214x120 at 1/6, drawn in about 32 ms of the 46 ms the UI
// leaves, within the budget but for its wobble; once still, the bands reach full size and all
// four samples in some 700 frames, each within the budget likewise. Planted: restart never
// drafting (at the view's own quality even 160x90 takes 78 ms a frame, over the budget).
TEST(RefinementSeries, OnACpuTheViewCoarsensWithinTheBudgetThenRefines) {
    Refinement r;
    r.restart(1280, 720, 1, true, true);
    std::vector<double> still;
    refine(r, kSlow, &still);
    ASSERT_TRUE(r.done());
    const Orbit o = orbit(r, 1280, 720, kSlow, 60);
    for (size_t f = 0; f < o.previews.size(); ++f) {
        EXPECT_TRUE(o.drafts[f]) << "frame " << f;
        EXPECT_LE(o.ms[f], 1.3 * r.budgetMs()) << "frame " << f;
    }
    std::vector<double> ms;
    const int frames = refine(r, kSlow, &ms);
    EXPECT_TRUE(r.done());
    EXPECT_EQ(r.describe(), "1280x720 done");
    for (double m : ms) EXPECT_LE(m, 1.3 * r.budgetMs());
    std::printf("llvmpipe, 5 s a frame: preview %dx%d in %.1f ms, then %d frames to refine\n",
                o.previews.back().width, o.previews.back().height, o.ms.back(), frames);
}
