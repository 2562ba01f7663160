// marchbox/editor/picking.h — what lies under the mouse: a CPU ray cast against the SDF mirror,
// the same ray the shader marches for that pixel.
//
// Pixels count from the bottom-left corner of the view, as gl_FragCoord does; the caller flips
// the mouse's y.
#pragma once

#include "marchbox/editor/camera_control.h"
#include "marchbox/editor/scene_edit.h"
#include "marchbox/editor/scene_tree.h"
#include "marchbox/scene/scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace mb {

// Index of the object seen at `pixel` of a view of viewSize, or -1 for the ground or the sky.
// A group's member is picked as itself, where the world sees it (every copy of a repeated or
// mirrored group picks the member it copies). Hidden and locked objects are seen through.
int pickObject(const Scene& scene, glm::vec2 pixel, glm::vec2 viewSize);

// The objects whose centres, in the world, show inside the box with corners `a` and `b`: what a
// box drag selects, hidden and locked ones left out. In the order of the list.
std::vector<Item> objectsInBox(const Scene& scene, glm::vec2 a, glm::vec2 b, glm::vec2 viewSize);

// The scene as the editor's view draws it: without its hidden objects (Object::hidden), which
// *r renumbers. Render and export draw them all.
Scene visibleScene(const Scene& scene, Renumbering* r);

// Where the ray through `pixel` meets the horizontal plane y = height. False when the ray runs
// parallel to it or away from it.
bool pixelOnPlane(const Camera& camera, glm::vec2 pixel, glm::vec2 viewSize, float height,
                  glm::vec3* hit);

// Where Add puts the new object `o`: resting on the ground (its lowest point on the floor) where
// the middle of the view's window shows it (below the camera's target when the ground is not
// there), then moved over the ground the least that keeps it clear of every object and whole
// inside the window. Where no spot in the window is clear, the nearest clear one; crowded all
// round, it goes above them to fall into place.
glm::vec3 placeNewObject(const Scene& scene, const Object& o, const ViewWindow& view = {});

// A modifier-drag in the view: an object or a group slides over the horizontal plane through
// its centre in the world, keeping the point first grabbed under the mouse.
struct GroundDrag {
    Item item{ItemKind::Object, -1};  // what moves; index -1: no drag
    float height = 0.0f;              // of the plane, the item's centre height
    glm::vec3 offset{0.0f};           // item centre minus the grabbed point

    bool begin(const Scene& scene, Item what, glm::vec2 pixel, glm::vec2 viewSize);
    bool begin(const Scene& scene, int object, glm::vec2 pixel, glm::vec2 viewSize) {
        return begin(scene, Item{ItemKind::Object, object}, pixel, viewSize);
    }
    // Where the item's centre goes, in the world, for the mouse at `pixel`; false when the ray
    // misses.
    bool follow(const Camera& camera, glm::vec2 pixel, glm::vec2 viewSize, glm::vec3* pos) const;
    bool active() const { return item.index >= 0; }
    void end() { item.index = -1; }
};

}  // namespace mb
