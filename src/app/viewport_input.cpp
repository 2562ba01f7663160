// viewport_input.cpp — orbit, pan, zoom, fly; click to select, Shift+click to add or remove,
// Ctrl drag in empty space to select a box; right click to edit; drag a gizmo handle to move,
// turn or size the selection; Ctrl drag an object to move it over the ground.
#include "viewport_input.h"

#include "marchbox/editor/events.h"
#include "marchbox/scene/sdf.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <array>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <imgui.h>

namespace mb {

// The fly keys as pairs along the view's x, y and z: left and right, down and up, back and on.
static constexpr std::array<int, 6> kFlyKeys = {GLFW_KEY_A, GLFW_KEY_D, GLFW_KEY_Q,
                                                GLFW_KEY_E, GLFW_KEY_S, GLFW_KEY_W};

glm::vec2 ViewportInput::pixel(glm::vec2 mouse) const {
    // The centre of the framebuffer pixel under the mouse, counted from the bottom as GL does.
    glm::vec2 fb = glm::floor(mouse * scale_);
    return {fb.x + 0.5f, view_.y - fb.y - 0.5f};
}

void ViewportInput::update(UiContext& c, glm::vec2 framebufferSize, float seconds) {
    ImGuiIO& io = ImGui::GetIO();
    view_ = framebufferSize;
    scale_ = {io.DisplayFramebufferScale.x, io.DisplayFramebufferScale.y};
    if (c.ui.placeCopies) beginPlacing(c);
    c.ui.placeCopies = false;
    if (drag_ == Drag::Place) return place(c);  // the mouse is the copies' until a click
    if (drag_ == Drag::None && !io.WantCaptureMouse) press(c);
    if (drag_ != Drag::None) hold(c);
    if (!io.WantCaptureMouse && io.MouseWheel != 0.0f)
        zoomCamera(c.editor.view(), io.MouseWheel, controls_);
    keys(c, seconds);
    if (c.ui.previewOrbit) previewOrbit(c.editor.view(), seconds, controls_);
}

void ViewportInput::press(UiContext& c) {
    ImGuiIO& io = ImGui::GetIO();
    glm::vec2 at = pixel({io.MousePos.x, io.MousePos.y});
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
        if (c.editor.pick(at, view_) >= 0) c.ui.wantObjectPopup = true;
        return;
    }
    moved_ = false;
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Middle)) {
        drag_ = Drag::Pan;
        button_ = ImGuiMouseButton_Middle;
        return;
    }
    if (!ImGui::IsMouseClicked(ImGuiMouseButton_Left)) return;
    button_ = ImGuiMouseButton_Left;
    if (!io.KeyShift && grabGizmo(c, at)) return;
    drag_ = io.KeyShift ? Drag::Pan : Drag::Orbit;
    if (io.KeyCtrl) pressCtrl(c, at);
}

// On an object, what a Ctrl drag moves (the selected group holding it, or the object, selected
// if it was not); in empty space, a box.
void ViewportInput::pressCtrl(UiContext& c, glm::vec2 at) {
    const Scene& s = c.editor.scene();
    const int hit = pickObject(s, at, view_);
    if (hit < 0) {
        drag_ = Drag::Box;
        boxFrom_ = at;
        boxExtends_ = ImGui::GetIO().KeyShift;
        return;
    }
    const Item target = dragTarget(s, c.editor.selection(), hit);
    if (!c.editor.selection().has(target.kind, target.index))
        c.editor.select(target.kind, target.index);
    if (ground_.begin(c.editor.scene(), target, at, view_)) {
        drag_ = Drag::Move;
        ++moves_;
    }
}

// The selection's handle at `at` and the frame it belongs to; kind None where there is none,
// or while the view follows the camera keys (no handles drawn: see drawGizmo()).
GizmoHandle ViewportInput::handleAt(const UiContext& c, glm::vec2 at, GizmoFrame* f) const {
    const Scene& s = c.editor.scene();
    GizmoMode mode;
    if (c.editor.followsPath() ||
        !selectionGizmo(s, c.editor.selection(), c.ui.gizmo, view_, f, &mode))
        return {};
    return hitGizmo(s.camera, *f, mode, at, view_);
}

// A press on a handle of the selection takes it; with Ctrl held too, it snaps rather than
// starting a move over the ground.
bool ViewportInput::grabGizmo(UiContext& c, glm::vec2 at) {
    const Scene& s = c.editor.scene();
    GizmoFrame f;
    const GizmoHandle h = handleAt(c, at, &f);
    if (h.kind == HandleKind::None || !gizmo_.begin(s.camera, f, h, at, view_)) return false;
    held_ = c.editor.selection();
    if (held_.kind == ItemKind::Light) heldLight_ = s.lights[size_t(held_.index)].vec;
    else hold_ = holdSelection(s, held_);
    drag_ = Drag::Gizmo;
    ++moves_;
    return true;
}

