// quality_preset.cpp — the one table of quality presets.
#include "marchbox/gl/quality_preset.h"

#include <algorithm>

namespace mb {

namespace {

// Measured with `marchbox report render` on llvmpipe, 2 threads, 480x270, against each scene's
// converged render (4096 steps, epsilon 1e-5, same sampling); docs/render-report.md:
// MEASURED
constexpr QualityPresetSettings kPresets[kQualityPresetCount] = {
    //  name      maxSteps minSteps minEps  maxEps  maxRefl minAa shadowSteps cone
    {"draft",     64,      0,       3e-3f,  0.0f,   1,      0,    32,         true},
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

void applyQualityPreset(QualityPreset p, RenderSettings* r, RenderQuality* q) {
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
