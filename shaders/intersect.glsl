// intersect.glsl — exact ray intersection with the scene's plain members: convex shapes joined
// by a sharp union that no other object's subtract, intersect or blend reaches, so the scene's
// surface there is the shape's own (src/gl/plain_members.cpp decides which they are).
//
// Each shape's span is the part of the ray inside the solid, (entry, exit), in the shape's frame
// with rd of unit length; kNoSpan when the ray misses. A hit is the entry, or 0 from inside: a
// march counts a start inside a surface as a hit at once, too.

const vec2 kNoSpan = vec2(1e30, -1e30);

// 1 / v with no infinity: a zero component becomes a huge one of either sign.
vec3 safeInverse(vec3 v) {
    return 1.0 / (vec3(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0, v.z >= 0.0 ? 1.0 : -1.0) *
                  max(abs(v), vec3(1e-20)));
}

// Where ro + t·rd is inside the box |p| <= b, by its three slabs.
vec2 boxSpan(vec3 ro, vec3 inv, vec3 b) {
    vec3 near = (-b - ro) * inv, far = (b - ro) * inv;
    vec3 lo = min(near, far), hi = max(near, far);
    return vec2(max(lo.x, max(lo.y, lo.z)), min(hi.x, min(hi.y, hi.z)));
}

// A ball of radius r at c. The square distance of its closest approach, from the projected
// point rather than b² - c, keeps its precision far from the ball.
vec2 ballSpan(vec3 ro, vec3 rd, vec3 c, float r) {
    vec3 oc = ro - c;
    float b = dot(oc, rd);
    vec3 q = oc - b * rd;
    float h = r * r - dot(q, q);
    if (h < 0.0) return kNoSpan;
    h = sqrt(h);
    return vec2(-b - h, -b + h);
}

// The part of the ray inside the slab lo <= y <= hi.
vec2 slabSpan(vec3 ro, vec3 rd, float lo, float hi) {
    float inv = 1.0 / (abs(rd.y) > 1e-20 ? rd.y : 1e-20);
    vec2 ends = vec2((lo - ro.y) * inv, (hi - ro.y) * inv);
    return vec2(min(ends.x, ends.y), max(ends.x, ends.y));
}

// The part of span inside s; empty (x > y) where they do not overlap.
vec2 meetSpans(vec2 span, vec2 s) { return vec2(max(span.x, s.x), min(span.y, s.y)); }

// The infinite cylinder x² + z² <= r², cut to |y| <= halfHeight: a capped cylinder.
vec2 cylinderSpan(vec3 ro, vec3 rd, float r, float halfHeight) {
    float a = dot(rd.xz, rd.xz), b = dot(ro.xz, rd.xz), c = dot(ro.xz, ro.xz) - r * r;
    vec2 side = vec2(-1e30, 1e30);  // a ray along the axis is inside all along or never
    if (a > 1e-12) {
        float h = b * b - a * c;
        side = h < 0.0 ? kNoSpan : (vec2(-b, -b) + vec2(-1.0, 1.0) * sqrt(h)) / a;
    } else if (c > 0.0) {
        side = kNoSpan;
    }
    return meetSpans(side, slabSpan(ro, rd, -halfHeight, halfHeight));
}

// A convex solid's span gives its hit: the entry, 0 from inside, -1 for a miss.
float spanHit(vec2 s) { return s.x > s.y || s.y < 0.0 ? -1.0 : max(s.x, 0.0); }

// The spans of two convex pieces of one convex solid join into one.
vec2 joinSpans(vec2 a, vec2 b) {
    if (a.x > a.y) return b;
    if (b.x > b.y) return a;
    return vec2(min(a.x, b.x), max(a.y, b.y));
}

#if HAS_SPHERE
// ballSpan at the origin, with selects for its branch: the commonest test, kept lean.
float hitSphere(vec3 ro, vec3 rd, float r) {
    float b = dot(ro, rd);
    vec3 q = ro - b * rd;
    float h = r * r - dot(q, q), s = sqrt(max(h, 0.0));
    return h < 0.0 || s - b < 0.0 ? -1.0 : max(-b - s, 0.0);
}
#endif