GizmoHandle ViewportInput::hotHandle(const UiContext& c) const {
    if (drag_ == Drag::Gizmo) return gizmo_.handle;
    const ImGuiIO& io = ImGui::GetIO();
    GizmoFrame f;
    if (drag_ != Drag::None || io.WantCaptureMouse || !ImGui::IsMousePosValid()) return {};
    return handleAt(c, pixel({io.MousePos.x, io.MousePos.y}), &f);
}

void ViewportInput::hold(UiContext& c) {
    ImGuiIO& io = ImGui::GetIO();
    // The frame that sees the button up still moves by the motion before the release: a drag
    // whose press and release reach one frame apart moves all the same. ImGui stops counting
    // the distance dragged once the button is up, so it is measured here.
    const ImVec2 from = io.MouseClickedPos[button_], to = io.MousePos;
    if (ImGui::IsMousePosValid(&to) && ImGui::IsMousePosValid(&from))
        moved_ = moved_ || glm::distance(glm::vec2(to.x, to.y), glm::vec2(from.x, from.y)) >=
                               io.MouseDragThreshold;
    glm::vec2 delta(io.MouseDelta.x, io.MouseDelta.y);
    if (moved_ && delta != glm::vec2(0.0f)) follow(c, delta);
    if (!ImGui::IsMouseDown(button_)) release(c);
}

void ViewportInput::follow(UiContext& c, glm::vec2 delta) {
    ImGuiIO& io = ImGui::GetIO();
    switch (drag_) {
        case Drag::Orbit:
            orbitCamera(c.editor.view(), delta, controls_);
            break;
        case Drag::Pan:
            panCamera(c.editor.view(), delta * scale_.y, view_.y);
            break;
        case Drag::Move: {
            glm::vec3 pos;
            if (ground_.follow(c.editor.scene().camera, pixel({io.MousePos.x, io.MousePos.y}),
                               view_, &pos))
                c.editor.placeItem(ground_.item, pos, dragKey());
            break;
        }
        case Drag::Gizmo:
            dragGizmo(c, pixel({io.MousePos.x, io.MousePos.y}));
            break;
        case Drag::Box:  // drawn from the mouse; selects at the release
        case Drag::Place:
        case Drag::None:
            break;
    }
}

// "Move object", "Rotate group", "Scale 3 items": what the drag does to what it holds.
static std::string dragLabel(HandleKind k, const GizmoHold& h) {
    const char* verb = k == HandleKind::Ring    ? "Rotate "
                       : k == HandleKind::Scale ? "Scale "
                                                : "Move ";
    if (h.items.size() == 1) return verb + std::string(itemKindName(h.items[0].kind));
    return verb + std::to_string(h.items.size()) + " items";
}

// Each frame applies the whole drag so far to the items as they were at the press.
void ViewportInput::dragGizmo(UiContext& c, glm::vec2 at) {
    GizmoDelta d;
    if (!gizmo_.follow(c.editor.scene().camera, at, view_, ImGui::GetIO().KeyCtrl, &d)) return;
    if (held_.kind == ItemKind::Light)
        return c.editor.moveLight(held_.index, heldLight_ + d.move, dragKey());
    c.editor.dragSelection(hold_, d, dragLabel(gizmo_.handle.kind, hold_), dragKey());
}

// Select the light marker or the object under the click (a marker is drawn over the scene, so
// it comes first). A second click on the active object climbs to its group (Editor::pick).
void ViewportInput::click(UiContext& c, glm::vec2 at, bool shift) {
    const int light = pickLightMarker(c.editor.scene(), at, view_, GizmoSettings{}.markerPixels);
    if (light >= 0) {
        c.editor.select(ItemKind::Light, light);
        c.ui.showLights = true;  // its fields, as the Objects panel shows a clicked object's
        return;
    }
    c.editor.pick(at, view_, shift ? Editor::Pick::Toggle : Editor::Pick::Climb);
}

void ViewportInput::release(UiContext& c) {
    ImGuiIO& io = ImGui::GetIO();
    const glm::vec2 at = pixel({io.MousePos.x, io.MousePos.y});
    // A left press that never became a drag is a click; with Shift (a pan's start) it adds or
    // removes what it hits.
    const bool clicked = button_ == ImGuiMouseButton_Left && !moved_;
    if (clicked && (drag_ == Drag::Orbit || drag_ == Drag::Box || drag_ == Drag::Pan))
        click(c, at, drag_ == Drag::Pan);
    if (drag_ == Drag::Box && !clicked)
        c.editor.selectItems(objectsInBox(c.editor.scene(), boxFrom_, at, view_), boxExtends_);
    if (drag_ == Drag::Move || drag_ == Drag::Gizmo) c.editor.endEdit();
    ground_.end();
    drag_ = Drag::None;
}

