// scene_parts.h — a scene cut into the parts an animated export meshes apart: the static solids,
// and each dynamic body alone in its own frame.
#pragma once

#include "marchbox/scene/scene.h"

#include <string>
#include <vector>

namespace mb {

// A dynamic body: a top-level object or group that the simulator moves (dynamic()).
struct BodyRef {
    bool group = false;
    int index = 0;  // in Scene::objects or Scene::groups
};

std::vector<BodyRef> dynamicBodies(const Scene& scene);  // in the scene's tree order
std::string bodyName(const Scene& scene, BodyRef body);  // its name, or "sphere 4", "group 2"
Placement bodyPose(const Scene& scene, BodyRef body);    // its pos and turn (orient or rot)

// Every top-level object and group that is not a dynamic body, with their members: what stays
// where it is for the whole run.
Scene staticPart(const Scene& scene);
// The body alone, its origin at (0,0,0) and unturned, joined by union without a blend: its own
// solid in its own frame, as the simulator moves it.
Scene bodyAtOrigin(const Scene& scene, BodyRef body);

}  // namespace mb
