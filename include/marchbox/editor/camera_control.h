// marchbox/editor/camera_control.h — orbit, pan, zoom and fly for the scene's camera.
//
// Rules: angles in radians, distances in metres, mouse movement in window pixels with +y down
// (as the mouse reports it). The camera orbits its target; panning and flying move both.
#pragma once

#include "marchbox/scene/scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace mb {

struct CameraControls {
    float orbitRadiansPerPixel = 0.005f;
    float zoomPerWheelStep = 0.85f;  // distance factor for one wheel notch forward
    float minDistance = 0.05f, maxDistance = 1e4f;
    float maxPitch = 1.54f;  // rad from the horizon: never quite over the pole
    float flySpeed = 4.0f;   // m/s
    float previewRadiansPerSecond = 0.4f;
};

// Turns the camera about its target so the scene follows the mouse, as three.js's
// OrbitControls do: dragging right swings the camera to the view's left, dragging down lifts it.
void orbitCamera(Camera& c, glm::vec2 dragPixels, const CameraControls& k = {});

// Slides camera and target across the view so the point under the mouse follows it.
// viewHeight is the view's height in the same pixels as dragPixels.
void panCamera(Camera& c, glm::vec2 dragPixels, float viewHeight);

// Moves towards the target (positive steps) or away, keeping the distance within limits.
void zoomCamera(Camera& c, float wheelSteps, const CameraControls& k = {});

// WASD/QE: move is (right, up, forward), each -1..1; up is the world's +y.
void flyCamera(Camera& c, glm::vec3 move, float seconds, const CameraControls& k = {});

// Key 1's preview: a slow turn about the vertical through the target.
void previewOrbit(Camera& c, float seconds, const CameraControls& k = {});

// What holds the eye, so the view can say why it shows nothing but black: the index of the
// object the eye is inside, kHitGround below the floor, kHitNone in the open (sdf.h's codes).
int solidAroundEye(const Scene& scene, glm::vec3 eye);

// A ball to frame: an object's bounding sphere, or a light's position with a small radius.
struct Ball {
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
};

// The view's shape, and the part of it where the scene shows unobstructed (the docked panels
// cover the rest): from `lo` to `hi` in fractions of the view's half extents from its centre,
// x right and y up, the whole view from -1 to 1.
struct ViewWindow {
    ViewWindow(float aspectOfView = 1.0f, glm::vec2 from = glm::vec2(-1.0f),
               glm::vec2 to = glm::vec2(1.0f))
        : aspect(aspectOfView), lo(from), hi(to) {}
    float aspect;  // the whole view's width over its height
    glm::vec2 lo, hi;
    glm::vec2 middle() const { return 0.5f * (lo + hi); }
};

// True when the whole ball lies inside the window of the camera's view.
bool ballInView(const Camera& c, const Ball& b, const ViewWindow& w);

// The ray from the eye through point `at` of the view (ViewWindow's units), not normalised.
glm::vec3 viewRay(const Camera& c, float aspect, glm::vec2 at);

// Frame selected and Frame all: from the same direction, as close as lets every ball fit the
// window, within the controls' distance limits, the middle of the balls at the window's middle.
// Nothing to frame leaves the camera as it was.
void frameBalls(Camera& c, const std::vector<Ball>& balls, const ViewWindow& w,
                const CameraControls& k = {});

}  // namespace mb
