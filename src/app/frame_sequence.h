// frame_sequence.h — a scene played once from t = 0 at the fixed physics step, frame k taken
// when the simulation reaches t = k / fps. Shared by render --frames and File > Render
// Animation..., so both write the same bytes for the same settings.
//
// Frame k is the picture `render --seconds k/fps` makes: the same number of steps (stepsFor) and
// the same camera (cameraAt). So a range gives the same bytes in one process or split over
// many, each simulating from t = 0 to its first frame.
#pragma once

#include "marchbox/physics/physics.h"
#include "marchbox/scene/scene.h"

#include <functional>

namespace mb {

class FrameSequence {
public:
    FrameSequence(const Scene& scene, const PhysicsSettings& settings, double fps);
    // Steps toward frame `frame`'s time until there (true) or until stop() says so (false),
    // to be called again later. Frames come in increasing order: the world only goes forward.
    bool reach(int frame, const std::function<bool()>& stop);
    Scene scene(int frame) const;  // after reach(frame): the bodies now, the path's camera

private:
    Scene start_;
    PhysicsSettings settings_;
    PhysicsWorld world_;
    double fps_;
};

}  // namespace mb
