// marchbox/editor/timeline.h — the timeline strip's geometry: seconds to pixels and back, and
// the camera key under the mouse; where a loop ends and wraps. The Simulation window draws it
// (src/app/panels_sim.cpp).
#pragma once

#include "marchbox/scene/scene.h"

#include <string>
#include <vector>

namespace mb {

struct TimelineStrip {
    float left = 0.0f, width = 1.0f;  // px
    double span = 1.0;                // s from the left end to the right

    float x(double t) const;      // the pixel column of time t
    double time(float px) const;  // the time under pixel column px, within 0..span
};

// A strip from t = 0 past the last of the baked frames (cached), the camera keys and the time
// shown (now), with a tenth to spare so that the end is never at the edge; at least 1 s.
TimelineStrip timelineStrip(float left, float width, double cached,
                            const std::vector<Keyframe>& keys, double now);

// The camera key whose marker is within `reach` px of column px, the nearest; -1 for none.
int keyMarkerAt(const TimelineStrip& strip, const std::vector<Keyframe>& keys, float px,
                float reach);

// The ticks: every 1, 2 or 5 times a power of ten seconds, at least `gap` px apart; each
// labelled with its time in as many decimals as the step needs ("0", "0.5", "1.25").
double tickStep(const TimelineStrip& strip, float gap);
std::string tickLabel(double t, double step);

// Loop playback. The time a loop goes back to 0 at: the last camera key's where it is past 0
// (the clip the keys make), else the end of the baked frames; 0 for neither: no end.
double loopEnd(const std::vector<Keyframe>& keys, double baked);
// The play head `seconds` after `head`: back to 0 once past `end` (0: no end).
double playHead(double head, double seconds, double end);

}  // namespace mb
