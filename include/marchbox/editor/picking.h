// marchbox/editor/picking.h — what lies under the mouse: a CPU ray cast against the SDF mirror,
// the same ray the shader marches for that pixel.
//
// Pixels count from the bottom-left corner of the view, as gl_FragCoord does; the caller flips
// the mouse's y.
#pragma once

#include "marchbox/scene/scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace mb {

// Index of the object seen at `pixel` of a view of viewSize, or -1 for the ground or the sky.
int pickObject(const Scene& scene, glm::vec2 pixel, glm::vec2 viewSize);

// Where the ray through `pixel` meets the horizontal plane y = height. False when the ray runs
// parallel to it or away from it.
bool pixelOnPlane(const Camera& camera, glm::vec2 pixel, glm::vec2 viewSize, float height,
                  glm::vec3* hit);

// Where Add puts the new object `o`: resting on the ground (its lowest point on the floor) below
// the camera's target, then moved over the ground the least that keeps it clear of every object
// and inside the view. Where no spot in view is clear, the nearest clear one; crowded all
// round, it goes above them to fall into place.
glm::vec3 placeNewObject(const Scene& scene, const Object& o);

// A modifier-drag in the view: the object slides over the horizontal plane through its centre,
// keeping the point first grabbed under the mouse.
struct GroundDrag {
    int object = -1;         // -1: no drag
    float height = 0.0f;     // of the plane, the object's centre height
    glm::vec3 offset{0.0f};  // object centre minus the grabbed point

    bool begin(const Scene& scene, int object, glm::vec2 pixel, glm::vec2 viewSize);
    // Where the object's centre goes for the mouse at `pixel`; false when the ray misses.
    bool follow(const Camera& camera, glm::vec2 pixel, glm::vec2 viewSize, glm::vec3* pos) const;
    bool active() const { return object >= 0; }
    void end() { object = -1; }
};

}  // namespace mb
