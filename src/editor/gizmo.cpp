// gizmo.cpp — the view's move, turn and size handles: projection, hit testing and drags.
#include "marchbox/editor/gizmo.h"

#include "marchbox/scene/camera.h"
#include "marchbox/scene/sdf.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

namespace mb {

const char* gizmoModeName(GizmoMode m) {
    static const char* names[kGizmoModeCount] = {"move", "rotate", "scale"};
    return names[int(m)];
}

//-----------------------------------------------------------------------------
// [SECTION] Projection
//-----------------------------------------------------------------------------
bool projectToPixel(const Camera& c, glm::vec3 p, glm::vec2 viewSize, glm::vec2* pixel) {
    // cameraRay() walks forward + u·right + v·up; the three are orthogonal, so u and v are the
    // offsets along right and up divided by the depth along forward.
    const CameraBasis b = cameraBasis(c);
    const glm::vec3 d = p - b.pos;
    const float along = glm::dot(d, b.forward);
    if (along <= 1e-6f || viewSize.y <= 0.0f) return false;
    const glm::vec2 uv(glm::dot(d, b.right) / glm::dot(b.right, b.right),
                       glm::dot(d, b.up) / glm::dot(b.up, b.up));
    *pixel = (uv / along * viewSize.y + viewSize) * 0.5f;  // cameraRay's uv, solved for pixel
    return true;
}

float metresPerPixel(const Camera& c, glm::vec3 p, float viewHeight) {
    // The view's height spans 2·tan(fov/2) metres at one metre's depth.
    const CameraBasis b = cameraBasis(c);
    const float along = std::max(glm::dot(p - b.pos, b.forward), 1e-4f);
    return 2.0f * glm::length(b.up) * along / std::max(viewHeight, 1.0f);
}

//-----------------------------------------------------------------------------
// [SECTION] Handles
//-----------------------------------------------------------------------------
GizmoFrame gizmoFrame(const Camera& c, glm::vec3 centre, const glm::mat3& axes, glm::vec2 viewSize,
                      const GizmoSettings& k) {
    return {centre, axes, k.lengthPixels * metresPerPixel(c, centre, viewSize.y)};
}

glm::vec3 ringPoint(const GizmoFrame& f, int axis, float angle) {
    const glm::vec3 u = f.axes[(axis + 1) % 3], v = f.axes[(axis + 2) % 3];
    return f.centre + f.length * (std::cos(angle) * u + std::sin(angle) * v);
}

static float distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    const glm::vec2 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::distance(p, a + t * ab);
}

// Inside the convex quad q[0..3], in either winding.
static bool insideQuad(glm::vec2 p, const glm::vec2 q[4]) {
    int pos = 0, neg = 0;
    for (int i = 0; i < 4; ++i) {
        const glm::vec2 e = q[(i + 1) % 4] - q[i], r = p - q[i];
        const float cross = e.x * r.y - e.y * r.x;
        pos += cross > 0.0f;
        neg += cross < 0.0f;
    }
    return pos == 0 || neg == 0;
}

// The screen distance from `pixel` to the polyline through world points pts[0..n).
template <typename Point>
static float distanceToPath(const Camera& c, glm::vec2 viewSize, glm::vec2 pixel, int n,
                            Point point) {
    float best = INFINITY;
    glm::vec2 prev, next;
    bool have = projectToPixel(c, point(0), viewSize, &prev);
    for (int i = 1; i < n; ++i) {
        const bool ok = projectToPixel(c, point(i), viewSize, &next);
        if (have && ok) best = std::min(best, distanceToSegment(pixel, prev, next));
        prev = next;
        have = ok;
    }
    return best;
}

static bool onPlaneSquare(const Camera& c, const GizmoFrame& f, int axis, glm::vec2 pixel,
                          glm::vec2 viewSize, const GizmoSettings& k) {
    const glm::vec3 u = f.axes[(axis + 1) % 3] * f.length, v = f.axes[(axis + 2) % 3] * f.length;
    const float a = k.planeFrom, b = k.planeTo;
    const glm::vec3 corners[4] = {a * u + a * v, b * u + a * v, b * u + b * v, a * u + b * v};
    glm::vec2 quad[4];
    for (int i = 0; i < 4; ++i)
        if (!projectToPixel(c, f.centre + corners[i], viewSize, &quad[i])) return false;
    return insideQuad(pixel, quad);
}

bool handleShown(const Camera& c, const GizmoFrame& f, GizmoHandle h, const GizmoSettings& k) {
    const glm::vec3 view = glm::normalize(f.centre - c.pos);
    const float cosine = std::abs(glm::dot(view, f.axes[h.axis]));
    switch (h.kind) {
        case HandleKind::Axis:
        case HandleKind::Scale:
            return cosine <= k.endOnAxis;
        case HandleKind::Plane:
            return cosine >= k.edgeOnPlane;
        case HandleKind::Ring:
            return true;
        case HandleKind::None:
            break;
    }
    return false;
}