#if HAS_BOX
float hitBox(vec3 ro, vec3 rd, vec3 b) { return spanHit(boxSpan(ro, safeInverse(rd), b)); }
#endif

#if HAS_CYLINDER
float hitCylinder(vec3 ro, vec3 rd, float height, float r) {
    return spanHit(cylinderSpan(ro, rd, r, 0.5 * height));
}
#endif

#if HAS_CAPSULE
// The capsule is the union of its cylinder and the two balls at its ends.
float hitCapsule(vec3 ro, vec3 rd, float height, float r) {
    float h = 0.5 * height;
    vec2 s = joinSpans(cylinderSpan(ro, rd, r, h), ballSpan(ro, rd, vec3(0.0, h, 0.0), r));
    return spanHit(joinSpans(s, ballSpan(ro, rd, vec3(0.0, -h, 0.0), r)));
}
#endif

#if HAS_CONE
// The frustum, base r1 at y = -h/2 and top r2 at h/2. Inside its slab the radius R(y) = R0 + s·y
// is never negative, so there the solid is x² + z² <= R(y)²: a quadratic a·t² + 2b·t + c <= 0
// along the ray. With a < 0 it holds on two rays, one of them the cone's other nappe, which
// lies beyond the apex and outside the slab (at most its apex point is on the slab's edge).
vec2 coneSpan(vec3 ro, vec3 rd, float height, float r1, float r2) {
    float s = (r2 - r1) / height, Ro = 0.5 * (r1 + r2) + s * ro.y, Rd = s * rd.y;
    float a = dot(rd.xz, rd.xz) - Rd * Rd, b = dot(ro.xz, rd.xz) - Ro * Rd;
    float c = dot(ro.xz, ro.xz) - Ro * Ro, h = b * b - a * c;
    vec2 slab = slabSpan(ro, rd, -0.5 * height, 0.5 * height);
    if (abs(a) < 1e-12) {  // along a generator: 2b·t + c <= 0
        if (abs(b) < 1e-20) return c <= 0.0 ? slab : kNoSpan;
        float t = -0.5 * c / b;
        return meetSpans(slab, b > 0.0 ? vec2(-1e30, t) : vec2(t, 1e30));
    }
    if (h < 0.0) return a < 0.0 ? slab : kNoSpan;
    vec2 roots = (vec2(-b, -b) + vec2(-1.0, 1.0) * sqrt(h)) / a;
    if (a > 0.0) return meetSpans(slab, roots);
    vec2 before = meetSpans(slab, vec2(-1e30, roots.y)), after = meetSpans(slab, vec2(roots.x, 1e30));
    return before.y - before.x >= after.y - after.x ? before : after;
}

// Solved from the bounding sphere's entry, where the quadratic's terms are of the shape's size.
float hitCone(vec3 ro, vec3 rd, float height, float r1, float r2) {
    float start = spanHit(ballSpan(ro, rd, vec3(0.0), length(vec2(0.5 * height, r1))));
    if (start < 0.0) return -1.0;
    float t = spanHit(coneSpan(ro + start * rd, rd, height, r1, r2));
    return t < 0.0 ? -1.0 : start + t;
}
#endif

#if HAS_ELLIPSOID
// The unit ball in the frame scaled by 1/r, where the ray's direction d is no longer of unit
// length: |o + t·d| = 1 at t = -b ± sqrt((1 - |q|²) / d·d), q the point of closest approach.
float hitEllipsoid(vec3 ro, vec3 rd, vec3 r) {
    vec3 o = ro / r, d = rd / r;
    float dd = dot(d, d), b = dot(o, d) / dd;
    vec3 q = o - b * d;
    float h = 1.0 - dot(q, q);
    if (h < 0.0) return -1.0;
    h = sqrt(h / dd);
    return spanHit(vec2(-b - h, -b + h));
}
#endif

