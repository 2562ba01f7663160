// window.cpp — GLFW setup and teardown.
#include "window.h"

#include "marchbox/gl/gl.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace mb {

static std::string gGlfwError;

Window::~Window() {
    if (window_) glfwDestroyWindow(window_);
    if (glfwUp_) glfwTerminate();
}

bool Window::create(const std::string& title, int width, int height, std::string* error) {
    glfwSetErrorCallback([](int, const char* text) { gGlfwError = text; });
    if (!(glfwUp_ = glfwInit())) {
        *error = "cannot start GLFW: " + gGlfwError;
        return false;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        *error = "cannot open an OpenGL 3.3 window: " + gGlfwError;
        return false;
    }
    title_ = title;
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);  // vsync: the editor need not draw faster than the screen shows
    glfwSetWindowUserPointer(window_, this);
    glfwSetDropCallback(window_, onDrop);
    // No focus callback: GLFW releases the keys and buttons held when the window loses focus.
    glfwSetCursorPosCallback(window_, onMove);
    glfwSetCursorEnterCallback(window_, onEnter);
    glfwSetMouseButtonCallback(window_, onButton);
    glfwSetScrollCallback(window_, onScroll);
    glfwSetKeyCallback(window_, onKey);
    glfwSetCharCallback(window_, onChar);
    return loadGl(false, error);
}

void Window::framebufferSize(int* width, int* height) const {
    glfwGetFramebufferSize(window_, width, height);
}

void Window::setTitle(const std::string& title) {
    if (title == title_) return;  // the title is set every frame; X11 need not hear it
    title_ = title;
    glfwSetWindowTitle(window_, title.c_str());
}

bool Window::closeRequested() const { return glfwWindowShouldClose(window_); }
void Window::clearCloseRequest() { glfwSetWindowShouldClose(window_, GLFW_FALSE); }

std::vector<std::string> Window::takeDrops() {
    std::vector<std::string> out;
    out.swap(drops_);
    return out;
}

void Window::swap() { glfwSwapBuffers(window_); }

void Window::onDrop(GLFWwindow* w, int count, const char** paths) {
    auto* self = static_cast<Window*>(glfwGetWindowUserPointer(w));
    for (int i = 0; i < count; ++i) self->drops_.push_back(paths[i]);
}

// Each event is stamped with the time it is received: during the poll that follows it.
static void enqueue(GLFWwindow* w, InputEvent e) {
    e.time = glfwGetTime();
    static_cast<Window*>(glfwGetWindowUserPointer(w))->input().push(e);
}

void Window::onMove(GLFWwindow* w, double x, double y) {
    enqueue(w, {.kind = InputEvent::Kind::Move, .at = {float(x), float(y)}});
}

void Window::onEnter(GLFWwindow* w, int entered) {
    if (!entered) enqueue(w, {.kind = InputEvent::Kind::Leave});  // entering also moves the mouse
}

void Window::onButton(GLFWwindow* w, int button, int action, int) {
    enqueue(w, {.kind = InputEvent::Kind::Button, .code = button, .down = action == GLFW_PRESS});
}

void Window::onScroll(GLFWwindow* w, double x, double y) {
    enqueue(w, {.kind = InputEvent::Kind::Wheel, .at = {float(x), float(y)}});
}

void Window::onKey(GLFWwindow* w, int key, int, int action, int mods) {
    if (action == GLFW_REPEAT) return;  // ImGui repeats held keys itself
    enqueue(
        w,
        {.kind = InputEvent::Kind::Key, .code = key, .down = action == GLFW_PRESS, .mods = mods});
}

void Window::onChar(GLFWwindow* w, unsigned int codepoint) {
    enqueue(w, {.kind = InputEvent::Kind::Text, .code = int(codepoint)});
}

}  // namespace mb
