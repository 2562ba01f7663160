// march.frag — one full-screen pass: map -> castRay -> calcNormal -> shadow/AO -> shade -> main.
// The #version line, the feature #defines and the HIT_ ids come first (src/gl/shader_source.cpp).
#include "scene_data.glsl"
#include "sdf.glsl"
#include "scene_map.glsl"
#include "raymarch.glsl"
#include "lighting.glsl"
#include "outline.glsl"

out vec4 fragColor;

#if MODE == MODE_SHADED
// The colour where a ray stops, fogged by its distance; s, p and n feed the next bounce.
// travelled: the path's length from the eye to ro, which widens the sample's cone.
vec3 surfaceColor(vec3 ro, vec3 rd, vec3 hit, float travelled, out Surface s, out vec3 p, out vec3 n) {
    p = ro + rd * hit.x;
    n = hitNormal(p, hit.y);
    s = surfaceAt(p, int(hit.y), rd, uSampleRadius * (travelled + hit.x));
    return applyFog(shade(s, p, n, rd), rd, hit.x);
}

// hit: castRay(ro, rd), which main() made for the outline too.
#if REFLECTIONS == 0
vec3 render(vec3 ro, vec3 rd, vec3 hit) {
    if (missed(hit.y)) return sky(rd);
    Surface s;
    vec3 p, n;
    return surfaceColor(ro, rd, hit, 0.0, s, p, n);
}
#else
// Mirror bounces: each surface keeps (1 - Kr) of its own colour and passes Kr on. The cone
// spreads on along the whole path, as if every mirror were flat.
vec3 render(vec3 ro, vec3 rd, vec3 hit) {
    vec3 acc = vec3(0.0), weight = vec3(1.0);
    float travelled = 0.0;
    for (int bounce = 0; bounce <= REFLECTIONS; ++bounce) {
        if (bounce > 0) hit = castRay(ro, rd);
        if (missed(hit.y)) return acc + weight * sky(rd);
        Surface s;
        vec3 p, n;
        vec3 col = surfaceColor(ro, rd, hit, travelled, s, p, n);
        bool last = bounce == REFLECTIONS || s.kr <= 0.0;
#if UBER
        last = last || bounce >= uReflections;
#endif
        if (last) return acc + weight * col;
        acc += weight * (1.0 - s.kr) * col;
        weight *= s.kr;
        ro = p + n * 4.0 * normalStep(p);
        rd = reflect(rd, n);
        travelled += hit.x;
    }
    return acc;
}
#endif
#else
// Debug views of the primary hit.
vec3 render(vec3 ro, vec3 rd, vec3 hit) {
#if MODE == MODE_STEPS
    float heat = hit.z / float(MAX_STEPS);
    return clamp(vec3(3.0 * heat, 3.0 * heat - 1.0, 3.0 * heat - 2.0), 0.0, 1.0);
#elif MODE == MODE_ID
    float id = hit.y - HIT_NONE;  // 0 miss, 1 ground, 2+ objects; objectIdAt() reads it
    return vec3(mod(id, 256.0), floor(id / 256.0), 0.0) / 255.0;
#else
    if (missed(hit.y)) return vec3(0.0);
    vec3 p = ro + rd * hit.x;
    vec3 n = hitNormal(p, hit.y);
#if MODE == MODE_NORMALS
    return n * 0.5 + 0.5;
#elif MODE == MODE_DEPTH
    return vec3(1.0 - clamp(hit.x / uMaxDist, 0.0, 1.0));
#elif MODE == MODE_AO && HAS_AO
    return vec3(calcAO(p, n));
#elif MODE == MODE_SHADOW
    float sum = 0.0;
    for (int i = 0; i < POINT_LIGHTS; ++i) {
        vec3 toLight = uLights[i].vec.xyz - p;
        sum += shadow(p + n * 4.0 * normalStep(p), normalize(toLight), length(toLight));
    }
    for (int i = 0; i < DIR_LIGHTS; ++i)
        sum += shadow(p + n * 4.0 * normalStep(p), uLights[POINT_LIGHTS + i].vec.xyz, uMaxDist);
    return vec3(POINT_LIGHTS + DIR_LIGHTS > 0 ? sum / float(POINT_LIGHTS + DIR_LIGHTS) : 1.0);
#else
    return vec3(1.0);
#endif
#endif
}
#endif

vec3 cameraRay(vec2 pixel) {
    vec2 uv = (2.0 * pixel - uResolution) / uResolution.y;  // y in [-1, 1], x by aspect
    return normalize(uCamForward + uv.x * uCamRight + uv.y * uCamUp);
}

// The pixel this fragment shades. With CHECKERBOARD (draft) the target is half as wide and
// fragment (i, y) shades pixel (2i + (y & 1), y); checkerboard.frag fills in the others.
vec2 shadedPixel() {
    vec2 p = floor(gl_FragCoord.xy);
#if CHECKERBOARD
    p.x = 2.0 * p.x + mod(p.y, 2.0);
#endif
    return p;
}

// Supersampling runs as passes, one sample each, added up by blending: a loop here would
// multiply every march of the pixel inside one invocation.
void main() {
#if COMPILED
    loadObjects();
#endif
    vec3 rd = cameraRay(shadedPixel() + uSubpixel), hit = castRay(uCamPos, rd);
    vec3 col = render(uCamPos, rd, hit);
#if OUTLINE
    col = outlineSelection(col, uCamPos, rd, hit);
#endif
    fragColor = vec4(clamp(col, 0.0, 1.0), 1.0) * uSampleWeight;
}
