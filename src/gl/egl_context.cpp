// egl_context.cpp — EGL loaded with dlopen, so machines without it still run the OSMesa path.
#include "egl_context.h"

#define EGL_NO_X11  // no window system here: keep Xlib out of eglplatform.h
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <cstring>
#include <dlfcn.h>

namespace mb::egl {

namespace {

struct Api {
    void* lib = nullptr;
    EGLDisplay display = EGL_NO_DISPLAY;
    PFNEGLGETPROCADDRESSPROC getProcAddress = nullptr;
    PFNEGLGETCURRENTCONTEXTPROC currentContext = nullptr;
};
Api g_api;

template <typename F>
F load(const char* name) {
    return reinterpret_cast<F>(g_api.getProcAddress(name));
}

bool open(std::string* error) {
    if (g_api.lib) return true;
    g_api.lib = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!g_api.lib)
        return *error = "cannot load EGL (install libegl1): " + std::string(dlerror()), false;
    g_api.getProcAddress =
        reinterpret_cast<PFNEGLGETPROCADDRESSPROC>(dlsym(g_api.lib, "eglGetProcAddress"));
    if (!g_api.getProcAddress) return *error = "libEGL has no eglGetProcAddress", false;
    g_api.currentContext = load<PFNEGLGETCURRENTCONTEXTPROC>("eglGetCurrentContext");
    return true;
}

// A hardware device if the driver lists one (not Mesa's software device), else null.
EGLDeviceEXT hardwareDevice() {
    auto queryDevices = load<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
    auto queryString = load<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (!queryDevices || !queryString || !queryDevices(16, devices, &count)) return nullptr;
    for (EGLint i = 0; i < count; ++i) {
        const char* ext = queryString(devices[i], EGL_EXTENSIONS);
        if (!ext || !std::strstr(ext, "EGL_MESA_device_software")) return devices[i];
    }
    return nullptr;
}

bool openDisplay(std::string* platform, std::string* error) {
    auto getDisplay = load<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
    auto initialize = load<PFNEGLINITIALIZEPROC>("eglInitialize");
    if (!getDisplay || !initialize) return *error = "EGL lacks eglGetPlatformDisplayEXT", false;
    EGLDeviceEXT device = hardwareDevice();
    g_api.display = device
                        ? getDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr)
                        : getDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    *platform = device ? "EGL device" : "EGL surfaceless";
    EGLint major = 0, minor = 0;
    if (g_api.display == EGL_NO_DISPLAY || !initialize(g_api.display, &major, &minor))
        return *error = "cannot initialise the " + *platform + " display", false;
    return true;
}

}  // namespace

bool create(void** context, std::string* platform, std::string* error) {
    if (!open(error) || !openDisplay(platform, error)) return false;
    auto bindApi = load<PFNEGLBINDAPIPROC>("eglBindAPI");
    auto chooseConfig = load<PFNEGLCHOOSECONFIGPROC>("eglChooseConfig");
    auto createContext = load<PFNEGLCREATECONTEXTPROC>("eglCreateContext");
    auto makeCurrent = load<PFNEGLMAKECURRENTPROC>("eglMakeCurrent");
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                     3,
                                     EGL_CONTEXT_MINOR_VERSION,
                                     3,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_NONE};
    // No surface means no config is needed (EGL_KHR_no_config_context) where none matches.
    EGLConfig config = EGL_NO_CONFIG_KHR;
    EGLint configs = 0;
    if (!bindApi(EGL_OPENGL_API))
        return *error = "the " + *platform + " display has no OpenGL", false;
    if (!chooseConfig(g_api.display, configAttribs, &config, 1, &configs) || !configs)
        config = EGL_NO_CONFIG_KHR;
    EGLContext ctx = createContext(g_api.display, config, EGL_NO_CONTEXT, contextAttribs);
    if (ctx == EGL_NO_CONTEXT)
        return *error = "cannot create an OpenGL 3.3 core context on " + *platform, false;
    // No surface: every pixel goes to the renderer's framebuffer objects.
    if (!makeCurrent(g_api.display, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
        destroy(ctx);
        return *error = "cannot make the " + *platform + " context current", false;
    }
    *context = ctx;
    return true;
}

void destroy(void* context) {
    auto makeCurrent = load<PFNEGLMAKECURRENTPROC>("eglMakeCurrent");
    auto destroyContext = load<PFNEGLDESTROYCONTEXTPROC>("eglDestroyContext");
    makeCurrent(g_api.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    destroyContext(g_api.display, static_cast<EGLContext>(context));
}

void* procAddress(const char* name) {
    if (!g_api.lib || !g_api.currentContext || g_api.currentContext() == EGL_NO_CONTEXT)
        return nullptr;
    return reinterpret_cast<void*>(g_api.getProcAddress(name));
}

}  // namespace mb::egl
