// frame_sequence.cpp — the simulation under a frame sequence.
#include "frame_sequence.h"

#include "marchbox/scene/camera_path.h"

namespace mb {

FrameSequence::FrameSequence(const Scene& scene, const PhysicsSettings& settings, double fps)
    : start_(scene), settings_(settings), world_(start_, settings_), fps_(fps) {}

bool FrameSequence::reach(int frame, const std::function<bool()>& stop) {
    for (const int steps = stepsFor(frame / fps_, settings_); world_.stepCount() < steps;) {
        if (stop()) return false;
        world_.step();
    }
    return true;
}

Scene FrameSequence::scene(int frame) const {
    Scene shown = start_;
    world_.writeBack(shown);
    shown.camera = cameraAt(shown.keyframes, shown.camera, frame / fps_);
    return shown;
}

}  // namespace mb
