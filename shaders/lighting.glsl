// lighting.glsl — Phong with point and directional lights, the floor, the sky and fog.

// The gradient leans towards the brightest light's colour; each directional light is a sun.
vec3 skyGradient(vec3 rd) {
    vec3 zenith = vec3(0.30, 0.50, 0.85), horizon = vec3(0.80, 0.86, 0.92) * mix(vec3(1.0), uSkyTint, 0.35);
    return rd.y >= 0.0 ? mix(horizon, zenith, sqrt(rd.y)) : mix(horizon, vec3(0.35, 0.33, 0.30), sqrt(-rd.y));
}

vec3 sunGlow(vec3 rd, float discWeight) {
    vec3 glow = vec3(0.0);
    for (int i = 0; i < DIR_LIGHTS; ++i) {
        Light L = uLights[POINT_LIGHTS + i];
        float c = max(dot(rd, L.vec.xyz), 0.0);
        glow += L.color.rgb * (discWeight * smoothstep(0.9995, 0.9997, c) + 0.25 * pow(c, 64.0));
    }
    return glow;
}

// Fog takes the colour of the horizon in the ray's direction, sun glow included.
vec3 fogColor(vec3 rd) {
    vec3 level = normalize(vec3(rd.x, 0.0, rd.z) + vec3(0.0, 1e-4, 0.0));
    return skyGradient(level) + sunGlow(rd, 0.0);
}

vec3 applyFog(vec3 col, vec3 rd, float t) {
#if HAS_FOG
    float f = exp(-(uFog * t) * (uFog * t));  // exp² fog
    return mix(fogColor(rd), col, f);
#else
    return col;
#endif
}

// The sky is fogged too, as if it hung at kSkyHeight: at the horizon it melts into the fog,
// so far ground and sky meet without a seam.
const float kSkyHeight = 200.0;

vec3 sky(vec3 rd) {
    vec3 col = skyGradient(rd) + sunGlow(rd, 4.0);
    return applyFog(col, rd, kSkyHeight / max(rd.y, 1e-3));
}

struct Surface {
    vec3 albedo;
    vec4 k;      // Ka, Kd, Ks, C
    float kr;    // mirror reflectivity
};

// The floor's 1 m checkers, light where floor(x) + floor(z) is even, are averaged over the
// square a sample covers on the floor (docs/shading-model.md §3), so that far squares blend to
// grey instead of aliasing. Along one axis the pattern is a ±1 wave of period 2, +1 on even
// squares; its integral is a triangle wave, so a box's mean is a difference of two of them.
vec2 waveIntegral(vec2 x) { return 1.0 - abs(1.0 - mod(x, 2.0)); }

// The dark share under a box of sides w about p: the light/dark sign is the product of the
// axes' waves, and over a box the mean of that product is the product of their means.
float darkShare(vec2 p, vec2 w) {
    p = mod(p, 2.0);  // nearer zero, so the difference below keeps its digits
    vec2 mean = (waveIntegral(p + 0.5 * w) - waveIntegral(p - 0.5 * w)) / w;
    return 0.5 - 0.5 * mean.x * mean.y;
}

// The box a sample's cone, radius r where it meets the floor, covers there: 2r across the ray,
// stretched by 1/|rd.y| along it.
vec2 floorFootprint(vec3 rd, float r) {
    vec2 along = dot(rd.xz, rd.xz) > 1e-12 ? normalize(rd.xz) : vec2(1.0, 0.0);
    vec2 across = vec2(-along.y, along.x);
    return max(2.0 * r * (abs(along) / max(abs(rd.y), 1e-4) + abs(across)), vec2(1e-4));
}

// cone: the sample's radius at p, uSampleRadius times the path's length from the eye.
Surface surfaceAt(vec3 p, int id, vec3 rd, float cone) {
    if (float(id) == HIT_GROUND) {
        float c = darkShare(p.xz, floorFootprint(rd, cone));
        return Surface(mix(vec3(0.80), vec3(0.35), c), vec4(0.1, 0.8, 0.1, 16.0), 0.0);
    }
    int m = uObjects[id].info.z;
    return Surface(uMaterials[m].color.rgb, uMaterials[m].coeffs, uMaterials[m].color.a);
}

// Light i's diffuse and specular share, shadowed if it casts. l points towards the light.
// The light loops unroll, so `casts` is a constant and a light that casts no shadow costs no
// shadow ray: llvmpipe would run a branch's code for the whole SIMD group anyway.
bool castsShadow(int i) { return ((uint(SHADOW_CASTERS) >> uint(i)) & 1u) != 0u; }

vec3 phong(Surface s, vec3 p, vec3 n, vec3 rd, vec3 l, vec3 color, float maxT, bool casts) {
    float diff = max(dot(n, l), 0.0);
    if (diff <= 0.0) return vec3(0.0);
    float spec = pow(max(dot(reflect(-l, n), -rd), 0.0), s.k.w);
    float sh = casts ? shadow(p + n * 4.0 * normalStep(p), l, maxT) : 1.0;
    return color * sh * (s.k.y * diff * s.albedo + s.k.z * spec);
}

// Occlusion dims the ambient term fully and direct light by half: ambient alone (Ka ~ 0.1)
// would leave contacts looking unoccluded, and full direct dimming would darken lit creases.
vec3 shade(Surface s, vec3 p, vec3 n, vec3 rd) {
    float ao = 1.0;
#if HAS_AO
#if UBER
    if (uAo)
#endif
    ao = calcAO(p, n);
#endif
    vec3 direct = vec3(0.0);
    for (int i = 0; i < POINT_LIGHTS; ++i) {
        vec3 toLight = uLights[i].vec.xyz - p;
        float dist = length(toLight);
        direct += phong(s, p, n, rd, toLight / max(dist, 1e-6), uLights[i].color.rgb, dist, castsShadow(i));
    }
    for (int i = 0; i < DIR_LIGHTS; ++i) {
        Light L = uLights[POINT_LIGHTS + i];
        direct += phong(s, p, n, rd, L.vec.xyz, L.color.rgb, uMaxDist, castsShadow(POINT_LIGHTS + i));
    }
    return s.k.x * s.albedo * ao + direct * (0.5 + 0.5 * ao);
}
