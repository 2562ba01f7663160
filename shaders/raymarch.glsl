// raymarch.glsl — sphere tracing, normals, shadows and occlusion over map().

float hitEpsilon(float t) {
#if CONE_EPSILON
    return max(uEpsilon, t * uPixelRadius);  // finer than a pixel cannot be seen
#else
    return uEpsilon;
#endif
}

// Where the ray meets the ground plane, exactly, as a converged march would: 0 when it starts
// under it, past any end if never.
float groundHit(vec3 ro, vec3 rd) {
#if HAS_GROUND
    float above = ro.y - uFloor;
    if (GROUND_ON && (above <= 0.0 || rd.y < 0.0)) return max(above, 0.0) / max(-rd.y, 1e-30);
#endif
    return 1e30;
}

// Within the box that holds every object's reach: only there is anything but the ground. A soft
// shadow grows it by 1/k, past which k·d/t > 1 changes nothing.
vec2 objectSpan(vec3 ro, vec3 rd, float far, float grow) {
    return grownBoxSpan(ro, rd, far, grow, uBoundLo, uBoundHi);
}

// Within the box of the marched objects: all but the plain members, which are met exactly.
vec2 restSpan(vec3 ro, vec3 rd, float far, float grow) {
    return grownBoxSpan(ro, rd, far, grow, uRestLo, uRestHi);
}

// Sphere tracing of the marched objects (mapRestAlong) over the span; x: t, y: object or HIT_NONE, z: steps.
// Past RELAX_PERCENT 100 it is over-relaxed (Keinert et al. 2014): steps of omega·d while
// consecutive unbounding spheres overlap; where they do not, it steps back and traces plainly.
// At 100 the relaxed branch is a constant false, so plain tracing compiles to steps of d alone.
vec3 marchObjects(vec3 ro, vec3 rd, vec2 span) {
    float t = span.x, omega = float(RELAX_PERCENT) / 100.0, stepLength = 0.0, prevRadius = 0.0;
    vec3 h = vec3(1e10, HIT_NONE, 1e10);
    int i = 0;
    for (; i < MAX_STEPS && t <= span.y; ++i) {
#if UBER
        if (i >= uSteps) break;
#endif
        h = mapRestAlong(ro + rd * t, rd);
        float radius = abs(h.x);
        if (RELAX_PERCENT > 100 && omega > 1.0 && radius + prevRadius < stepLength) {
            stepLength -= omega * stepLength;
            omega = 1.0;
        } else {
            // Inside a surface (the camera in an object) counts as a hit at once; a grid cell's
            // capped step (y = HIT_NONE) never does.
            if (h.x < hitEpsilon(t) && !missed(h.y)) return vec3(t, h.y, float(i + 1));
            stepLength = h.x * omega;
        }
        prevRadius = radius;
        t += stepLength;
    }
    // Out of steps still in the span: the ray is grazing the object it is nearest to.
    return vec3(t, t <= span.y ? h.y : HIT_NONE, float(i));
}

// x: distance along rd; y: object index, HIT_GROUND or HIT_NONE; z: steps taken. The ground and
// the plain members are met exactly, so no ray runs out of steps over open floor and shows sky at
// the horizon; the march of the rest ends at the nearest of them.
vec3 castRay(vec3 ro, vec3 rd) {
    float ground = groundHit(ro, rd);
    vec3 hit = vec3(min(ground, uMaxDist), HIT_NONE, 0.0);
#if PLAIN
    hit.xy = hitPlainMembers(ro, rd, hit.x, false);
#endif
#if HAS_REST
    vec3 marched = marchObjects(ro, rd, restSpan(ro, rd, hit.x, 0.0));
    if (!missed(marched.y)) return marched;
    hit.z = marched.z;
#endif
    if (!missed(hit.y)) return hit;
    return ground <= uMaxDist ? vec3(ground, HIT_GROUND, hit.z) : vec3(uMaxDist, HIT_NONE, hit.z);
}

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

