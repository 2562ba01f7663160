// gl_loader.cpp — GLEW through glXGetProcAddressARB, forwarded to the off-screen context (OSMesa
// or EGL) while one is current.
#include "marchbox/gl/gl.h"

#include "marchbox/gl/offscreen_context.h"

#include <cstring>
#include <dlfcn.h>

namespace mb {

Gl11 gl11;

}  // namespace mb

using ProcFn = void (*)();

// Debian's GLEW resolves every function through this symbol. Defining it here, in the
// executable, puts OSMesa in front while an off-screen context is current; otherwise the
// window system's own function (found with RTLD_NEXT) answers.
extern "C" ProcFn glXGetProcAddressARB(const unsigned char* name) {
    if (void* p = mb::offscreenProcAddress(reinterpret_cast<const char*>(name)))
        return reinterpret_cast<ProcFn>(p);
    using Real = ProcFn (*)(const unsigned char*);
    static Real real = reinterpret_cast<Real>(dlsym(RTLD_NEXT, "glXGetProcAddressARB"));
    return real ? real(name) : nullptr;
}

namespace mb {

template <typename F>
static bool loadFn(F& fn, const char* name) {
    fn = reinterpret_cast<F>(glXGetProcAddressARB(reinterpret_cast<const unsigned char*>(name)));
    return fn != nullptr;
}

static bool loadGl11() {
    return loadFn(gl11.Clear, "glClear") && loadFn(gl11.ClearColor, "glClearColor") &&
           loadFn(gl11.Viewport, "glViewport") && loadFn(gl11.Scissor, "glScissor") &&
           loadFn(gl11.Enable, "glEnable") && loadFn(gl11.Disable, "glDisable") &&
           loadFn(gl11.DrawElements, "glDrawElements") && loadFn(gl11.ReadPixels, "glReadPixels") &&
           loadFn(gl11.PixelStorei, "glPixelStorei") && loadFn(gl11.GetIntegerv, "glGetIntegerv") &&
           loadFn(gl11.GetString, "glGetString") && loadFn(gl11.GetError, "glGetError") &&
           loadFn(gl11.Finish, "glFinish") && loadFn(gl11.GenTextures, "glGenTextures") &&
           loadFn(gl11.DeleteTextures, "glDeleteTextures") &&
           loadFn(gl11.BindTexture, "glBindTexture") && loadFn(gl11.TexImage2D, "glTexImage2D") &&
           loadFn(gl11.TexParameteri, "glTexParameteri") &&
           loadFn(gl11.DrawArrays, "glDrawArrays") && loadFn(gl11.BlendFunc, "glBlendFunc");
}

bool loadGl(bool offscreen, std::string* error) {
    glewExperimental = GL_TRUE;  // core profiles need it for GLEW to load everything
    GLenum err = glewInit();
    bool noGlx = err == GLEW_ERROR_GLX_VERSION_11_ONLY || err == GLEW_ERROR_NO_GLX_DISPLAY;
    bool ok = err == GLEW_OK || (offscreen && noGlx);
    if (!ok) {
        *error = std::string("cannot load OpenGL functions: ") +
                 reinterpret_cast<const char*>(glewGetErrorString(err));
        return false;
    }
    if (!loadGl11() || !glCreateShader) {
        *error = "the OpenGL driver lacks core functions";
        return false;
    }
    glGetError();  // glewInit may leave GL_INVALID_ENUM behind on core profiles
    return true;
}

}  // namespace mb