GizmoHandle hitGizmo(const Camera& c, const GizmoFrame& f, GizmoMode mode, glm::vec2 pixel,
                     glm::vec2 viewSize, const GizmoSettings& k) {
    if (mode == GizmoMode::Move)
        for (int i = 0; i < 3; ++i)
            if (handleShown(c, f, {HandleKind::Plane, i}, k) &&
                onPlaneSquare(c, f, i, pixel, viewSize, k))
                return {HandleKind::Plane, i};
    const HandleKind kind = mode == GizmoMode::Rotate  ? HandleKind::Ring
                            : mode == GizmoMode::Scale ? HandleKind::Scale
                                                       : HandleKind::Axis;
    GizmoHandle best;
    float nearest = k.pickPixels;
    for (int i = 0; i < 3; ++i) {
        if (!handleShown(c, f, {kind, i}, k)) continue;
        float d;
        if (mode == GizmoMode::Rotate) {
            const int n = 65;  // 64 segments: within a pixel of the circle at lengthPixels
            d = distanceToPath(c, viewSize, pixel, n, [&](int j) {
                return ringPoint(f, i, glm::two_pi<float>() * float(j) / float(n - 1));
            });
        } else {
            const glm::vec3 a = f.axes[i] * f.length;
            d = distanceToPath(c, viewSize, pixel, 2,
                               [&](int j) { return f.centre + (j == 0 ? k.axisFrom : 1.0f) * a; });
        }
        if (d <= nearest) {
            nearest = d;
            best = {kind, i};
        }
    }
    return best;
}

//-----------------------------------------------------------------------------
// [SECTION] Drags
//-----------------------------------------------------------------------------
bool closestOnLine(glm::vec3 p, glm::vec3 a, glm::vec3 o, glm::vec3 d, float* t) {
    // Minimising |w + t·a − s·d|² with w = p − o, a and d unit: the two derivatives give
    // a·w + t − s·b = 0 and d·w + t·b − s = 0, with b = a·d; so t = (b·(d·w) − a·w) / (1 − b²).
    const glm::vec3 w = p - o;
    const float b = glm::dot(a, d), denom = 1.0f - b * b;
    if (denom < 1e-6f) return false;
    *t = (b * glm::dot(d, w) - glm::dot(a, w)) / denom;
    return true;
}

bool rayOnPlane(glm::vec3 p, glm::vec3 n, glm::vec3 o, glm::vec3 d, glm::vec3* hit) {
    const float dn = glm::dot(d, n);
    if (std::abs(dn) < 1e-6f) return false;
    const float s = glm::dot(p - o, n) / dn;
    if (s <= 0.0f) return false;
    *hit = o + s * d;
    return true;
}

float snapTo(float v, float step) { return step > 0.0f ? std::round(v / step) * step : v; }

static glm::vec3 mouseRay(const Camera& c, glm::vec2 pixel, glm::vec2 viewSize) {
    return cameraRay(cameraBasis(c), pixel, viewSize);
}

// The mouse's angle about the frame's centre on screen, counter-clockwise.
static bool screenAngle(const Camera& c, const GizmoFrame& f, glm::vec2 pixel, glm::vec2 viewSize,
                        float* angle) {
    glm::vec2 centre;
    if (!projectToPixel(c, f.centre, viewSize, &centre) || pixel == centre) return false;
    *angle = std::atan2(pixel.y - centre.y, pixel.x - centre.x);
    return true;
}

bool GizmoDrag::begin(const Camera& c, const GizmoFrame& f, GizmoHandle h, glm::vec2 pixel,
                      glm::vec2 viewSize) {
    handle = h;
    frame = f;
    const glm::vec3 a = f.axes[h.axis], d = mouseRay(c, pixel, viewSize);
    switch (h.kind) {
        case HandleKind::Axis:
        case HandleKind::Scale:
            if (!closestOnLine(f.centre, a, c.pos, d, &grabT)) return false;
            grabbed = f.centre + grabT * a;
            return std::abs(grabT) > 1e-3f * f.length;  // sizing divides by it
        case HandleKind::Plane:
            return rayOnPlane(f.centre, a, c.pos, d, &grabbed);
        case HandleKind::Ring:
            // Seen from the side its axis points to, a positive turn runs counter-clockwise.
            sign = glm::dot(a, c.pos - f.centre) >= 0.0f ? 1.0f : -1.0f;
            return screenAngle(c, f, pixel, viewSize, &grabAngle);
        case HandleKind::None:
            break;
    }
    return false;
}

