// quality_preset.cpp — the one table of quality presets.
#include "marchbox/gl/quality_preset.h"

#include <algorithm>

namespace mb {

namespace {

// Measured with `marchbox report render` on llvmpipe, 2 threads, 480x270, against each scene's
// converged render (4096 steps, epsilon 1e-5, same sampling); docs/render-report.md:
// since the march is bounded and the ground met analytically, steps, epsilon, relaxation and
// shadow steps move frame time by at most 1.3x on default, csg and reflections, and the spread
// of repeated frames is as wide; only pile (124 objects) gains, 1.4x from 128 steps, 1.6x from
// cone epsilon, 1.9x from both with 64 shadow steps, each keeping >= 33 dB. Fewer reflections
// cost 21 dB on reflections; drawing 0.7 or 0.5 of the pixels per axis and stretching them
// (a variant measured once, on 2026-11-22, and dropped) was 1.5-4.6x faster but only 22-27 dB,
// and the editor's live view already previews at reduced size. So draft takes the marching cuts that hold >= 28 dB on every
// scene, and is 2x faster only where marching is the cost (pile).
constexpr QualityPresetSettings kPresets[kQualityPresetCount] = {
    //  name      maxSteps minSteps minEps  maxEps  maxRefl minAa shadowSteps cone
    {"draft",     128,     0,       0.0f,   0.0f,   -1,     0,    64,         true},
    {"normal",    0,       0,       0.0f,   0.0f,   -1,     0,    0,          false},
    {"final",     0,       1024,    0.0f,   1e-4f,  -1,     3,    256,        false},
};

}  // namespace

const char* qualityPresetName(QualityPreset p) { return kPresets[int(p)].name; }

bool parseQualityPreset(const std::string& s, QualityPreset* out) {
    for (int i = 0; i < kQualityPresetCount; ++i)
        if (s == kPresets[i].name) return *out = QualityPreset(i), true;
    return false;
}

const QualityPresetSettings& qualityPresetSettings(QualityPreset p) { return kPresets[int(p)]; }

void applyQualityPreset(QualityPreset p, RenderSettings* r, RenderOptions* o) {
    RenderQuality* q = &o->quality;
    const QualityPresetSettings& s = kPresets[int(p)];
    if (s.maxSteps) r->steps = std::min(r->steps, s.maxSteps);
    if (s.minSteps) r->steps = std::max(r->steps, s.minSteps);
    if (s.minEpsilon > 0) r->epsilon = std::max(r->epsilon, s.minEpsilon);
    if (s.maxEpsilon > 0) r->epsilon = std::min(r->epsilon, s.maxEpsilon);
    if (s.maxReflections >= 0) r->reflections = std::min(r->reflections, s.maxReflections);
    if (s.minAa) r->aa = std::max(r->aa, s.minAa);
    if (s.shadowSteps) q->shadowSteps = s.shadowSteps;
    if (s.coneEpsilon) q->coneEpsilon = true;
}

}  // namespace mb
