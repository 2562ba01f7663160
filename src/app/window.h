// window.h — the GLFW window with its OpenGL 3.3 core context, vsync on.
#pragma once

#include <string>
#include <vector>

struct GLFWwindow;

namespace mb {

// A key going down. Kept in a queue because a tap shorter than a frame (a slow software
// renderer, a script) would otherwise be seen neither down nor up.
struct KeyPress {
    int key;   // GLFW_KEY_*
    int mods;  // GLFW_MOD_*
};

class Window {
public:
    Window() = default;
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    // Opens the window, makes its context current and loads GL through GLEW. Its callbacks are
    // installed here, before ImGui's backend, which chains to them.
    bool create(const std::string& title, int width, int height, std::string* error);

    GLFWwindow* handle() const { return window_; }
    void framebufferSize(int* width, int* height) const;  // pixels: differs from the window on HiDPI
    void setTitle(const std::string& title);
    bool closeRequested() const;  // the window's close button
    void clearCloseRequest();
    std::vector<std::string> takeDrops();  // paths dropped on the window since the last call
    std::vector<KeyPress> takeKeys();      // keys pressed since the last call
    void swap();

private:
    static void onDrop(GLFWwindow* w, int count, const char** paths);
    static void onKey(GLFWwindow* w, int key, int scancode, int action, int mods);
    GLFWwindow* window_ = nullptr;
    bool glfwUp_ = false;
    std::string title_;
    std::vector<std::string> drops_;
    std::vector<KeyPress> keys_;
};

}  // namespace mb