bool GizmoDrag::follow(const Camera& c, glm::vec2 pixel, glm::vec2 viewSize, bool snap,
                       GizmoDelta* out, const GizmoSettings& k) const {
    const int i = handle.axis;
    const glm::vec3 a = frame.axes[i], d = mouseRay(c, pixel, viewSize);
    const float metres = snap ? k.snapMetres : 0.0f;
    GizmoDelta r;
    float t, angle;
    glm::vec3 hit;
    switch (handle.kind) {
        case HandleKind::Axis:
            if (!closestOnLine(frame.centre, a, c.pos, d, &t)) return false;
            r.move = a * snapTo(t - grabT, metres);
            break;
        case HandleKind::Scale:  // on the object's own axis i: the frame was built from them
            if (!closestOnLine(frame.centre, a, c.pos, d, &t)) return false;
            r.scaleAxis = i;
            r.scale = std::max(snapTo(t / grabT, snap ? k.snapFactor : 0.0f), 0.0f);
            break;
        case HandleKind::Plane: {
            if (!rayOnPlane(frame.centre, a, c.pos, d, &hit)) return false;
            const glm::vec3 u = frame.axes[(i + 1) % 3], v = frame.axes[(i + 2) % 3];
            r.move = u * snapTo(glm::dot(hit - grabbed, u), metres) +
                     v * snapTo(glm::dot(hit - grabbed, v), metres);
            break;
        }
        case HandleKind::Ring:
            if (!screenAngle(c, frame, pixel, viewSize, &angle)) return false;
            // Wrapped to one turn either way: a turn by θ and by θ − 2π are the same turn.
            angle = std::remainder(sign * (angle - grabAngle), glm::two_pi<float>());
            r.turn = glm::angleAxis(snapTo(angle, snap ? k.snapRadians : 0.0f), a);
            break;
        case HandleKind::None:
            return false;
    }
    *out = r;
    return true;
}

// The length a drag along the object's own axis `axis` sizes, for each shape.
static float* sizedLength(Object& o, int axis) {
    switch (o.type) {
        case ShapeType::Sphere:
            return &o.radius;
        case ShapeType::Box:
            return &o.size[axis];
        case ShapeType::Torus:  // the ring lies in local xz; y is across the tube
            return axis == 1 ? &o.minor : &o.radius;
        case ShapeType::Capsule:
        case ShapeType::Cylinder:
            return axis == 1 ? &o.height : &o.radius;
    }
    return &o.radius;
}

Object applyGizmo(Object o, const GizmoDelta& d, const GizmoSettings& k) {
    o.pos += d.move;
    if (d.turn != glm::quat(1.0f, 0.0f, 0.0f, 0.0f)) {
        const glm::quat q = glm::normalize(d.turn * o.orientation());
        if (o.orient || o.dynamic()) o.orient = q;
        o.rot = eulerFromRotation(glm::mat3_cast(q));
    }
    if (d.scaleAxis >= 0) {
        float* length = sizedLength(o, d.scaleAxis);
        *length = std::max(*length * d.scale, k.minSize);
    }
    return o;
}

//-----------------------------------------------------------------------------
// [SECTION] Selection
//-----------------------------------------------------------------------------
bool selectionGizmo(const Scene& s, const Selection& sel, GizmoMode mode, glm::vec2 viewSize,
                    GizmoFrame* f, GizmoMode* shown, const GizmoSettings& k) {
    glm::vec3 centre;
    glm::mat3 axes(1.0f);
    if (sel.kind == ItemKind::Object && sel.index >= 0 && sel.index < int(s.objects.size())) {
        const Object& o = s.objects[size_t(sel.index)];
        centre = o.pos;
        if (mode == GizmoMode::Scale) axes = glm::mat3_cast(o.orientation());
        *shown = mode;
    } else if (sel.kind == ItemKind::Light && sel.index >= 0 && sel.index < int(s.lights.size()) &&
               !s.lights[size_t(sel.index)].directional) {
        centre = s.lights[size_t(sel.index)].vec;
        *shown = GizmoMode::Move;
    } else {
        return false;
    }
    glm::vec2 unused;
    if (!projectToPixel(s.camera, centre, viewSize, &unused)) return false;
    *f = gizmoFrame(s.camera, centre, axes, viewSize, k);
    return true;
}

int pickLightMarker(const Scene& s, glm::vec2 pixel, glm::vec2 viewSize, float radiusPixels) {
    int best = -1;
    float nearest = INFINITY;
    for (size_t i = 0; i < s.lights.size(); ++i) {
        const Light& l = s.lights[i];
        glm::vec2 at;
        if (l.directional || !projectToPixel(s.camera, l.vec, viewSize, &at)) continue;
        const float depth = glm::distance(l.vec, s.camera.pos);
        if (glm::distance(at, pixel) <= radiusPixels && depth < nearest) {
            nearest = depth;
            best = int(i);
        }
    }
    return best;
}

}  // namespace mb
