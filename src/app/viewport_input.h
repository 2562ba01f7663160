// viewport_input.h — the mouse and the fly keys over the scene: camera, picking, box selection,
// dragging.
// ImGui's WantCaptureMouse and WantCaptureKeyboard keep input it uses away from here.
#pragma once

#include "marchbox/editor/camera_control.h"
#include "marchbox/editor/gizmo.h"
#include "marchbox/editor/picking.h"
#include "ui.h"

#include <bitset>
#include <glm/vec2.hpp>

namespace mb {

class ViewportInput {
public:
    // One frame of input; the view is framebufferSize pixels, the mouse in window coordinates.
    void update(UiContext& c, glm::vec2 framebufferSize, float seconds);
    bool dragging() const { return drag_ != Drag::None; }
    // The gizmo handle held, or under the mouse while nothing is dragged: the one drawn lit.
    GizmoHandle hotHandle(const UiContext& c) const;
    // Over the scene, under the panels: the box of a box selection being dragged, and a ring
    // about each selected object but the active one (the picture outlines that one).
    void drawSelection(const UiContext& c) const;

private:
    enum class Drag { None, Orbit, Pan, Move, Gizmo, Box, Place };
    glm::vec2 pixel(glm::vec2 mouse) const;  // window coordinates to a bottom-up view pixel
    void press(UiContext& c);
    GizmoHandle handleAt(const UiContext& c, glm::vec2 at, GizmoFrame* f) const;
    bool grabGizmo(UiContext& c, glm::vec2 at);  // a press on a handle of the selection
    void pressCtrl(UiContext& c, glm::vec2 at);  // a move over the ground, or a box
    void hold(UiContext& c);
    void follow(UiContext& c, glm::vec2 delta);  // the drag moved the mouse by delta
    void dragGizmo(UiContext& c, glm::vec2 at);
    void release(UiContext& c);
    void click(UiContext& c, glm::vec2 at, bool shift);  // a press that never became a drag
    void keys(UiContext& c, float seconds);
    void beginPlacing(UiContext& c);  // Duplicate's copies, selected, take the mouse
    void place(UiContext& c);         // each frame until a click places them or Esc drops
                                      // them back beside the originals
    uint64_t dragKey() const { return 0x4d6f7665ull << 32 | moves_; }  // "Move": its undo step

    Drag drag_ = Drag::None;
    int button_ = 0;      // the button that started the drag
    bool moved_ = false;  // past ImGui's drag threshold: not a click
    GroundDrag ground_;
    GizmoDrag gizmo_;
    Selection held_;      // what the gizmo drag acts on
    GizmoHold hold_;      // its objects and groups at the press: each frame applies the whole
    glm::vec3 heldLight_{0.0f};  // drag to them, or to a light's place
    glm::vec2 boxFrom_{0.0f};    // a box selection's first corner, in view pixels
    glm::vec3 placedFrom_{0.0f};  // the active copy's centre when placing began
    bool boxExtends_ = false;    // Shift held: the box adds to the selection
    uint64_t moves_ = 0;  // numbers each drag that edits: one undo step per drag
    glm::vec2 view_{0.0f}, scale_{1.0f};
    CameraControls controls_;
    std::bitset<6> flying_;  // which fly keys (kFlyKeys) went down as flight and are held
};

}  // namespace mb
