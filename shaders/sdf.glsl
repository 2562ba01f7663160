// sdf.glsl — signed distances at the origin and the CSG operators. Twin of src/scene/sdf.cpp.

#if HAS_SPHERE
float sdSphere(vec3 p, float r) { return length(p) - r; }  // exact
#endif

#if HAS_BOX
float sdBox(vec3 p, vec3 b) {  // exact
    vec3 q = abs(p) - b;
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}
#endif

#if HAS_TORUS
float sdTorus(vec3 p, float major, float minor) {  // exact; ring in the x-z plane
    vec2 q = vec2(length(p.xz) - major, p.y);
    return length(q) - minor;
}
#endif

#if HAS_CAPSULE
float sdCapsule(vec3 p, float height, float r) {  // exact; segment [-h/2, h/2] on y
    float h = 0.5 * height;
    p.y -= clamp(p.y, -h, h);
    return length(p) - r;
}
#endif

#if HAS_CYLINDER
float sdCylinder(vec3 p, float height, float r) {  // exact; capped, axis y
    vec2 d = abs(vec2(length(p.xz), p.y)) - vec2(r, 0.5 * height);
    return min(max(d.x, d.y), 0.0) + length(max(d, 0.0));
}
#endif

#if HAS_CONE
// exact; axis y, base radius r1 at y = -h/2, top radius r2 at +h/2. Quilez's capped cone: the
// distance to the trapezoid in the (radial, y) half-plane, signed by both caps and the slant.
float sdCone(vec3 p, float height, float r1, float r2) {
    float h = 0.5 * height;
    vec2 q = vec2(length(p.xz), p.y);
    vec2 k1 = vec2(r2, h), k2 = vec2(r2 - r1, 2.0 * h);
    vec2 ca = vec2(q.x - min(q.x, q.y < 0.0 ? r1 : r2), abs(q.y) - h);
    vec2 cb = q - k1 + k2 * clamp(dot(k1 - q, k2) / dot(k2, k2), 0.0, 1.0);
    float s = cb.x < 0.0 && ca.y < 0.0 ? -1.0 : 1.0;
    return s * sqrt(min(dot(ca, ca), dot(cb, cb)));
}
#endif

#if HAS_ELLIPSOID
// bound, exact on the surface; semi-axes r. Quilez's k0·(k0 − 1)/k1.
float sdEllipsoid(vec3 p, vec3 r) {
    float k0 = length(p / r), k1 = length(p / (r * r));
    return k1 > 0.0 ? k0 * (k0 - 1.0) / k1 : -min(r.x, min(r.y, r.z));
}
#endif

#if HAS_ROUND
// Rounded edges of radius e (inset() and sdObjectLocal in src/scene/sdf.cpp): the points within e
// of the same shape with every face moved in by e. Exact where the shape is.
#endif
#if HAS_ROUND && HAS_BOX
float sdRoundedBox(vec3 p, vec3 b, float e) { return sdBox(p, b - e) - e; }
#endif
#if HAS_ROUND && HAS_CYLINDER
float sdRoundedCylinder(vec3 p, float height, float r, float e) {
    return sdCylinder(p, height - 2.0 * e, r - e) - e;
}
#endif
#if HAS_ROUND && HAS_CONE
// The slant moves in by e across it, e·sqrt(1 + slope²) along the radius; where that passes a
// pointed top, the inset cone ends at its apex, lower down, and its centre drops by `lift`.
float sdRoundedCone(vec3 p, float height, float r1, float r2, float e) {
    float h = height - 2.0 * e;
    float slope = (r1 - r2) / (h + 2.0 * e), side = e * sqrt(1.0 + slope * slope);
    float base = r1 - slope * e - side, top = r2 + slope * e - side, lift = 0.0;
    if (top < 0.0) {
        float apex = h * base / (base - top);
        lift = 0.5 * (apex - h);
        h = apex;
    }
    return sdCone(p - vec3(0.0, lift, 0.0), h, base, max(top, 0.0)) - e;
}
#endif

#if HAS_SHELL
// bound; the wall between the surface and the surface moved t inward: max(d, −(d + t)).
float opShell(float d, float t) { return abs(d + 0.5 * t) - 0.5 * t; }
#endif

// x: combined distance; y: 1 where b's surface wins. Polynomial smooth minimum (Quilez):
// it equals min(a, b) wherever |a - b| >= k, so objects farther than k can be skipped.
vec2 opUnion(float a, float b, float k) {
    float w = b < a ? 1.0 : 0.0;
#if HAS_BLEND
    if (k > 0.0) {
        float h = max(k - abs(a - b), 0.0) / k;
        return vec2(min(a, b) - h * h * k * 0.25, w);
    }
#endif
    return vec2(min(a, b), w);
}

#if HAS_SUBTRACT
vec2 opSubtract(float a, float b, float k) {  // max(a, -b) = -min(-a, b)
    vec2 u = opUnion(-a, b, k);
    return vec2(-u.x, u.y);
}
#endif

#if HAS_INTERSECT
vec2 opIntersect(float a, float b, float k) {  // max(a, b) = -min(-a, -b)
    vec2 u = opUnion(-a, -b, k);
    return vec2(-u.x, u.y);
}
#endif

// Joins an object's distance d onto the chain res = (distance, surface's object): the object
// takes the surface where its side wins. k = 0 is the sharp operator.
vec2 joined(vec2 res, vec2 r, float id) { return vec2(r.x, r.y > 0.5 ? id : res.y); }
vec2 joinUnion(vec2 res, float d, float k, float id) { return joined(res, opUnion(res.x, d, k), id); }
#if HAS_SUBTRACT
vec2 joinSubtract(vec2 res, float d, float k, float id) { return joined(res, opSubtract(res.x, d, k), id); }
#endif
#if HAS_INTERSECT
vec2 joinIntersect(vec2 res, float d, float k, float id) { return joined(res, opIntersect(res.x, d, k), id); }
#endif
