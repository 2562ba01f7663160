// imgui_input.h — one frame of the window's queued input, given to Dear ImGui.
//
// ImGui's GLFW backend (installed without its callbacks) still sizes the display, keeps the
// clipboard and sets the mouse cursor's shape; the mouse, keys, text and ImGui's clock come
// from here instead, so a press and release inside one slow frame are seen as two frames.
#pragma once

#include "marchbox/editor/input_queue.h"

namespace mb {

// Sets ImGui's input to `s`. Call it between ImGui_ImplGlfw_NewFrame, which reads the mouse
// from GLFW as it is now, and ImGui::NewFrame. pollSeconds: the time between the last two
// polls of the window, which is how far apart two events stamped at their poll may look.
void feedImGui(const InputState& s, double pollSeconds);

}  // namespace mb
