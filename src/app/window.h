// window.h — the GLFW window with its OpenGL 3.3 core context, vsync on.
#pragma once

#include "marchbox/editor/input_queue.h"

#include <string>
#include <vector>

struct GLFWwindow;

namespace mb {

class Window {
public:
    Window() = default;
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    // Opens the window, makes its context current and loads GL through GLEW. Its input
    // callbacks queue every event; ImGui's backend installs none (see imgui_input.h).
    bool create(const std::string& title, int width, int height, std::string* error);

    GLFWwindow* handle() const { return window_; }
    void framebufferSize(int* width,
                         int* height) const;  // pixels: differs from the window on HiDPI
    void setTitle(const std::string& title);
    bool closeRequested() const;  // the window's close button
    void clearCloseRequest();
    std::vector<std::string> takeDrops();   // paths dropped on the window since the last call
    InputQueue& input() { return input_; }  // mouse, keys and text, in the order they came
    void swap();

private:
    static void onDrop(GLFWwindow* w, int count, const char** paths);
    static void onMove(GLFWwindow* w, double x, double y);
    static void onEnter(GLFWwindow* w, int entered);
    static void onButton(GLFWwindow* w, int button, int action, int mods);
    static void onScroll(GLFWwindow* w, double x, double y);
    static void onKey(GLFWwindow* w, int key, int scancode, int action, int mods);
    static void onChar(GLFWwindow* w, unsigned int codepoint);
    GLFWwindow* window_ = nullptr;
    bool glfwUp_ = false;
    std::string title_;
    std::vector<std::string> drops_;
    InputQueue input_;
};

}  // namespace mb
