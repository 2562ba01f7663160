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
