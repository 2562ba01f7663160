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
    glfwSetKeyCallback(window_, onKey);
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

std::vector<KeyPress> Window::takeKeys() {
    std::vector<KeyPress> out;
    out.swap(keys_);
    return out;
}

void Window::swap() { glfwSwapBuffers(window_); }

void Window::onDrop(GLFWwindow* w, int count, const char** paths) {
    auto* self = static_cast<Window*>(glfwGetWindowUserPointer(w));
    for (int i = 0; i < count; ++i) self->drops_.push_back(paths[i]);
}

void Window::onKey(GLFWwindow* w, int key, int, int action, int mods) {
    if (action != GLFW_PRESS) return;
    static_cast<Window*>(glfwGetWindowUserPointer(w))->keys_.push_back({key, mods});
}

}  // namespace mb