// The normal of a plain member's surface, which is its own: from its SDF alone, in its frame.
// On the grid only: a compiled scene's field reads registers and costs less than this read.
#if PLAIN == 2
// The object is read once: a block read indexed per pixel costs more than its SDF.
vec3 objectNormal(int id, vec3 p) {
    Object o = uObjects[id];
    vec3 q = o.toLocal * (p - o.posBound.xyz);
    float h = normalStep(p);
    const vec2 k = vec2(1.0, -1.0);
    vec3 n = k.xyy * sdShape(o, q + k.xyy * h) + k.yyx * sdShape(o, q + k.yyx * h) +
             k.yxy * sdShape(o, q + k.yxy * h) + k.xxx * sdShape(o, q + k.xxx * h);
    float len = length(n);
    return len > 1e-20 ? (n * o.toLocal) / len : vec3(0.0, 1.0, 0.0);  // n·M is Mᵀ·n: to world
}
#endif

// The normal where a ray stopped on object id. The ground's is up and a plain member's its own;
// only a marched object's needs the scene's field, in a loop that llvmpipe leaves at once when
// no pixel of a SIMD group needs it (an if would run for all of them). A missed ray (the sky's
// lanes, run with the rest) needs none.
vec3 hitNormal(vec3 p, float id) {
    vec3 n = vec3(0.0, 1.0, 0.0);
    bool exact = id == HIT_GROUND || missed(id);
#if PLAIN == 2
    int member = max(int(id), 0);
    if (plainMember(int(id))) n = objectNormal(member, p), exact = true;
#endif
    for (bool field = !exact; field; field = false) n = calcNormal(p);
    return n;
}

#if SHADOWS == 1 || UBER
float hardShadow(vec3 ro, vec3 rd, float maxT) {
    if (groundHit(ro, rd) < maxT) return 0.0;  // a light under the floor
#if PLAIN
    if (!missed(hitPlainMembers(ro, rd, maxT, true).y)) return 0.0;
#endif
#if HAS_REST
    vec2 span = restSpan(ro, rd, maxT, 0.0);
    float t = span.x;
    for (int i = 0; i < SHADOW_STEPS && t <= span.y; ++i) {
        float h = mapRestAlong(ro + rd * t, rd).x;
        if (h < uEpsilon) return 0.0;
        t += h;
    }
#endif
    return 1.0;
}
#endif

#if SHADOWS == 2
// The marched objects' penumbra from the nearest miss, with the improved estimate that uses the
// previous step to place the closest approach between samples (Quilez 2018); the sqrt argument
// is clamped. The plain members' own, where taken apart (penumbra.glsl), joins by the least.
float softShadow(vec3 ro, vec3 rd, float maxT) {
    if (groundHit(ro, rd) < maxT) return 0.0;  // a light under the floor
    float k = uSoftness, res = 1.0;
#if HAS_GROUND
    // The floor's own penumbra under grazing light: its distance over t, (height + t·rd.y) / t,
    // falls all along the ray, so its least value is at the end.
    if (GROUND_ON) res = min(res, k * (ro.y - uFloor + maxT * rd.y) / maxT);
#endif
#if PLAIN
    res = min(res, k * plainClearance(ro, rd, maxT, k));
    if (res < 0.001) return 0.0;
#endif
#if PLAIN == 2
    vec2 span = restSpan(ro, rd, maxT, 1.0 / k);
#else
    vec2 span = objectSpan(ro, rd, maxT, 1.0 / k);
#endif
#if PLAIN != 2 || HAS_REST  // a grid of plain members alone: nothing to march
    float t = span.x, ph = 1e10;
    for (int i = 0; i < SHADOW_STEPS && t <= span.y; ++i) {
#if PLAIN == 1
        vec3 m = chainAlong(mapSoftRest(ro + rd * t));  // all but the plain balls
#else
        vec3 m = mapRestAlong(ro + rd * t, rd);  // the grid's: only inside the rest's box
#endif
        if (m.x < uEpsilon) return 0.0;
        float h = m.z;
        // A true distance's unbounding spheres overlap (h <= 2·ph); a grid cell's own distance
        // past an empty cell (1e10) need not, and there the plain estimate (y = 0) stands.
        float y = h < 2.0 * ph ? h * h / (2.0 * ph) : 0.0;
        float d = sqrt(max(h * h - y * y, 0.0));
        res = min(res, k * d / max(1e-6, t - y));
        if (res < 0.001) return 0.0;  // fully dark already: the rest of the ray cannot matter
        ph = h;
        t += m.x;
    }
#endif
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
