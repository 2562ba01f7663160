// refinement.cpp — the view's drawing policy: budgeted previews, then full size and more samples.
#include "marchbox/editor/refinement.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace mb {

void RunningMean::add(double sample) {
    value_ = known_ ? (1.0 - rate_) * value_ + rate_ * sample : sample;
    known_ = true;
}

// A preview at divisor d draws width·height/d² pixels.
static double estimateMs(double msPerPixel, int width, int height, int d) {
    return msPerPixel * double(width) * double(height) / double(d * d);
}

int previewDivisor(double msPerPixel, int width, int height, int previous, int maxDivisor,
                   double budgetMs) {
    const int most = std::max(1, maxDivisor);
    if (previous >= 1 && previous <= most) {
        double ms = estimateMs(msPerPixel, width, height, previous);
        if (ms >= 0.5 * budgetMs && ms <= 1.25 * budgetMs) return previous;
    }
    // est(d) ≤ budget  ⇔  d ≥ √(width·height·msPerPixel / budget)
    double d = std::ceil(std::sqrt(estimateMs(msPerPixel, width, height, 1) / budgetMs));
    return std::clamp(int(std::min(d, double(most))), 1, most);
}

int bandRows(double msPerPixel, int width, int rowsLeft, double budgetMs) {
    if (rowsLeft <= 0) return 0;
    if (msPerPixel <= 0.0 || width <= 0) return rowsLeft;
    double rows = std::floor(budgetMs / (msPerPixel * double(width)));
    return int(std::clamp(rows, 1.0, double(rowsLeft)));
}

int sampleCount(int aa, bool canAverage, const RefinementSettings& s) {
    if (!canAverage) return 1;
    return aa > 1 ? aa * aa : std::max(1, s.jitterSamples);
}

// The radical inverse of i in `base`: 0.1, 0.01, 0.11, ... read as a fraction (Halton's sequence).
static float halton(int i, int base) {
    float f = 1.0f, r = 0.0f;
    for (; i > 0; i /= base) {
        f /= float(base);
        r += f * float(i % base);
    }
    return r;
}

glm::vec2 samplePosition(int k, int aa) {
    if (aa <= 1) {
        // Halton index 1 is (1/2, 1/3), next to the centre already drawn: start from index 2.
        return k == 0 ? glm::vec2(0.5f) : glm::vec2(halton(k + 1, 2), halton(k + 1, 3));
    }
    std::vector<glm::vec2> grid;
    for (int j = 0; j < aa; ++j)
        for (int i = 0; i < aa; ++i)
            grid.push_back({(i + 0.5f) / float(aa), (j + 0.5f) / float(aa)});
    // Nearest the centre first: the first full-size pass then looks like the preview, unshifted.
    auto fromCentre = [](glm::vec2 p) {
        return (p.x - 0.5f) * (p.x - 0.5f) + (p.y - 0.5f) * (p.y - 0.5f);
    };
    std::stable_sort(grid.begin(), grid.end(),
                     [&](glm::vec2 a, glm::vec2 b) { return fromCentre(a) < fromCentre(b); });
    return grid[size_t(std::clamp(k, 0, aa * aa - 1))];
}

void Refinement::restart(int width, int height, int aa, bool canAverage, bool draftAvailable) {
    started_ = true;
    previewed_ = false;
    width_ = std::max(1, width);
    height_ = std::max(1, height);
    draftPreview_ = draftAvailable && !fullSizeFits();
    aa_ = canAverage ? std::max(1, aa) : 1;  // ids: the one sample at the pixel's centre
    samples_ = sampleCount(aa, canAverage, s_);
    sample_ = rowsDone_ = 0;
    lastRows_ = 0;  // the preview's cost is a whole-image average: no band to grow from yet
}

