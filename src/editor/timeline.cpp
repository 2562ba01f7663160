// timeline.cpp — the timeline strip's pixels and seconds.
#include "marchbox/editor/timeline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace mb {

float TimelineStrip::x(double t) const { return left + float(t / span) * width; }

double TimelineStrip::time(float px) const {
    return std::clamp(double(px - left) / double(width), 0.0, 1.0) * span;
}

TimelineStrip timelineStrip(float left, float width, double cached,
                            const std::vector<Keyframe>& keys, double now) {
    double last = std::max(cached, now);
    for (const Keyframe& k : keys) last = std::max(last, double(k.t));
    return {left, std::max(width, 1.0f), std::max(1.0, last * 1.1)};
}

int keyMarkerAt(const TimelineStrip& strip, const std::vector<Keyframe>& keys, float px,
                float reach) {
    int best = -1;
    float nearest = 0.0f;
    for (size_t i = 0; i < keys.size(); ++i) {
        const float d = std::abs(strip.x(keys[i].t) - px);
        if (d <= reach && (best < 0 || d < nearest)) best = int(i), nearest = d;
    }
    return best;
}

double tickStep(const TimelineStrip& strip, float gap) {
    const double least = strip.span * gap / strip.width;
    double step = std::pow(10.0, std::floor(std::log10(least)));
    for (double m : {1.0, 2.0, 5.0})
        if (step * m >= least) return step * m;
    return step * 10.0;
}

std::string tickLabel(double t, double step) {
    // A step of 0.05 s needs two decimals, 0.5 s one, 5 s none.
    const int decimals = std::clamp(int(std::ceil(-std::log10(step) - 1e-9)), 0, 6);
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", decimals, t);
    return text;
}

double loopEnd(const std::vector<Keyframe>& keys, double baked) {
    const double last = keys.empty() ? 0.0 : double(keys.back().t);
    return last > 0 ? last : baked;
}

double playHead(double head, double seconds, double end) {
    const double next = head + seconds;
    // Step sums run a rounding past a time they were meant to meet: that is still at the end.
    return end > 0 && next > end + 1e-9 ? 0.0 : next;
}

}  // namespace mb