#if HAS_TORUS
// The largest real root of x³ + a·x² + b·x + c, from the depressed cubic u³ + P·u + Q.
float largestCubicRoot(float a, float b, float c) {
    float P = b - a * a / 3.0, Q = 2.0 * a * a * a / 27.0 - a * b / 3.0 + c;
    float D = 0.25 * Q * Q + P * P * P / 27.0, u;
    if (D > 0.0) {  // one real root (Cardano)
        float s = sqrt(D), A = -0.5 * Q + s, B = -0.5 * Q - s;
        u = sign(A) * pow(abs(A), 1.0 / 3.0) + sign(B) * pow(abs(B), 1.0 / 3.0);
    } else {  // three real roots: the largest of the trigonometric ones
        float m = sqrt(max(-P / 3.0, 0.0));
        float cosine = m > 0.0 ? clamp(-0.5 * Q / (m * m * m), -1.0, 1.0) : 0.0;
        u = 2.0 * m * cos(acos(cosine) / 3.0);
    }
    float x = u - a / 3.0;
    float f = ((x + a) * x + b) * x + c, df = (3.0 * x + 2.0 * a) * x + b;
    return abs(df) > 1e-20 ? x - f / df : x;  // one Newton step against rounding
}

// The least t = y − shift >= 0 over the roots y of y² + p·y + q, into best.
void leastQuadraticRoot(float p, float q, float shift, inout float best) {
    float h = 0.25 * p * p - q;
    if (h < 0.0) return;
    h = sqrt(h);
    float lo = -0.5 * p - h - shift, hi = -0.5 * p + h - shift;
    best = min(best, lo >= 0.0 ? lo : hi >= 0.0 ? hi : best);
}

// The ring of radius R in the x-z plane, tube radius r. |p|² + R² − r² squared equals 4R²(x² + z²)
// on the surface; with p = ro + t·rd that is a quartic in t. It is solved from the bounding
// sphere's entry with lengths over R + r, where its coefficients are of order one (Ferrari's
// method through the resolvent cubic), and its root polished by Newton on the scaled quartic.
float hitTorus(vec3 ro, vec3 rd, float R, float r) {
    if (sdTorus(ro, R, r) < 0.0) return 0.0;
    float scale = R + r, start = spanHit(ballSpan(ro, rd, vec3(0.0), scale));
    if (start < 0.0) return -1.0;
    vec3 o = (ro + start * rd) / scale;
    float R2 = (R / scale) * (R / scale), r2 = (r / scale) * (r / scale);
    float n = dot(o, rd), k = dot(o, o) + R2 - r2;
    // t⁴ + 4n·t³ + c2·t² + c1·t + c0
    float c2 = 4.0 * n * n + 2.0 * k - 4.0 * R2 * dot(rd.xz, rd.xz);
    float c1 = 4.0 * n * k - 8.0 * R2 * dot(o.xz, rd.xz);
    float c0 = k * k - 4.0 * R2 * dot(o.xz, o.xz);
    // t = y − n gives y⁴ + p·y² + q·y + s.
    float p = c2 - 6.0 * n * n, q = c1 - 2.0 * c2 * n + 8.0 * n * n * n;
    float s = c0 - c1 * n + c2 * n * n - 3.0 * n * n * n * n;
    float best = 1e30;
    // (y² + p/2 + m)² = 2m(y − q/4m)² for the resolvent's root m > 0.
    float m = largestCubicRoot(p, 0.25 * p * p - s, -0.125 * q * q);
    if (m > 1e-7) {
        float w = sqrt(2.0 * m), e = q / (2.0 * w);
        leastQuadraticRoot(-w, 0.5 * p + m + e, n, best);
        leastQuadraticRoot(w, 0.5 * p + m - e, n, best);
    } else {  // q ≈ 0: a quadratic in y²
        float h = 0.25 * p * p - s;
        if (h >= 0.0)
            for (int i = 0; i < 2; ++i) {
                float y2 = -0.5 * p + (i == 0 ? -1.0 : 1.0) * sqrt(h);
                if (y2 >= 0.0) {
                    float y = sqrt(y2);
                    best = min(best, -y - n >= 0.0 ? -y - n : y - n >= 0.0 ? y - n : best);
                }
            }
    }
    if (best >= 1e30) return -1.0;
    for (int i = 0; i < 2; ++i) {  // Newton on the quartic in t
        float t = best;
        float f = (((t + 4.0 * n) * t + c2) * t + c1) * t + c0;
        float df = ((4.0 * t + 12.0 * n) * t + 2.0 * c2) * t + c1;
        best = abs(df) > 1e-12 ? max(t - f / df, 0.0) : t;
    }
    return start + best * scale;
}
#endif

