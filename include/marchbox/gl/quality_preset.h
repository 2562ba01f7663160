// marchbox/gl/quality_preset.h — draft, normal and final: presets over a scene's own render
// settings, each a point chosen from the measured error-against-time front
// (docs/render-report.md, "Quality presets").
#pragma once

#include "marchbox/gl/renderer.h"
#include "marchbox/scene/scene.h"

#include <string>

namespace mb {

enum class QualityPreset : int { Draft = 0, Normal, Final };
constexpr int kQualityPresetCount = 3;

const char* qualityPresetName(QualityPreset p);  // "draft", "normal", "final"
bool parseQualityPreset(const std::string& s, QualityPreset* out);

// What a preset does to the scene's settings. A cap only lowers a value, a floor only raises it,
// so a scene already cheaper than draft (or finer than final) keeps its own value; 0 leaves the
// setting as the scene has it.
struct QualityPresetSettings {
    const char* name;
    int maxSteps, minSteps;        // march steps
    float minEpsilon, maxEpsilon;  // hit distance
    int maxReflections;            // -1: the scene's own
    int minAa, maxAa;              // supersamples per axis
    int shadowSteps;               // RenderQuality::shadowSteps; 0: the renderer's own
    bool coneEpsilon;              // true turns RenderQuality::coneEpsilon on
    float shadowCutoff;            // RenderQuality::shadowCutoff; 0: every light casts
    bool checkerboard;             // true turns RenderQuality::checkerboard on
};
const QualityPresetSettings& qualityPresetSettings(QualityPreset p);

// Applies the preset to a scene's render record and the renderer's options. Normal changes nothing.
void applyQualityPreset(QualityPreset p, RenderSettings* render, RenderOptions* options);

// The reference the presets' error is measured against: the scene marched to convergence (4096
// steps, epsilon 1e-5), every other setting as written.
Scene converged(Scene scene);

}  // namespace mb