// View pixels (from the bottom, framebuffer) to ImGui's window coordinates.
static ImVec2 toWindow(glm::vec2 px, glm::vec2 view, glm::vec2 scale) {
    return ImVec2(px.x / scale.x, (view.y - px.y) / scale.y);
}

void ViewportInput::drawSelection(const UiContext& c) const {
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    const ImU32 orange = IM_COL32(255, 153, 25, 255);  // the outline's colour
    if (drag_ == Drag::Box && moved_) {
        const ImVec2 to = ImGui::GetIO().MousePos;
        const ImVec2 from = toWindow(boxFrom_, view_, scale_);
        dl->AddRectFilled(from, to, IM_COL32(255, 153, 25, 40));
        dl->AddRect(from, to, orange, 0.0f, 0, 1.5f);
    }
    const Selection& sel = c.editor.selection();
    const std::vector<Item> items = treeItems(sel);
    const bool outlined = items.size() == 1 && sel.is(ItemKind::Object, items[0].index);
    if (c.editor.followsPath() || items.empty() || outlined) return;
    const Scene& s = c.editor.scene();
    const SceneSdf sdf = makeSceneSdf(s);
    for (Item it : items) {
        if (sel.is(it.kind, it.index) && it.kind == ItemKind::Object) continue;  // outlined
        const bool object = it.kind == ItemKind::Object;
        const glm::vec3 centre =
            object ? sdf.objects[size_t(it.index)].pos : sdf.groups[size_t(it.index)].pos;
        const float bound =
            object ? sdf.objects[size_t(it.index)].bound : sdf.groups[size_t(it.index)].bound;
        glm::vec2 at;
        if (!projectToPixel(s.camera, centre, view_, &at)) continue;
        const float r = bound / metresPerPixel(s.camera, centre, view_.y) / scale_.y;
        dl->AddCircle(toWindow(at, view_, scale_), std::max(r, 4.0f), orange, 0,
                      sel.is(it.kind, it.index) ? 2.5f : 1.5f);
    }
}

// As in Blender, the copies move with the mouse over the ground at their height from where
// their originals stand: a click with the mouse unmoved puts each on its original. Esc leaves
// them where Duplicate put them, beside.
void ViewportInput::beginPlacing(UiContext& c) {
    const ImGuiIO& io = ImGui::GetIO();
    const Scene& s = c.editor.scene();
    const Selection& sel = c.editor.selection();
    const glm::vec2 at = pixel({io.MousePos.x, io.MousePos.y});
    if (drag_ != Drag::None || !ImGui::IsMousePosValid() ||
        !ground_.begin(s, Item{sel.kind, sel.index}, at, view_) ||
        !ground_.follow(s.camera, at, view_, &placedFrom_))
        return;
    held_ = sel;
    hold_ = holdSelection(s, held_);
    drag_ = Drag::Place;
    ++moves_;
    emitEvent("placing");
}

void ViewportInput::place(UiContext& c) {
    const ImGuiIO& io = ImGui::GetIO();
    const bool drop = ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false) ||
                      ImGui::IsMouseClicked(ImGuiMouseButton_Right);
    GizmoDelta d;
    glm::vec3 pos;
    if (!drop &&
        ground_.follow(c.editor.scene().camera, pixel({io.MousePos.x, io.MousePos.y}), view_, &pos))
        d.move = pos - placedFrom_ - kCopyAside;
    c.editor.dragSelection(hold_, d, "Place copies", dragKey());
    if (!drop && !ImGui::IsMouseClicked(ImGuiMouseButton_Left)) return;
    c.editor.endEdit();
    ground_.end();
    drag_ = Drag::None;
    emitEvent(drop ? "placing dropped" : "placed");
}

void ViewportInput::keys(UiContext& c, float seconds) {
    ImGuiIO& io = ImGui::GetIO();
    // Ctrl and Shift make W, A, S, D shortcuts (Ctrl+S, Shift+D), not flight, and a key keeps
    // the meaning it went down with: Ctrl let go before S after Ctrl+S must not fly backwards.
    const bool flight = !io.WantCaptureKeyboard && !io.KeyCtrl && !io.KeyShift;
    for (size_t i = 0; i < kFlyKeys.size(); ++i) {
        if (!ImGui::IsKeyDown(kFlyKeys[i])) flying_[i] = false;
        else if (ImGui::IsKeyPressed(kFlyKeys[i], false)) flying_[i] = flight;
    }
    if (!flight) return;
    auto axis = [&](size_t minus, size_t plus) {
        return float(flying_[plus]) - float(flying_[minus]);
    };
    const glm::vec3 move(axis(0, 1), axis(2, 3), axis(4, 5));
    if (move != glm::vec3(0.0f)) flyCamera(c.editor.view(), move, seconds, controls_);
}

}  // namespace mb
