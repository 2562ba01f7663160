// raymarch.glsl — sphere tracing, normals, shadows and occlusion over map().

float hitEpsilon(float t) {
#if CONE_EPSILON
    return max(uEpsilon, t * uPixelRadius);  // finer than a pixel cannot be seen
#else
    return uEpsilon;
#endif
}

// x: distance along rd; y: object index (-1 ground, -2 miss); z: steps taken.
#if RELAX_PERCENT > 100
// Over-relaxed sphere tracing (Keinert et al. 2014): steps of omega·d while consecutive
// unbounding spheres overlap; where they do not, step back and fall to plain tracing.
vec3 castRay(vec3 ro, vec3 rd) {
    float t = 0.0, omega = float(RELAX_PERCENT) / 100.0, stepLength = 0.0, prevRadius = 0.0;
    for (int i = 0; i < MAX_STEPS; ++i) {
#if UBER
        if (i >= uSteps) break;
#endif
        vec3 h = mapAlong(ro + rd * t, rd);
        float radius = abs(h.x);
        bool fail = omega > 1.0 && radius + prevRadius < stepLength;
        if (fail) {
            stepLength -= omega * stepLength;
            omega = 1.0;
        } else {
            if (h.x < hitEpsilon(t) && h.y > -1.5) return vec3(t, h.y, float(i + 1));
            stepLength = h.x * omega;
        }
        prevRadius = radius;
        t += stepLength;
        if (t > uMaxDist) return vec3(t, -2.0, float(i + 1));
    }
    return vec3(t, -2.0, float(MAX_STEPS));
}
#else
vec3 castRay(vec3 ro, vec3 rd) {
    float t = 0.0;
    for (int i = 0; i < MAX_STEPS; ++i) {
#if UBER
        if (i >= uSteps) break;
#endif
        vec3 h = mapAlong(ro + rd * t, rd);
        // Inside a surface (the camera in an object) counts as a hit at once; a grid cell's
        // capped step (y = -2) never does.
        if (h.x < hitEpsilon(t) && h.y > -1.5) return vec3(t, h.y, float(i + 1));
        t += h.x;
        if (t > uMaxDist) return vec3(t, -2.0, float(i + 1));
    }
    return vec3(t, -2.0, float(MAX_STEPS));
}
#endif

// Differences far from the origin must span several float ulps of p to stay smooth.
float normalStep(vec3 p) { return max(0.5 * uEpsilon, 1e-5 * length(p)); }

vec3 calcNormal(vec3 p) {  // tetrahedron of four samples (Quilez)
    float h = normalStep(p);
    const vec2 k = vec2(1.0, -1.0);
    vec3 n = k.xyy * map(p + k.xyy * h).x + k.yyx * map(p + k.yyx * h).x +
             k.yxy * map(p + k.yxy * h).x + k.xxx * map(p + k.xxx * h).x;
    float len = length(n);
    return len > 1e-20 ? n / len : vec3(0.0, 1.0, 0.0);  // flat field (deep inside): no NaN
}

#if SHADOWS == 1 || UBER
float hardShadow(vec3 ro, vec3 rd, float maxT) {
    float t = 0.0;
    for (int i = 0; i < SHADOW_STEPS; ++i) {
        float h = mapAlong(ro + rd * t, rd).x;
        if (h < uEpsilon) return 0.0;
        t += h;
        if (t > maxT) break;
    }
    return 1.0;
}
#endif

#if SHADOWS == 2
// Penumbra from the nearest miss, with the improved estimate that uses the previous step to
// place the closest approach between samples (Quilez 2018); the sqrt argument is clamped.
float softShadow(vec3 ro, vec3 rd, float maxT) {
    float k = uSoftness;
    float res = 1.0, t = 0.0, ph = 1e10;
    for (int i = 0; i < SHADOW_STEPS; ++i) {
        vec3 m = mapAlong(ro + rd * t, rd);
        if (m.x < uEpsilon) return 0.0;
        float h = m.z;
        float y = h * h / (2.0 * ph);
        float d = sqrt(max(h * h - y * y, 0.0));
        res = min(res, k * d / max(1e-6, t - y));
        if (res < 0.001) return 0.0;  // fully dark already: the rest of the ray cannot matter
        ph = h;
        t += m.x;
        if (t > maxT) break;
    }
    res = clamp(res, 0.0, 1.0);
    return res * res * (3.0 - 2.0 * res);
}
#endif

float shadow(vec3 ro, vec3 rd, float maxT) {
#if UBER
    if (uShadows == 1) return hardShadow(ro, rd, maxT);
    if (uShadows == 2) return softShadow(ro, rd, maxT);
    return 1.0;
#elif SHADOWS == 1
    return hardShadow(ro, rd, maxT);
#elif SHADOWS == 2
    return softShadow(ro, rd, maxT);
#else
    return 1.0;
#endif
}

#if HAS_AO
float calcAO(vec3 p, vec3 n) {  // five samples along the normal (Quilez)
    float occ = 0.0, sca = 1.0;
    for (int i = 0; i < 5; ++i) {
        float h = 0.01 + 0.12 * float(i) / 4.0;
        occ += (h - map(p + h * n).x) * sca;
        sca *= 0.95;
    }
    return clamp(1.0 - 3.0 * occ, 0.0, 1.0);
}
#endif