// Each kind of step sized by its own cost. Until one is known the other stands in: the passes'
// overestimates a draft preview (it comes out coarser), the draft's underestimates the first
// band (whose draw then corrects it).
const RunningMean& Refinement::previewCost() const {
    return draftPreview_ && draftCost_.known() ? draftCost_ : cost_;
}
const RunningMean& Refinement::passCost() const { return cost_.known() ? cost_ : draftCost_; }

ViewStep Refinement::next() const {
    ViewStep step;
    if (!started_ || done()) return step;
    if (!previewed_) {
        const RunningMean& cost = previewCost();
        step.kind = StepKind::Preview;
        step.divisor =
            cost.known()
                ? previewDivisor(cost.value(), width_, height_, divisor_, s_.maxDivisor, budgetMs())
                : std::max(1, s_.maxDivisor);  // nothing learnt yet: the cheapest
        step.width = (width_ + step.divisor - 1) / step.divisor;
        step.height = (height_ + step.divisor - 1) / step.divisor;
        step.startsFrame = true;
        return step;
    }
    step.kind = StepKind::Band;
    step.width = width_;
    step.height = height_;
    const int top = height_ - rowsDone_;  // top down, as a person reads
    int rows = bandRows(passCost().value(), width_, top, budgetMs());
    // Bands run from the sky down into mirrors: the cost learnt from cheap rows underestimates
    // the next ones, so a band may at most double the last.
    if (lastRows_ > 0) rows = std::min(rows, 2 * lastRows_);
    rows = std::max(kBandAlign, rows / kBandAlign * kBandAlign);
    step.y = std::max(0, top - rows) / kBandAlign * kBandAlign;
    step.rows = top - step.y;
    step.sample = sample_;
    step.subpixel = samplePosition(sample_, aa_);
    step.weight = 1.0f / float(sample_ + 1);
    step.startsFrame = sample_ == 0 && rowsDone_ == 0;
    return step;
}

// Whether the view's own full-size frame, at the passes' cost, fits the budget: then a change is
// drawn whole at the view's quality (a GPU's case), not as a draft. Once so, it stays so while
// the frame is at most a quarter over, so the picture does not flicker between the two.
bool Refinement::fullSizeFits() const {
    if (!cost_.known()) return false;
    const double slack = draftPreview_ ? 1.0 : 1.25;
    return estimateMs(cost_.value(), width_, height_, 1) <= slack * budgetMs();
}

double Refinement::budgetMs() const {
    double other = otherMs_.known() ? otherMs_.value() : 0.0;
    return std::max(s_.minSceneMs, s_.frameBudgetMs - other);
}

void Refinement::otherWork(double ms) {
    if (ms >= 0.0) otherMs_.add(ms);
}

void Refinement::finished(const ViewStep& step, double ms) {
    const bool draft = step.kind == StepKind::Preview && draftPreview_;
    if (step.pixels() > 0 && ms >= 0.0)
        (draft ? draftCost_ : cost_).add(ms / double(step.pixels()));
    if (step.kind == StepKind::Preview) {
        previewed_ = true;
        divisor_ = step.divisor;
        if (divisor_ == 1 && !draft) sample_ = 1;  // a full-size preview is the first pass, whole
        return;
    }
    if (step.kind != StepKind::Band) return;
    lastRows_ = step.rows;
    rowsDone_ += step.rows;
    if (rowsDone_ >= height_) {
        ++sample_;
        rowsDone_ = 0;
    }
}

std::string Refinement::describe() const {
    if (!started_) return "no picture yet";
    auto size = [](int w, int h) { return std::to_string(w) + "x" + std::to_string(h); };
    if (previewing()) {  // before the preview is drawn, the one on its way
        int d = previewed_ ? divisor_ : next().divisor;
        return size((width_ + d - 1) / d, (height_ + d - 1) / d) + " (1/" + std::to_string(d) +
               ")" + (draftPreview_ ? " draft" : "") + " preview";
    }
    if (done()) return size(width_, height_) + " done";
    return size(width_, height_) + " refining " + std::to_string(pass()) + "/" +
           std::to_string(samples_);
}

}  // namespace mb
