// viewport_input.h — the mouse and the fly keys over the scene: camera, picking, dragging.
// ImGui's WantCaptureMouse and WantCaptureKeyboard keep input it uses away from here.
#pragma once

#include "marchbox/editor/camera_control.h"
#include "marchbox/editor/gizmo.h"
#include "marchbox/editor/picking.h"
#include "ui.h"

#include <glm/vec2.hpp>

namespace mb {

class ViewportInput {
public:
    // One frame of input; the view is framebufferSize pixels, the mouse in window coordinates.
    void update(UiContext& c, glm::vec2 framebufferSize, float seconds);
    bool dragging() const { return drag_ != Drag::None; }
    // The gizmo handle held, or under the mouse while nothing is dragged: the one drawn lit.
    GizmoHandle hotHandle(const UiContext& c) const;

private:
    enum class Drag { None, Orbit, Pan, Move, Gizmo };
    glm::vec2 pixel(glm::vec2 mouse) const;  // window coordinates to a bottom-up view pixel
    void press(UiContext& c);
    GizmoHandle handleAt(const UiContext& c, glm::vec2 at, GizmoFrame* f) const;
    bool grabGizmo(UiContext& c, glm::vec2 at);  // a press on a handle of the selection
    void hold(UiContext& c);
    void follow(UiContext& c, glm::vec2 delta);  // the drag moved the mouse by delta
    void dragGizmo(UiContext& c, glm::vec2 at);
    void release(UiContext& c);
    void keys(UiContext& c, float seconds);
    uint64_t dragKey() const { return 0x4d6f7665ull << 32 | moves_; }  // "Move": its undo step

    Drag drag_ = Drag::None;
    int button_ = 0;      // the button that started the drag
    bool moved_ = false;  // past ImGui's drag threshold: not a click
    GroundDrag ground_;
    GizmoDrag gizmo_;
    Selection held_;      // what the gizmo drag acts on
    GizmoHold hold_;      // its objects and groups at the press: each frame applies the whole
    glm::vec3 heldLight_{0.0f};  // drag to them, or to a light's place
    uint64_t moves_ = 0;  // numbers each drag that edits: one undo step per drag
    glm::vec2 view_{0.0f}, scale_{1.0f};
    CameraControls controls_;
};

}  // namespace mb
