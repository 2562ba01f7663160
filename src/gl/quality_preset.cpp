// quality_preset.cpp — the one table of quality presets, and the converged reference.
#include "marchbox/gl/quality_preset.h"

#include <algorithm>

namespace mb {

namespace {

// Chosen from the measured front (docs/render-report.md, "Where a frame's time goes" and the
// marching sweeps), llvmpipe, 480x270, against each scene's converged render. llvmpipe runs
// both sides of a branch for its whole SIMD group, so a frame costs about the same per pixel
// wherever it looks: only code left out at compile time or loops cut short save time. What
// draft takes, each at >= 28 dB on every example scene: shadows from the lights at least half
// as bright as the brightest only (1.2-1.3x where a dim second light casts), aa at most 2
// (2.2x on ao_aa's 3x3), 128 steps, 64 shadow steps and cone epsilon (up to 1.4x, on pile),
// and half the pixels shaded in a checkerboard, the rest filled in (1.5-1.6x more, CPU time;
// 28.5-38 dB with the other cuts). Left out: no shadows (24-27 dB), fewer reflections (18-22 dB
// on reflections), fewer pixels stretched (22-27 dB), 32 shadow steps (no faster: shadow rays
// leave their loop early already).
constexpr QualityPresetSettings kPresets[kQualityPresetCount] = {
    //  name      maxSteps minSteps minEps  maxEps  maxRefl minAa maxAa shadowSteps cone   cutoff
    //  checker
    {"draft", 128, 0, 0.0f, 0.0f, -1, 0, 2, 64, true, 0.5f, true},
    {"normal", 0, 0, 0.0f, 0.0f, -1, 0, 0, 0, false, 0.0f, false},
    {"final", 0, 1024, 0.0f, 1e-4f, -1, 3, 0, 256, false, 0.0f, false},
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
    if (s.maxAa) r->aa = std::min(r->aa, s.maxAa);
    if (s.shadowSteps) q->shadowSteps = s.shadowSteps;
    if (s.coneEpsilon) q->coneEpsilon = true;
    if (s.shadowCutoff > 0) q->shadowCutoff = s.shadowCutoff;
    if (s.checkerboard) q->checkerboard = true;
}

Scene converged(Scene scene) {
    scene.render.steps = 4096;
    scene.render.epsilon = 1e-5f;
    return scene;
}

}  // namespace mb