// Narrows span to where a·t >= b.
void clipSpan(inout vec2 span, float a, float b) {
    if (a > 0.0) span.x = max(span.x, b / a);
    else if (a < 0.0) span.y = min(span.y, b / a);
    else if (b > 0.0) span.y = -1.0;
}

// The part of the ray, up to `far`, inside the box lo..hi grown by grow·t at distance t. Empty
// (x > y) when it misses.
vec2 grownBoxSpan(vec3 ro, vec3 rd, float far, float grow, vec3 lo, vec3 hi) {
    vec2 span = vec2(0.0, far);
    if (OBJECT_COUNT == 0) return vec2(1.0, 0.0);
    for (int i = 0; i < 3; ++i) {  // lo - grow·t <= ro + t·rd <= hi + grow·t
        clipSpan(span, rd[i] + grow, lo[i] - ro[i]);
        clipSpan(span, grow - rd[i], ro[i] - hi[i]);
    }
    return span;
}

#if PLAIN
// Whether the ray meets the plain members' box before far.
bool plainBoxMet(vec3 ro, vec3 rd, float far) {
    vec3 c = 0.5 * (uPlainLo + uPlainHi);
    vec2 s = boxSpan(ro - c, safeInverse(rd), 0.5 * (uPlainHi - uPlainLo));
    return s.x <= s.y && s.y >= 0.0 && s.x <= far;
}

// Whether it comes within t/k of that box at some t before far: past that, k times any
// member's clearance is over 1 and changes nothing (penumbra.glsl).
bool plainBoxNear(vec3 ro, vec3 rd, float far, float k) {
    vec2 s = grownBoxSpan(ro, rd, far, 1.0 / k, uPlainLo, uPlainHi);
    return s.x <= s.y;
}
#endif

// The nearer of a hit so far (x: t, y: object) and object id's hit t (< 0: a miss).
vec2 nearerHit(vec2 best, float t, float id) { return t >= 0.0 && t < best.x ? vec2(t, id) : best; }

#if PLAIN == 2
// The plain members' own grid (src/scene/object_grid.cpp over them alone): each cell lists the
// members whose bounding spheres touch it, and uPlainShapes holds each object in three texels:
// (centre, radius), (0, 0, 0, type) and the quaternion that turns world into the object's frame.
// Its sizes are its record's in uObjects.
vec3 turnedByQuat(vec4 q, vec3 v) {
    vec3 u = cross(q.xyz, v) * 2.0;
    return v + q.w * u + cross(q.xyz, u);
}

bool plainMember(int id) { return id >= 0 && texelFetch(uPlainShapes, 3 * id + 1).w >= 0.0; }

// Object o's exact hit along the ray r + t·d in its frame: the per-type switch over the types
// with a hit in include/marchbox/scene/shapes.h, written with the scene (scene_compiler.cpp).
float hitShape(Object o, vec3 r, vec3 d);

