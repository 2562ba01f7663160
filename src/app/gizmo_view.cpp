// gizmo_view.cpp — the selection's handles and the point lights' markers, drawn with ImGui's
// background draw list: over the scene's picture, under every panel. Where each goes comes from
// marchbox/editor/gizmo.h, the same numbers the mouse is tested against.
#include "ui.h"

#include "marchbox/editor/events.h"

#include <cmath>
#include <glm/common.hpp>
#include <glm/gtc/constants.hpp>
#include <imgui.h>
#include <vector>

namespace mb {

namespace {

constexpr int kRingPoints = 65;  // 64 segments, as hitGizmo() measures them
const ImU32 kHot = IM_COL32(255, 220, 60, 255);
const ImU32 kSelected = IM_COL32(240, 240, 240, 255);  // a selected light's ring

ImU32 axisColour(int axis, bool hot, int alpha = 255) {
    static const ImU32 rgb[3] = {IM_COL32(230, 70, 70, 0), IM_COL32(110, 210, 70, 0),
                                 IM_COL32(70, 130, 240, 0)};  // x red, y green, z blue
    return (hot ? kHot & ~IM_COL32_A_MASK : rgb[axis]) | ImU32(alpha) << IM_COL32_A_SHIFT;
}

// World points to ImGui's window coordinates: the view's pixels count up from the bottom in
// framebuffer pixels, ImGui's down from the top in window points.
struct Screen {
    const Camera& camera;
    glm::vec2 view, scale;
    bool at(glm::vec3 p, ImVec2* out) const {
        glm::vec2 px;
        if (!projectToPixel(camera, p, view, &px)) return false;
        *out = ImVec2(px.x / scale.x, (view.y - px.y) / scale.y);
        return true;
    }
};

ImVec2 operator+(ImVec2 a, ImVec2 b) { return {a.x + b.x, a.y + b.y}; }
ImVec2 operator*(ImVec2 a, float s) { return {a.x * s, a.y * s}; }

// Move: a line ending in an arrowhead; scale: a line ending in a box.
void drawAxes(ImDrawList* dl, const Screen& s, const GizmoFrame& f, GizmoMode mode, GizmoHandle hot,
              const GizmoSettings& k) {
    const HandleKind kind = mode == GizmoMode::Scale ? HandleKind::Scale : HandleKind::Axis;
    for (int i = 0; i < 3; ++i) {
        ImVec2 from, to;
        const glm::vec3 a = f.axes[i] * f.length;
        if (!handleShown(s.camera, f, {kind, i}, k) || !s.at(f.centre + k.axisFrom * a, &from) ||
            !s.at(f.centre + a, &to))
            continue;
        const ImU32 col = axisColour(i, hot == GizmoHandle{kind, i});
        dl->AddLine(from, to, col, 3.0f);
        if (mode == GizmoMode::Scale) {
            dl->AddRectFilled(to + ImVec2(-5, -5), to + ImVec2(5, 5), col);
            continue;
        }
        glm::vec2 dir(to.x - from.x, to.y - from.y);
        if (glm::dot(dir, dir) < 1.0f) continue;  // end on: no direction to point
        dir = glm::normalize(dir);
        const ImVec2 along(dir.x, dir.y), across(-dir.y, dir.x);
        dl->AddTriangleFilled(to + along * 12.0f, to + across * 5.0f, to + across * -5.0f, col);
    }
}

// Move: a square on each plane, between the axes, in the colour of the axis it moves off.
void drawPlanes(ImDrawList* dl, const Screen& s, const GizmoFrame& f, GizmoHandle hot,
                const GizmoSettings& k) {
    for (int i = 0; i < 3; ++i) {
        const glm::vec3 u = f.axes[(i + 1) % 3] * f.length, v = f.axes[(i + 2) % 3] * f.length;
        const float a = k.planeFrom, b = k.planeTo;
        ImVec2 q[4];
        if (!handleShown(s.camera, f, {HandleKind::Plane, i}, k) ||
            !s.at(f.centre + a * u + a * v, &q[0]) || !s.at(f.centre + b * u + a * v, &q[1]) ||
            !s.at(f.centre + b * u + b * v, &q[2]) || !s.at(f.centre + a * u + b * v, &q[3]))
            continue;
        const bool lit = hot == GizmoHandle{HandleKind::Plane, i};
        dl->AddQuadFilled(q[0], q[1], q[2], q[3], axisColour(i, lit, lit ? 150 : 80));
        dl->AddQuad(q[0], q[1], q[2], q[3], axisColour(i, lit), 1.5f);
    }
}

void drawRings(ImDrawList* dl, const Screen& s, const GizmoFrame& f, GizmoHandle hot) {
    std::vector<ImVec2> points(kRingPoints);
    for (int i = 0; i < 3; ++i) {
        bool whole = true;
        for (int j = 0; j < kRingPoints && whole; ++j)
            whole = s.at(ringPoint(f, i, glm::two_pi<float>() * float(j) / (kRingPoints - 1)),
                         &points[size_t(j)]);
        if (whole)
            dl->AddPolyline(points.data(), kRingPoints,
                            axisColour(i, hot == GizmoHandle{HandleKind::Ring, i}), 0, 2.5f);
    }
}

// A disc in the light's colour with short rays about it; the selected one ringed in white.
void drawLightMarkers(ImDrawList* dl, const Screen& s, const Scene& scene, const Selection& sel,
                      const GizmoSettings& k) {
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& l = scene.lights[i];
        ImVec2 c;
        if (l.directional || !s.at(l.vec, &c)) continue;
        const glm::vec3 rgb = glm::clamp(l.color, 0.0f, 1.0f) * 255.0f;
        const ImU32 fill = IM_COL32(int(rgb.r), int(rgb.g), int(rgb.b), 230);
        const bool selected = sel.is(ItemKind::Light, int(i));
        const float r = k.markerPixels * 0.6f;
        dl->AddCircleFilled(c, r, fill);
        dl->AddCircle(c, r, selected ? kSelected : IM_COL32(20, 20, 20, 255), 0,
                      selected ? 2.5f : 1.5f);
        for (int j = 0; j < 8; ++j) {
            const float a = glm::two_pi<float>() * float(j) / 8.0f;
            const ImVec2 dir(std::cos(a), std::sin(a));
            dl->AddLine(c + dir * (r + 2.0f), c + dir * (k.markerPixels + 3.0f), fill, 1.5f);
        }
    }
}

}  // namespace

void drawGizmo(const UiContext& c, GizmoHandle hot, glm::vec2 viewSize) {
    // While playing along the camera keys the view is not the camera the handles are placed by.
    if (c.editor.followsPath()) return;
    const Scene& scene = c.editor.scene();
    const ImGuiIO& io = ImGui::GetIO();
    const Screen s{
        scene.camera, viewSize, {io.DisplayFramebufferScale.x, io.DisplayFramebufferScale.y}};
    const GizmoSettings k;
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    drawLightMarkers(dl, s, scene, c.editor.selection(), k);
    GizmoFrame f;
    GizmoMode mode;
    if (!selectionGizmo(scene, c.editor.selection(), c.ui.gizmo, viewSize, &f, &mode)) return;
    if (mode == GizmoMode::Move) drawPlanes(dl, s, f, hot, k);
    if (mode == GizmoMode::Rotate) drawRings(dl, s, f, hot);
    else drawAxes(dl, s, f, mode, hot, k);
    // Nothing at the centre itself: the selection's own colour shows there (e2e.select).
}

void setGizmoMode(UiState& ui, GizmoMode m) {
    ui.gizmo = m;
    emitEvent(std::string("gizmo ") + gizmoModeName(m));
}

}  // namespace mb
