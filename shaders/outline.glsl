// outline.glsl — the editor's selection: an orange ring just outside the selected object's
// silhouette. The object's own pixels keep their shading, so its colour reads true.

uniform int uHighlight;  // the editor's selected object + 1; 0, the default, outlines nothing

const vec3 kOutlineColor = vec3(1.0, 0.6, 0.1);
const float kOutlinePixels = 2.0;  // the ring's width
const int kOutlineSteps = 64;      // a grazing ray creeps: its steps shrink to the ring's width

// Whether the ray passes within kOutlinePixels pixels of object i before tEnd without entering
// it. A pixel spans 2·uPixelRadius·t at distance t, so the test is d < ring·t with ring the
// ring's width per metre; the march starts where the ray meets the object's bounding sphere
// grown by the ring there. Entering counts as no ring: a ray through a carving (subtract)
// object, which the scene does not show there, must not fill its shape with orange.
bool passesNear(int i, vec3 ro, vec3 rd, float tEnd) {
    vec3 centre = uObjects[i].posBound.xyz, toCentre = centre - ro;
    float ring = 2.0 * uPixelRadius * kOutlinePixels;
    float reach = uObjects[i].posBound.w * (1.0 + ring) + ring * length(toCentre);
    float b = dot(toCentre, rd), h = reach * reach - (dot(toCentre, toCentre) - b * b);
    if (h < 0.0) return false;
    float t = max(b - sqrt(h), 0.0), t1 = min(b + sqrt(h), tEnd);
    bool near = false;
    for (int k = 0; k < kOutlineSteps && t <= t1; ++k) {
        float d = sdObjectLocal(i, uObjects[i].toLocal * (ro + rd * t - centre));
        if (d < uEpsilon) return false;
        near = near || d < ring * t;
        t += d;
    }
    return near;
}

// The primary ray's colour with the ring painted over it; hit is castRay's for that ray.
vec3 outlineSelection(vec3 col, vec3 ro, vec3 rd, vec3 hit) {
    int selected = uHighlight - 1;
    if (selected < 0 || selected >= OBJECT_COUNT || int(hit.y) == selected) return col;
    return passesNear(selected, ro, rd, hit.x) ? kOutlineColor : col;
}