// PLAIN_SPHERES_ONLY: of the types a plain member can be, the scene has spheres alone.
float hitPlainMember(int id, vec3 ro, vec3 rd) {
    vec4 a = texelFetch(uPlainShapes, 3 * id);
    vec3 o = ro - a.xyz;
#if PLAIN_SPHERES_ONLY
    return hitSphere(o, rd, a.w);  // one texel, nothing to turn
#else
#if HAS_SPHERE
    if (texelFetch(uPlainShapes, 3 * id + 1).w == 0.0) return hitSphere(o, rd, a.w);
#endif
    vec4 q = texelFetch(uPlainShapes, 3 * id + 2);
    return hitShape(uObjects[id], turnedByQuat(q, o), turnedByQuat(q, rd));
#endif
}

// A walk through the grid's cells in the ray's order (Amanatides & Woo 1987), up to `end`.
struct PlainWalk {
    ivec3 cell, stepDir;
    vec3 tNext, tDelta;  // where the ray crosses the next boundary on each axis; a cell's width
    float end;
};

// The walk over the ray up to far; false when that misses the grid.
bool startPlainWalk(vec3 ro, vec3 rd, float far, out PlainWalk w) {
    vec3 inv = safeInverse(rd), size = vec3(uPlainDims) * uPlainCell;
    vec2 span = boxSpan(ro - uPlainOrigin - 0.5 * size, inv, 0.5 * size);
    span = vec2(max(span.x, 0.0), min(span.y, far));
    vec3 enter = ro + rd * span.x - uPlainOrigin;
    w.cell = clamp(ivec3(floor(enter / uPlainCell)), ivec3(0), uPlainDims - 1);
    w.stepDir = ivec3(rd.x >= 0.0 ? 1 : -1, rd.y >= 0.0 ? 1 : -1, rd.z >= 0.0 ? 1 : -1);
    w.tDelta = abs(uPlainCell * inv);
    w.tNext = (uPlainOrigin + (vec3(w.cell) + step(0.0, rd)) * uPlainCell - ro) * inv;
    w.end = span.y;
    return span.x <= span.y;
}

// The most cells a walk can visit.
int plainWalkLimit() { return uPlainDims.x + uPlainDims.y + uPlainDims.z; }

// The current cell's members: uPlainItems from x up to y.
ivec2 plainCellItems(PlainWalk w) {
    int c = (w.cell.z * uPlainDims.y + w.cell.y) * uPlainDims.x + w.cell.x;
    return ivec2(texelFetch(uPlainCells, c).r, texelFetch(uPlainCells, c + 1).r);
}

float plainCellExit(PlainWalk w) { return min(w.tNext.x, min(w.tNext.y, w.tNext.z)); }

// Into the next cell; false past the walk's end or the grid.
bool stepPlainWalk(inout PlainWalk w) {
    float exit = plainCellExit(w);
    if (exit >= w.end) return false;
    // Every axis whose boundary comes first steps: at a corner, two at once.
    ivec3 move = ivec3(lessThanEqual(w.tNext, vec3(exit)));
    w.cell += move * w.stepDir;
    w.tNext += vec3(move) * w.tDelta;
    return all(greaterThanEqual(w.cell, ivec3(0))) && all(lessThan(w.cell, uPlainDims));
}

// Nearest plain hit before `far` (x: t, y: object; (far, HIT_NONE) if none). A hit beyond its
// cell's exit may yet be beaten in a later cell, so the walk ends only at a cell holding a hit.
// `anyHit` (shadows) ends it at the first hit at all.
vec2 hitPlainMembers(vec3 ro, vec3 rd, float far, bool anyHit) {
    vec2 best = vec2(far, HIT_NONE);
    PlainWalk w;
    if (!startPlainWalk(ro, rd, far, w)) return best;
    for (int i = 0; i < plainWalkLimit(); ++i) {
        ivec2 items = plainCellItems(w);
        for (int k = items.x; k < items.y; ++k) {
            int id = int(texelFetch(uPlainItems, k).r);
            best = nearerHit(best, hitPlainMember(id, ro, rd), float(id));
        }
        bool found = best.x <= plainCellExit(w) || (anyHit && !missed(best.y));
        if (found || !stepPlainWalk(w)) break;
    }
    return best;
}
#endif
