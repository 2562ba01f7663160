// reference_sky.cpp — sky, suns and fog of the CPU reference (docs/shading-model.md §7, §8).
#include "reference_model.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace mb::reference {

namespace {

const dvec3 kZenith(0.30, 0.50, 0.85);
const dvec3 kHorizon(0.80, 0.86, 0.92);    // before the tint
const dvec3 kUnderside(0.35, 0.33, 0.30);  // what a ray below the horizon sees with no ground
constexpr double kTintShare = 0.35;
constexpr double kSkyHeight = 200.0;       // the sky is fogged as if it hung this high
constexpr double kLowestElevation = 1e-3;  // keeps the sky's fog distance finite at the horizon

// Sky colour by elevation e = sin(angle above the horizon): square roots make the colour
// change fastest near the horizon, where the eye expects the haze.
dvec3 gradient(const Model& m, double e) {
    if (e >= 0.0) return m.horizon + (kZenith - m.horizon) * std::sqrt(e);
    return m.horizon + (kUnderside - m.horizon) * std::sqrt(-e);
}

// Each directional light is a sun: a disc of 1.4 degrees radius, its rim fading out by 1.8
// (cos 0.9997 and 0.9995), of `discWeight` times the light, over a broad cos^64 halo of a quarter.
dvec3 sunLight(const Model& m, dvec3 dir, double discWeight) {
    dvec3 sum(0.0);
    for (const LightSource& l : m.lights) {
        if (!l.directional) continue;
        double c = std::max(glm::dot(dir, l.vec), 0.0);
        sum += l.radiance * (discWeight * smoothstep(0.9995, 0.9997, c) + 0.25 * std::pow(c, 64.0));
    }
    return sum;
}

// Fog is the horizon seen in the ray's direction: the sun's glow shows through it, its disc not.
dvec3 fogColor(const Model& m, dvec3 dir) { return m.horizon + sunLight(m, dir, 0.0); }

}  // namespace

double smoothstep(double edge0, double edge1, double x) {
    double s = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return s * s * (3.0 - 2.0 * s);
}

// The brightest light (largest channel of colour × intensity; the first of equals) gives its
// hue, scaled so its largest channel is 1, to a third of the horizon.
dvec3 skyHorizon(const Scene& scene) {
    dvec3 tint(1.0);
    double best = 0.0;
    for (const Light& l : scene.lights) {
        dvec3 c = dvec3(l.color) * double(l.intensity);
        double power = std::max({c.r, c.g, c.b});
        if (power > best) best = power, tint = c / power;
    }
    return kHorizon * ((1.0 - kTintShare) + kTintShare * tint);
}

dvec3 skyColor(const Model& m, dvec3 dir) {
    dvec3 open = gradient(m, dir.y) + sunLight(m, dir, 4.0);
    return applyFog(m, open, dir, kSkyHeight / std::max(dir.y, kLowestElevation));
}

// exp² fog: the share of the surface's own colour left after t metres is exp(-(density·t)²).
dvec3 applyFog(const Model& m, dvec3 color, dvec3 dir, double t) {
    double density = m.scene->render.fog;
    if (density <= 0.0) return color;
    double kept = std::exp(-(density * t) * (density * t));
    dvec3 fog = fogColor(m, dir);
    return fog + (color - fog) * kept;
}

}  // namespace mb::reference
