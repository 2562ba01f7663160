// gizmo.cpp — the view's move, turn and size handles: projection, hit testing and drags.
#include "marchbox/editor/gizmo.h"

#include "marchbox/editor/scene_tree.h"
#include "marchbox/scene/camera.h"
#include "marchbox/scene/sdf.h"
#include "marchbox/scene/shapes.h"

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

// How near `pixel` the polyline through world points point(0..n) passes on screen, and how
// far from the eye the nearest of its segments that pass within `reach` px are.
struct PathHit {
    float pixels = INFINITY;
    float depth = INFINITY;
};

template <typename Point>
static PathHit hitPath(const Camera& c, glm::vec2 viewSize, glm::vec2 pixel, int n, Point point,
                       float reach) {
    PathHit hit;
    glm::vec2 prev, next;
    bool have = projectToPixel(c, point(0), viewSize, &prev);
    for (int i = 1; i < n; ++i) {
        const bool ok = projectToPixel(c, point(i), viewSize, &next);
        const float d = have && ok ? distanceToSegment(pixel, prev, next) : INFINITY;
        hit.pixels = std::min(hit.pixels, d);
        if (d <= reach)
            hit.depth = std::min(hit.depth, glm::distance(c.pos, 0.5f * (point(i - 1) + point(i))));
        prev = next;
        have = ok;
    }
    return hit;
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
    // Axes and handles: the nearest on screen. Rings: of those within reach, the one in front,
    // as where two cross the ring drawn over the other is the one meant.
    GizmoHandle best;
    float bestKey = INFINITY;
    for (int i = 0; i < 3; ++i) {
        if (!handleShown(c, f, {kind, i}, k)) continue;
        PathHit hit;
        if (mode == GizmoMode::Rotate) {
            const int n = 65;  // 64 segments: within a pixel of the circle at lengthPixels
            hit = hitPath(c, viewSize, pixel, n, [&](int j) {
                return ringPoint(f, i, glm::two_pi<float>() * float(j) / float(n - 1));
            }, k.pickPixels);
        } else {
            const glm::vec3 a = f.axes[i] * f.length;
            hit = hitPath(c, viewSize, pixel, 2,
                          [&](int j) { return f.centre + (j == 0 ? k.axisFrom : 1.0f) * a; },
                          k.pickPixels);
        }
        const float key = mode == GizmoMode::Rotate ? hit.depth : hit.pixels;
        if (hit.pixels <= k.pickPixels && key <= bestKey) {
            bestKey = key;
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

// The length a drag along the object's own axis `axis` sizes: a size along its axis; the
// height, or a torus's tube (the ring lies in local xz), along y; else the radius.
static float* sizedLength(Object& o, int axis) {
    if (reads(o.type, kSizeKey)) return &o.size[axis];
    if (axis == 1 && reads(o.type, kHeightKey)) return &o.height;
    if (axis == 1 && reads(o.type, kMinorKey)) return &o.minor;
    return &o.radius;
}

static void sizeAlongAxis(Object& o, int axis, float factor, const GizmoSettings& k) {
    float* length = sizedLength(o, axis);
    const float was = *length;
    *length = std::max(was * factor, k.minSize);
    if (reads(o.type, kTopKey) && length == &o.radius) o.top *= *length / was;  // its shape
    fitShape(o);
}

Object applyGizmo(Object o, const GizmoDelta& d, const GizmoSettings& k) {
    o.pos += d.move;
    if (d.turn != glm::quat(1.0f, 0.0f, 0.0f, 0.0f)) {
        const glm::quat q = glm::normalize(d.turn * o.orientation());
        if (o.orient || o.dynamic()) o.orient = q;
        o.rot = eulerFromRotation(glm::mat3_cast(q));
    }
    if (d.scaleAxis >= 0) sizeAlongAxis(o, d.scaleAxis, d.scale, k);
    return o;
}

// The lengths the object's type uses, which sizing it changes (the file keeps no others).
static std::vector<float*> lengthsOf(Object& o) {
    std::vector<float*> lengths;
    if (reads(o.type, kSizeKey)) lengths = {&o.size.x, &o.size.y, &o.size.z};
    if (reads(o.type, kRadiusKey)) lengths.push_back(&o.radius);
    if (reads(o.type, kMinorKey)) lengths.push_back(&o.minor);
    if (reads(o.type, kHeightKey)) lengths.push_back(&o.height);
    return lengths;
}

// The least factor that keeps each of the object's lengths at minSize or more.
static float leastFactor(Object o, const GizmoSettings& k) {
    float least = INFINITY;
    for (float* length : lengthsOf(o)) least = std::min(least, *length);
    return k.minSize / least;
}

void scaleObject(Object& o, float f, const GizmoSettings& k) {
    f = std::max(f, leastFactor(o, k));
    for (float* length : lengthsOf(o)) *length *= f;
    o.top *= f, o.round *= f, o.shell *= f, o.blend *= f;
    fitShape(o);
}

// Groups g holds, below it.
static bool inside(const Scene& s, size_t h, int g) {
    return int(h) > g && within(s, {ItemKind::Group, int(h)}, g);
}

void scaleGroup(Scene& s, int g, float f, const GizmoSettings& k) {
    const int first = s.groups[size_t(g)].first, end = groupEnd(s, g);
    for (int i = first; i < end; ++i) f = std::max(f, leastFactor(s.objects[size_t(i)], k));
    for (int i = first; i < end; ++i) {
        s.objects[size_t(i)].pos *= f;
        scaleObject(s.objects[size_t(i)], f, k);
    }
    s.groups[size_t(g)].spacing *= f;
    for (size_t h = size_t(g) + 1; h < s.groups.size(); ++h) {
        if (!inside(s, h, g)) continue;
        s.groups[h].pos *= f;
        s.groups[h].spacing *= f;
        s.groups[h].blend *= f;
    }
}

namespace {

// The records of `it` and of everything in it, back as the hold has them.
void restore(Scene& s, const GizmoHold& h, Item it) {
    if (it.kind == ItemKind::Object) {
        s.objects[size_t(it.index)] = h.objects[size_t(it.index)];
        return;
    }
    for (int i = s.groups[size_t(it.index)].first; i < groupEnd(s, it.index); ++i)
        s.objects[size_t(i)] = h.objects[size_t(i)];
    s.groups[size_t(it.index)] = h.groups[size_t(it.index)];
    for (size_t g = size_t(it.index) + 1; g < s.groups.size(); ++g)
        if (inside(s, g, it.index)) s.groups[g] = h.groups[g];
}

// The least uniform factor that keeps every length the items hold at minSize or more.
float leastFactor(const Scene& s, const std::vector<Item>& items, const GizmoSettings& k) {
    float least = 0.0f;
    for (Item it : items) {
        const bool object = it.kind == ItemKind::Object;
        const int first = object ? it.index : s.groups[size_t(it.index)].first;
        const int end = object ? it.index + 1 : groupEnd(s, it.index);
        for (int i = first; i < end; ++i)
            least = std::max(least, leastFactor(s.objects[size_t(i)], k));
    }
    return least;
}

glm::vec3& ownPos(Scene& s, Item it) {
    return it.kind == ItemKind::Object ? s.objects[size_t(it.index)].pos
                                       : s.groups[size_t(it.index)].pos;
}

// One held item: moved by the drag in its parent's frame (exact where that frame does not
// turn), then turned and sized about the centre in the world.
void applyToItem(Scene& s, const GizmoHold& h, Item it, const GizmoDelta& d,
                 const GizmoSettings& k) {
    restore(s, h, it);
    const Placement frame = groupPose(s, parentOf(s, it));
    ownPos(s, it) += glm::inverse(frame.turn) * d.move;
    Placement world = itemPose(s, it);
    const bool turns = d.turn != glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
    if (turns) {
        world.pos = h.centre + d.turn * (world.pos - h.centre);
        world.turn = glm::normalize(d.turn * world.turn);
    }
    if (d.scaleAxis >= 0 && h.alone && it.kind == ItemKind::Object) {
        sizeAlongAxis(s.objects[size_t(it.index)], d.scaleAxis, d.scale, k);
    } else if (d.scaleAxis >= 0) {
        world.pos = h.centre + d.scale * (world.pos - h.centre);
        if (it.kind == ItemKind::Object) scaleObject(s.objects[size_t(it.index)], d.scale, k);
        else scaleGroup(s, it.index, d.scale, k);
    }
    if (turns || (d.scaleAxis >= 0 && !h.alone)) setItemPose(s, it, world);
}

}  // namespace

// The mean of the items' places in the world.
static glm::vec3 centreOf(const Scene& s, const std::vector<Item>& items) {
    glm::vec3 sum(0.0f);
    for (Item it : items) sum += itemPose(s, it).pos;
    return items.empty() ? sum : sum / float(items.size());
}

GizmoHold holdSelection(const Scene& s, const Selection& sel, const GizmoSettings& k) {
    GizmoHold h;
    h.items = roots(s, treeItems(sel));
    h.objects = s.objects;
    h.groups = s.groups;
    h.centre = centreOf(s, h.items);
    h.alone = h.items.size() == 1 && h.items[0].kind == ItemKind::Object;
    h.leastScale = leastFactor(s, h.items, k);
    return h;
}

void applyGizmo(Scene& s, const GizmoHold& h, const GizmoDelta& d, const GizmoSettings& k) {
    if (s.objects.size() != h.objects.size() || s.groups.size() != h.groups.size()) return;
    GizmoDelta uniform = d;
    if (d.scaleAxis >= 0 && !h.alone) uniform.scale = std::max(d.scale, h.leastScale);
    for (Item it : h.items) applyToItem(s, h, it, uniform, k);
}

//-----------------------------------------------------------------------------
// [SECTION] Selection
//-----------------------------------------------------------------------------
bool selectionGizmo(const Scene& s, const Selection& sel, GizmoMode mode, glm::vec2 viewSize,
                    GizmoFrame* f, GizmoMode* shown, const GizmoSettings& k) {
    glm::vec3 centre;
    glm::mat3 axes(1.0f);
    const std::vector<Item> items = roots(s, treeItems(sel));
    if (!items.empty()) {
        centre = centreOf(s, items);
        if (mode == GizmoMode::Scale && items.size() == 1)
            axes = glm::mat3_cast(itemPose(s, items[0]).turn);
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
