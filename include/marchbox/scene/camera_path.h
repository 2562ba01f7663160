// marchbox/scene/camera_path.h — the camera over time: a C¹ spline through the scene's keyframes.
//
// pos, target and fov each follow a cubic Hermite curve from key to key in t. At an inner key
// the tangent is the slope there of the parabola through that key and its two neighbours
// (Catmull-Rom on the keys' own times, so unevenly spaced keys keep a steady speed, and a path
// that is quadratic in t comes out exact). At the first and the last key the tangent is zero:
// the camera holds still before the first key and after the last, and eases into and out of
// those holds, so position and velocity are continuous at every t.
#pragma once

#include "marchbox/scene/scene.h"

#include <vector>

namespace mb {

// The view at time t (s). `keys` in increasing order of t, as the loader leaves them. No keys:
// `rest` (the camera record); one key: that key at every t.
Camera cameraAt(const std::vector<Keyframe>& keys, const Camera& rest, double t);

}  // namespace mb
