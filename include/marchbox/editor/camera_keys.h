// marchbox/editor/camera_keys.h — adding, moving and deleting the scene's camera keyframes.
//
// Keys stay in order of t with no two at one t, as the loader leaves them and cameraAt()
// expects (marchbox/scene/camera_path.h).
#pragma once

#include "marchbox/scene/scene.h"

namespace mb {

// A key at time t (s) holding `view`; one already at t takes the view instead. Returns its index.
int setCameraKey(Scene& s, float t, const Camera& view);
// Moves key `index` to time t (>= 0), the keys kept in order; its view stays. Returns its new
// index, or -1 with nothing moved when another key is at t or the index or time is out of range.
int moveCameraKey(Scene& s, int index, float t);
// The index of the key nearest to t (the earlier of two as near), -1 without keys.
int nearestCameraKey(const Scene& s, double t);

}  // namespace mb
