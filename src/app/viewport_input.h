// viewport_input.h — the mouse and the fly keys over the scene: camera, picking, dragging.
// ImGui's WantCaptureMouse and WantCaptureKeyboard keep input it uses away from here.
#pragma once

#include "marchbox/editor/camera_control.h"
#include "marchbox/editor/picking.h"
#include "ui.h"

#include <glm/vec2.hpp>

namespace mb {

class ViewportInput {
public:
    // One frame of input; the view is framebufferSize pixels, the mouse in window coordinates.
    void update(UiContext& c, glm::vec2 framebufferSize, float seconds);
    bool dragging() const { return drag_ != Drag::None; }

private:
    enum class Drag { None, Orbit, Pan, Move };
    glm::vec2 pixel(glm::vec2 mouse) const;  // window coordinates to a bottom-up view pixel
    void press(UiContext& c);
    void hold(UiContext& c);
    void follow(UiContext& c, glm::vec2 delta);  // the drag moved the mouse by delta
    void release(UiContext& c);
    void keys(UiContext& c, float seconds);

    Drag drag_ = Drag::None;
    int button_ = 0;      // the button that started the drag
    bool moved_ = false;  // past ImGui's drag threshold: not a click
    GroundDrag ground_;
    uint64_t moves_ = 0;  // numbers each move-drag: one undo step per drag
    glm::vec2 view_{0.0f}, scale_{1.0f};
    CameraControls controls_;
};

}  // namespace mb
