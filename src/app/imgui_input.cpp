// imgui_input.cpp — Dear ImGui 1.86's IO set from the window's InputState.
#include "imgui_input.h"

#include "widgets.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cfloat>

namespace mb {

namespace {

constexpr float kDoubleClickSeconds = 0.30f;  // ImGui's own default
constexpr double kLeastDeltaSeconds = 1e-6;   // ImGui needs time to pass between frames

bool eitherDown(const InputState& s, int left, int right) {
    return s.keys[size_t(left)] || s.keys[size_t(right)];
}

}  // namespace

void feedImGui(const InputState& s, double pollSeconds) {
    ImGuiIO& io = ImGui::GetIO();
    static_assert(IM_ARRAYSIZE(io.MouseDown) <= InputState::kButtons);
    static_assert(IM_ARRAYSIZE(io.KeysDown) == InputState::kKeys);
    io.MousePos = s.mouseIn ? ImVec2(s.mouse.x, s.mouse.y) : ImVec2(-FLT_MAX, -FLT_MAX);
    for (int b = 0; b < IM_ARRAYSIZE(io.MouseDown); ++b) io.MouseDown[b] = s.buttons[size_t(b)];
    io.MouseWheelH += s.wheel.x;
    io.MouseWheel += s.wheel.y;
    for (int k = 0; k < InputState::kKeys; ++k) io.KeysDown[k] = s.keys[size_t(k)];
    io.KeyCtrl = eitherDown(s, GLFW_KEY_LEFT_CONTROL, GLFW_KEY_RIGHT_CONTROL);
    io.KeyShift = eitherDown(s, GLFW_KEY_LEFT_SHIFT, GLFW_KEY_RIGHT_SHIFT);
    io.KeyAlt = eitherDown(s, GLFW_KEY_LEFT_ALT, GLFW_KEY_RIGHT_ALT);
    io.KeySuper = eitherDown(s, GLFW_KEY_LEFT_SUPER, GLFW_KEY_RIGHT_SUPER);
    for (unsigned c : s.text) io.AddInputCharacter(c == ',' && !typingText() ? '.' : c);
    // ImGui times clicks on its own clock, which here follows the events' stamps. A stamp is
    // the poll after the event, up to one poll late: a double-click may look that much slower.
    io.DeltaTime = float(std::max(s.seconds, kLeastDeltaSeconds));
    io.MouseDoubleClickTime = kDoubleClickSeconds + float(pollSeconds);
}

}  // namespace mb
