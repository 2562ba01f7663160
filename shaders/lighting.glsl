// lighting.glsl — Phong with point and directional lights, the floor, the sky and fog.

vec3 sky(vec3 rd) {
    vec3 zenith = vec3(0.30, 0.50, 0.85), horizon = vec3(0.80, 0.86, 0.92);
    return rd.y >= 0.0 ? mix(horizon, zenith, sqrt(rd.y)) : mix(horizon, vec3(0.35, 0.33, 0.30), sqrt(-rd.y));
}

vec3 applyFog(vec3 col, float t) {
#if HAS_FOG
    float f = exp(-(uFog * t) * (uFog * t));  // exp² fog
    return mix(sky(vec3(0.0)), col, f);
#else
    return col;
#endif
}

struct Surface {
    vec3 albedo;
    vec4 k;      // Ka, Kd, Ks, C
    float kr;    // mirror reflectivity
};

uniform int uHighlight;  // the editor's selected object + 1; 0, the default, highlights nothing

Surface surfaceAt(vec3 p, int id) {
    if (id < 0) {  // the ground: 1 m checkers aligned to x and z
        float c = mod(floor(p.x) + floor(p.z), 2.0);
        return Surface(mix(vec3(0.80), vec3(0.35), c), vec4(0.1, 0.8, 0.1, 16.0), 0.0);
    }
    int m = uObjects[id].info.z;
    Surface s = Surface(uMaterials[m].color.rgb, uMaterials[m].coeffs, uMaterials[m].color.a);
    if (id == uHighlight - 1) s.albedo = mix(s.albedo, vec3(1.0, 0.6, 0.1), 0.6);  // selection tint
    return s;
}

// One light's diffuse and specular share, shadowed. l points towards the light.
vec3 phong(Surface s, vec3 p, vec3 n, vec3 rd, vec3 l, vec3 color, float maxT) {
    float diff = max(dot(n, l), 0.0);
    if (diff <= 0.0) return vec3(0.0);
    float spec = pow(max(dot(reflect(-l, n), -rd), 0.0), s.k.w);
    float sh = shadow(p + n * 4.0 * normalStep(p), l, maxT);
    return color * sh * (s.k.y * diff * s.albedo + s.k.z * spec);
}

vec3 shade(Surface s, vec3 p, vec3 n, vec3 rd) {
    vec3 col = s.k.x * s.albedo;
#if HAS_AO
#if UBER
    if (uAo)
#endif
    col *= calcAO(p, n);
#endif
    for (int i = 0; i < POINT_LIGHTS; ++i) {
        vec3 toLight = uLights[i].vec.xyz - p;
        float dist = length(toLight);
        col += phong(s, p, n, rd, toLight / max(dist, 1e-6), uLights[i].color.rgb, dist);
    }
    for (int i = 0; i < DIR_LIGHTS; ++i) {
        Light L = uLights[POINT_LIGHTS + i];
        col += phong(s, p, n, rd, L.vec.xyz, L.color.rgb, uMaxDist);
    }
    return col;
}
