// penumbra.glsl — soft shadows from the plain members without a march. A soft shadow is
// k · min over t of f(ro + t·rd) / t (Quilez). For a union, f is the least of the members' own
// distances, so the minimum is the least of each member's own minimum, and a member's can be
// taken apart: a ball's in closed form; on the grid, another shape's by a short search. The
// rest of the scene is marched (raymarch.glsl's softShadow).
//
// A member's clearance is its least f/t over 0 < t <= far: the sine of the angle between rd
// and the member's silhouette seen from ro; negative when the ray meets it.

#if SHADOWS == 2 && PLAIN

// A ball of radius r at the origin, exactly. With u = 1/t, f/t is g(u) = sqrt(c·u² + 2b·u + 1)
// − r·u (c = |ro|², b = ro·rd), convex in u and least where (c·u + b)² = r²(c·u² + 2b·u + 1):
// u* = (r·sqrt(q/e) − b) / c, q the square distance of the closest approach and e = c − r² the
// square tangent from ro; there g = sin(θ − α), θ the angle to the centre, α the ball's half
// angle. A light nearer than 1/u* bounds u from below.
float sphereClearance(vec3 ro, vec3 rd, float r, float far) {
    float c = dot(ro, ro), b = dot(ro, rd), e = c - r * r;
    if (e <= 0.0) return -1.0;  // ro inside the ball
    vec3 nearest = ro - b * rd;
    float u = max((r * sqrt(dot(nearest, nearest) / e) - b) / c, 1.0 / far);
    return sqrt(max((c * u + 2.0 * b) * u + 1.0, 0.0)) - r * u;
}

#if PLAIN == 2
float sdShape(Object o, vec3 q);  // the per-type switch, written with the scene (scene_map.glsl)

// Golden-section steps of the search below. Against the CPU reference's converged minimum
// (test_reference.cpp, shadows_soft's plate) the largest penumbra difference was 51/255 at 4
// steps, 12.7 at 6, 1.2 at 8 and 0.5, rounding alone, from 9 on.
const int kClearanceSteps = 10;

// Another shape, by golden-section search for its least f/t. For a convex shape u·f(ro + rd/u)
// is convex in u = 1/t (the perspective of a convex function), so f/t has one minimum in t, and
// a ray through the shape finds it below 0. Where a penumbra shows (an angle under 1/k) that
// minimum lies within ±R of the bounding sphere's projection on the ray, widened by the slant
// 1/cos² (2% at most). A torus is not convex: its search is an estimate. The bounding sphere's
// own clearance is a floor on the shape's, so where k times it is 1 or more nothing is searched.
float shapeClearance(Object o, vec3 ro, vec3 rd, float far, float k) {
    float least = sphereClearance(ro - o.posBound.xyz, rd, o.posBound.w, far);
    // A loop, not an if: llvmpipe leaves it at once when no ray of a SIMD group comes near.
    for (bool near = k * least < 1.0; near; near = false) {
        float tc = dot(o.posBound.xyz - ro, rd), radius = o.posBound.w;
        float lo = max(tc - radius, 1e-4), hi = min((tc + radius) * 1.02, far);
        if (lo >= hi) break;  // behind ro or past the light
        vec3 q = o.toLocal * (ro - o.posBound.xyz), d = o.toLocal * rd;
        const float kGolden = 0.618034;
        float t1 = hi - kGolden * (hi - lo), t2 = lo + kGolden * (hi - lo);
        float f1 = sdShape(o, q + t1 * d) / t1, f2 = sdShape(o, q + t2 * d) / t2;
        for (int i = 0; i < kClearanceSteps; ++i) {
            if (f1 < f2) {  // the minimum is in lo..t2
                hi = t2, t2 = t1, f2 = f1;
                t1 = hi - kGolden * (hi - lo);
                f1 = sdShape(o, q + t1 * d) / t1;
            } else {
                lo = t1, t1 = t2, f1 = f2;
                t2 = lo + kGolden * (hi - lo);
                f2 = sdShape(o, q + t2 * d) / t2;
            }
        }
        least = min(f1, f2);
    }
    return least;
}

// Member id's clearance: a ball's from its texel, another shape's from its record.
float memberClearance(int id, vec3 ro, vec3 rd, float far, float k) {
    vec4 a = texelFetch(uPlainShapes, 3 * id);
#if PLAIN_SPHERES_ONLY
    return sphereClearance(ro - a.xyz, rd, a.w, far);  // spheres alone: one texel
#else
#if HAS_SPHERE
    if (texelFetch(uPlainShapes, 3 * id + 1).w == 0.0)
        return sphereClearance(ro - a.xyz, rd, a.w, far);
#endif
    return shapeClearance(uObjects[id], ro, rd, far, k);
#endif
}

// The least clearance of the members listed in the cells the ray crosses up to far: those
// whose bounding spheres touch the ray's cells, as the grid's march saw them. It ends once the
// shadow is full: k times the clearance under 0.001.
float plainClearance(vec3 ro, vec3 rd, float far, float k) {
    float least = 1e10;
    PlainWalk w;
    if (!startPlainWalk(ro, rd, far, w)) return least;
    for (int i = 0; i < plainWalkLimit(); ++i) {
        ivec2 items = plainCellItems(w);
        for (int j = items.x; j < items.y; ++j)
            least = min(least, memberClearance(int(texelFetch(uPlainItems, j).r), ro, rd, far, k));
        if (k * least < 0.001 || !stepPlainWalk(w)) break;
    }
    return least;
}
#endif
#endif
