// picking.cpp — ray casts for selection, for dragging objects over the ground and for placing
// new ones.
#include "marchbox/editor/picking.h"

#include "marchbox/editor/gizmo.h"
#include "marchbox/editor/scene_tree.h"
#include "marchbox/scene/camera.h"
#include "marchbox/scene/sdf.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace mb {

// As far as the shader marches (gpu_scene's maxRayDistance): past every object's bound.
static float reach(const Scene& scene, const SceneSdf& sdf) {
    float far = 100.0f;
    for (const SdfObject& o : sdf.objects)
        far = std::max(far, 2.0f * (glm::length(o.pos - scene.camera.pos) + o.bound));
    return far;
}

// Objects that match `leave`, erased; *r renumbers.
template <typename Leave>
static Scene without(const Scene& scene, Renumbering* r, Leave leave) {
    std::vector<Item> gone;
    for (size_t i = 0; i < scene.objects.size(); ++i)
        if (leave(scene.objects[i])) gone.push_back({ItemKind::Object, int(i)});
    Scene s = scene;
    *r = eraseItems(s, gone);
    return s;
}

Scene visibleScene(const Scene& scene, Renumbering* r) {
    return without(scene, r, [](const Object& o) { return o.hidden; });
}

// What a click can take: neither hidden nor locked. *original is each object's index in `scene`.
static Scene pickable(const Scene& scene, std::vector<int>* original) {
    Renumbering r;
    Scene s = without(scene, &r, [](const Object& o) { return o.hidden || o.locked; });
    original->assign(s.objects.size(), -1);
    for (size_t i = 0; i < r.objects.size(); ++i)
        if (r.objects[i] >= 0) (*original)[size_t(r.objects[i])] = int(i);
    return s;
}

int pickObject(const Scene& all, glm::vec2 pixel, glm::vec2 viewSize) {
    if (viewSize.x <= 0.0f || viewSize.y <= 0.0f) return -1;
    std::vector<int> original;
    const Scene scene = pickable(all, &original);
    SceneSdf sdf = makeSceneSdf(scene);
    glm::vec3 dir = cameraRay(cameraBasis(scene.camera), pixel, viewSize);
    RayHit hit = castRay(sdf, scene.camera.pos, dir, scene.render.steps, scene.render.epsilon,
                         reach(scene, sdf));
    return hit.hit && hit.object >= 0 ? original[size_t(hit.object)] : -1;
}

std::vector<Item> objectsInBox(const Scene& scene, glm::vec2 a, glm::vec2 b, glm::vec2 viewSize) {
    const glm::vec2 lo = glm::min(a, b), hi = glm::max(a, b);
    std::vector<Item> inside;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        if (scene.objects[i].hidden || scene.objects[i].locked) continue;
        glm::vec2 at;
        const glm::vec3 centre = worldPose(scene, scene.objects[i]).pos;
        if (projectToPixel(scene.camera, centre, viewSize, &at) &&
            glm::all(glm::greaterThanEqual(at, lo)) && glm::all(glm::lessThanEqual(at, hi)))
            inside.push_back({ItemKind::Object, int(i)});
    }
    return inside;
}

bool pixelOnPlane(const Camera& camera, glm::vec2 pixel, glm::vec2 viewSize, float height,
                  glm::vec3* hit) {
    if (viewSize.x <= 0.0f || viewSize.y <= 0.0f) return false;
    glm::vec3 dir = cameraRay(cameraBasis(camera), pixel, viewSize);
    if (std::abs(dir.y) < 1e-6f) return false;
    float t = (height - camera.pos.y) / dir.y;
    if (t <= 0.0f) return false;
    *hit = camera.pos + t * dir;
    return true;
}

// Clear: past each object's reach, or outside its surface by the new radius, its blend (a smooth
// blend pulls surfaces together by up to that much) and a hair.
static bool clearOf(const std::vector<SdfObject>& objects, glm::vec3 p, float radius) {
    const float gap = 1e-3f;
    for (const SdfObject& o : objects) {
        if (glm::length(p - o.pos) >= objectReach(o) + radius + gap) continue;
        if (sdObject(o, p) < radius + o.blend + gap) return false;
    }
    return true;
}

// The spots about `centre` nearest first, in rings one `step` apart: ring k holds 6k spots, about
// a step apart along it. The first that `fits` accepts, if any.
template <typename Fits>
static bool nearestSpot(glm::vec3 centre, float step, Fits fits, glm::vec3* out) {
    for (int k = 0; k <= 64; ++k) {
        const int spots = std::max(1, 6 * k);
        for (int i = 0; i < spots; ++i) {
            float a = 6.2831853f * float(i) / float(spots);
            glm::vec3 p = centre + float(k) * step * glm::vec3(std::cos(a), 0.0f, std::sin(a));
            if (fits(p)) return *out = p, true;
        }
    }
    return false;
}

// The ground spot, at height y, that the middle of the window shows; below the camera's target
// where the ray through it misses the ground (the sky, or the ground above the eye).
static glm::vec3 aimedSpot(const Camera& c, const ViewWindow& view, float y) {
    const glm::vec3 ray = viewRay(c, view.aspect, view.middle());
    const float along = ray.y != 0.0f ? (y - c.pos.y) / ray.y : -1.0f;
    return along > 0.0f ? c.pos + along * ray : glm::vec3(c.target.x, y, c.target.z);
}

glm::vec3 placeNewObject(const Scene& scene, const Object& o, const ViewWindow& view) {
    const Camera& c = scene.camera;
    const float radius = boundingRadius(o);
    const glm::vec3 centre = aimedSpot(c, view, scene.world.floor + depthBelowCentre(o));
    SceneSdf sdf = makeSceneSdf(scene);
    const float step = std::max(radius, 0.01f);
    glm::vec3 spot;
    if (nearestSpot(
            centre, step,
            [&](glm::vec3 p) {
                return clearOf(sdf.objects, p, radius) && ballInView(c, {p, radius}, view);
            },
            &spot) ||
        nearestSpot(
            centre, step, [&](glm::vec3 p) { return clearOf(sdf.objects, p, radius); }, &spot))
        return spot;
    float top = centre.y;
    for (const SdfObject& s : sdf.objects) top = std::max(top, s.pos.y + objectReach(s) + radius);
    return {centre.x, top, centre.z};
}

bool GroundDrag::begin(const Scene& scene, Item what, glm::vec2 pixel, glm::vec2 viewSize) {
    if (!validItem(scene, what)) return false;
    const glm::vec3 centre = itemPose(scene, what).pos;
    glm::vec3 grabbed;
    if (!pixelOnPlane(scene.camera, pixel, viewSize, centre.y, &grabbed)) return false;
    item = what;
    height = centre.y;
    offset = centre - grabbed;
    return true;
}

bool GroundDrag::follow(const Camera& camera, glm::vec2 pixel, glm::vec2 viewSize,
                        glm::vec3* pos) const {
    glm::vec3 point;
    if (!active() || !pixelOnPlane(camera, pixel, viewSize, height, &point)) return false;
    *pos = point + offset;
    pos->y = height;  // exactly: the plane's y, not a rounding of it
    return true;
}

}  // namespace mb
