// reference_shade.cpp — light and mirrors of the CPU reference (docs/shading-model.md §3, §4,
// §6, §9): the surface's material, Phong per light with its shadow, occlusion, the mirror path.
#include "reference_model.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace mb::reference {

namespace {

struct SurfaceMaterial {
    dvec3 albedo{0.0};
    double ka = 0, kd = 0, ks = 0, shininess = 1, kr = 0;
};

// Clamped so a ray that grazes the plane cannot overflow the cast: squares that far out are noise.
long long squareIndex(double v) { return (long long)std::floor(std::clamp(v, -1e15, 1e15)); }

// Along x or z the checkers are a ±1 wave, +1 on even squares, of period 2; its integral from 0
// is a triangle wave, and the mean over [a, b] is the integral's change over b − a. Width 0
// takes the wave's value.
double waveMean(double centre, double width) {
    if (width <= 0.0) return squareIndex(centre) % 2 == 0 ? 1.0 : -1.0;
    auto integral = [](double x) { return 1.0 - std::abs(1.0 - (x - 2.0 * std::floor(x / 2.0))); };
    return (integral(centre + width / 2) - integral(centre - width / 2)) / width;
}

// The x-z box a sample's cone of radius r covers where the ray d meets the floor: 2r across the
// ray, 2r/|d.y| along its level direction (§3); none for a ray with no pixel (r = 0).
glm::dvec2 floorFootprint(dvec3 d, double r) {
    if (r <= 0.0) return glm::dvec2(0.0);
    double level = std::hypot(d.x, d.z);
    double ux = level > 1e-6 ? d.x / level : 1.0, uz = level > 1e-6 ? d.z / level : 0.0;
    double stretch = 1.0 / std::max(std::abs(d.y), 1e-4);
    return glm::max(2.0 * r *
                        glm::dvec2(std::abs(ux) * stretch + std::abs(uz),
                                   std::abs(uz) * stretch + std::abs(ux)),
                    glm::dvec2(1e-4));
}

SurfaceMaterial materialAt(const Model& m, dvec3 p, int object, glm::dvec2 footprint) {
    if (object == kHitGround) {
        double dark = 0.5 - 0.5 * waveMean(p.x, footprint.x) * waveMean(p.z, footprint.y);
        return {dvec3(0.80 + (0.35 - 0.80) * dark), 0.1, 0.8, 0.1, 16.0, 0.0};
    }
    const Scene& s = *m.scene;
    int index = std::clamp(s.objects[size_t(object)].material, 0, int(s.materials.size()) - 1);
    const Material& mat = s.materials[size_t(index)];
    return {dvec3(mat.color), mat.Ka, mat.Kd, mat.Ks, mat.C, mat.Kr};
}

// ReferenceImage::region is FNV-1a over the events that make the colour jump: which surface,
// which checker square, which lights face it and which of them a hard shadow blocks.
void mixKey(uint64_t* key, uint64_t value) { *key = (*key ^ value) * 1099511628211ull; }

struct LightDirection {
    dvec3 l;       // unit, towards the light
    double reach;  // how far a shadow ray goes
};

LightDirection towards(const Model& m, const LightSource& light, dvec3 p) {
    if (light.directional) return {light.vec, m.far};
    dvec3 toLight = light.vec - p;
    double dist = glm::length(toLight);
    return {toLight / std::max(dist, 1e-12), dist};
}

// Ambient Ka·albedo·ao, plus for each light facing the surface its diffuse Kd·(n·l)·albedo and
// specular Ks·(r·v)^C (r: l mirrored about n, v: towards the eye), times its colour and shadow.
// Occlusion dims the direct sum by half of what it takes from the ambient.
dvec3 shade(const Model& m, const SurfaceMaterial& s, dvec3 p, dvec3 n, dvec3 d, PathResult* path) {
    double ao = m.scene->render.ao ? occlusion(m, p, n) : 1.0;
    dvec3 direct(0.0), start = liftOff(p, n, m.epsilon), v = -d;
    for (const LightSource& light : m.lights) {
        LightDirection ld = towards(m, light, p);
        double facing = glm::dot(n, ld.l);
        mixKey(&path->region, facing > 0.0);
        if (facing <= 0.0) continue;
        dvec3 r = 2.0 * facing * n - ld.l;
        double specular = std::pow(std::max(glm::dot(r, v), 0.0), s.shininess);
        double shadow = visibility(m, start, ld.l, ld.reach);
        if (m.scene->render.shadows == 1) mixKey(&path->region, shadow > 0.0);
        path->penumbra = path->penumbra || (shadow > 0.0 && shadow < 1.0);
        direct += light.radiance * shadow * (s.kd * facing * s.albedo + s.ks * specular);
    }
    return s.ka * s.albedo * ao + direct * (0.5 + 0.5 * ao);
}

// A surface on the path: its object, whether its normal is a crease's blend, and on the ground
// its checker square itself, not its parity, which every other square shares. Averaged over a
// sample's footprint the squares' edges are a pixel wide, but a curved mirror spreads its rays
// wider than the cone that footprint assumes, and there they still alias.
void noteSurface(PathResult* path, const Hit& hit, dvec3 p, bool crease) {
    mixKey(&path->region, uint64_t(int64_t(hit.object)));
    if (!hit.hit) return;
    mixKey(&path->region, crease);
    if (hit.object != kHitGround) return;
    mixKey(&path->region, uint64_t(squareIndex(p.x)));
    mixKey(&path->region, uint64_t(squareIndex(p.z)));
}

}  // namespace

// Each bounce keeps (1 - Kr) of its surface's own fogged colour and hands Kr on to the mirror
// ray; the last allowed bounce, or a surface with Kr = 0, keeps all of its colour.
PathResult tracePath(const Model& m, dvec3 origin, dvec3 dir) {
    PathResult out;
    out.region = 14695981039346656037ull;
    dvec3 weight(1.0), o = origin, d = dir;
    double travelled = 0.0;  // from the eye to o: the cone widens along the whole path
    int bounces = std::max(m.scene->render.reflections, 0);
    for (int bounce = 0; bounce <= bounces; ++bounce) {
        Hit hit = firstHit(m, o, d);
        if (bounce == 0) out.first = hit;
        if (!hit.hit) {
            noteSurface(&out, hit, o, false);
            out.color += weight * skyColor(m, d);
            break;
        }
        dvec3 p = o + d * hit.t;
        SurfaceNormal normal = normalAt(m, p, hit.object);
        dvec3 n = normal.n;
        SurfaceMaterial s =
            materialAt(m, p, hit.object, floorFootprint(d, m.sampleRadius * (travelled + hit.t)));
        noteSurface(&out, hit, p, normal.crease);
        dvec3 color = applyFog(m, shade(m, s, p, n, d, &out), d, hit.t);
        if (bounce == bounces || s.kr <= 0.0) {
            out.color += weight * color;
            break;
        }
        out.color += weight * (1.0 - s.kr) * color;
        weight *= s.kr;
        o = liftOff(p, n, m.epsilon);
        d = d - 2.0 * glm::dot(d, n) * n;
        travelled += hit.t;
    }
    return out;
}

}  // namespace mb::reference
