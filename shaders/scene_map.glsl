// scene_map.glsl — the scene's CSG chain in file order, then the ground. Twin of mapScene().

float sdObjectLocal(int i, vec3 q) {
    int type = uObjects[i].info.x;
#if HAS_SPHERE
    if (type == 0) return sdSphere(q, uObjects[i].shape.x);
#endif
#if HAS_BOX
    if (type == 1) return sdBox(q, uObjects[i].sizeMinor.xyz);
#endif
#if HAS_TORUS
    if (type == 2) return sdTorus(q, uObjects[i].shape.x, uObjects[i].sizeMinor.w);
#endif
#if HAS_CAPSULE
    if (type == 3) return sdCapsule(q, uObjects[i].shape.y, uObjects[i].shape.x);
#endif
#if HAS_CYLINDER
    if (type == 4) return sdCylinder(q, uObjects[i].shape.y, uObjects[i].shape.x);
#endif
    return 1e10;
}

// x: distance; y: index of the surface's object, -1 ground, -2 nothing.
vec2 mapObjects(vec3 p) {
    vec2 res = vec2(1e10, -2.0);
    for (int i = 0; i < OBJECT_COUNT; ++i) {
        int op = uObjects[i].info.y;
        float k = uObjects[i].shape.z;
        vec3 rel = p - uObjects[i].posBound.xyz;
        // dObj >= bound: union and subtract keep their value when the object is k beyond it.
        float bound = length(rel) - uObjects[i].posBound.w;
        if (op == 0 && bound >= res.x + k) continue;
#if HAS_SUBTRACT
        if (op == 1 && bound >= k - res.x) continue;
#endif
        float d = sdObjectLocal(i, uObjects[i].toLocal * rel);
        vec2 r = opUnion(res.x, d, k);
#if HAS_SUBTRACT
        if (op == 1) r = opSubtract(res.x, d, k);
#endif
#if HAS_INTERSECT
        if (op == 2) r = opIntersect(res.x, d, k);
#endif
        res = vec2(r.x, r.y > 0.5 ? float(i) : res.y);
    }
    return res;
}

vec2 map(vec3 p) {
    vec2 res = mapObjects(p);
#if HAS_GROUND
    if (GROUND_ON && p.y - uFloor < res.x) res = vec2(p.y - uFloor, -1.0);
#endif
    return res;
}
