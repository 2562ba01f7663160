// offscreen_context.cpp — OSMesa, loaded with dlopen so that it never shadows the window's libGL,
// or EGL (egl_context.cpp), behind one OffscreenContext.
#include "marchbox/gl/offscreen_context.h"

#include "marchbox/gl/gl.h"

#include "egl_context.h"

#ifndef GLAPI
#define GLAPI extern  // glew.h undefines it; osmesa.h declares with it
#endif
#include <GL/osmesa.h>
#include <cstring>
#include <dlfcn.h>
#include <utility>

namespace mb {

namespace {

struct OsMesaApi {
    void* lib = nullptr;
    OSMesaContext(GLAPIENTRY* createContextAttribs)(const int*, OSMesaContext) = nullptr;
    GLboolean(GLAPIENTRY* makeCurrent)(OSMesaContext, void*, GLenum, GLsizei, GLsizei) = nullptr;
    void(GLAPIENTRY* destroyContext)(OSMesaContext) = nullptr;
    OSMesaContext(GLAPIENTRY* getCurrentContext)() = nullptr;
    OSMESAproc(GLAPIENTRY* getProcAddress)(const char*) = nullptr;
};

OsMesaApi g_osmesa;

template <typename F>
void bind(F& fn, const char* name) {
    fn = reinterpret_cast<F>(dlsym(g_osmesa.lib, name));
}

bool openOsMesa(std::string* error) {
    if (g_osmesa.lib) return true;
    void* lib = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
    if (!lib) lib = dlopen("libOSMesa.so", RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
        *error = "cannot load OSMesa (install libosmesa6): " + std::string(dlerror());
        return false;
    }
    g_osmesa.lib = lib;
    bind(g_osmesa.createContextAttribs, "OSMesaCreateContextAttribs");
    bind(g_osmesa.makeCurrent, "OSMesaMakeCurrent");
    bind(g_osmesa.destroyContext, "OSMesaDestroyContext");
    bind(g_osmesa.getCurrentContext, "OSMesaGetCurrentContext");
    bind(g_osmesa.getProcAddress, "OSMesaGetProcAddress");
    if (!g_osmesa.createContextAttribs || !g_osmesa.makeCurrent || !g_osmesa.getProcAddress) {
        *error = "OSMesa lacks OSMesaCreateContextAttribs";
        return false;
    }
    return true;
}

}  // namespace

void* offscreenProcAddress(const char* name) {
    // GLEW asks for GLX entry points too; EGL would hand back a stub for any name, so those
    // go to the real GLX, which reports no display and leaves GLEW's GL part loaded.
    if (std::strncmp(name, "glX", 3) == 0) return nullptr;
    if (g_osmesa.lib && g_osmesa.getCurrentContext())
        return reinterpret_cast<void*>(g_osmesa.getProcAddress(name));
    return egl::procAddress(name);
}

bool parseBackend(const std::string& s, OffscreenBackend* out) {
    if (s == "osmesa") return *out = OffscreenBackend::OsMesa, true;
    if (s == "egl") return *out = OffscreenBackend::Egl, true;
    return false;
}

OffscreenContext::~OffscreenContext() { destroy(); }

OffscreenContext::OffscreenContext(OffscreenContext&& o) noexcept
    : context_(std::exchange(o.context_, nullptr)),
      backend_(o.backend_),
      platform_(std::move(o.platform_)),
      buffer_(std::move(o.buffer_)) {}

OffscreenContext& OffscreenContext::operator=(OffscreenContext&& o) noexcept {
    if (this != &o) {
        destroy();
        context_ = std::exchange(o.context_, nullptr);
        backend_ = o.backend_;
        platform_ = std::move(o.platform_);
        buffer_ = std::move(o.buffer_);
    }
    return *this;
}

void OffscreenContext::destroy() {
    if (!context_) return;
    if (backend_ == OffscreenBackend::Egl) egl::destroy(context_);
    else g_osmesa.destroyContext(static_cast<OSMesaContext>(context_));
    context_ = nullptr;
}

bool OffscreenContext::create(int width, int height, std::string* error, OffscreenBackend backend) {
    destroy();
    backend_ = backend;
    if (backend == OffscreenBackend::Egl) {
        if (!egl::create(&context_, &platform_, error)) return false;
        if (loadGl(true, error)) return true;
        destroy();
        return false;
    }
    platform_ = "OSMesa";
    if (!openOsMesa(error)) return false;
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           0,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           3,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           3,
                           0};
    OSMesaContext ctx = g_osmesa.createContextAttribs(attribs, nullptr);
    if (!ctx) {
        *error = "cannot create an OSMesa OpenGL 3.3 core context";
        return false;
    }
    context_ = ctx;
    buffer_.assign(size_t(width) * height * 4, 0);
    if (!g_osmesa.makeCurrent(ctx, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
        *error = "cannot make the OSMesa context current";
        destroy();
        return false;
    }
    if (!loadGl(true, error)) {
        destroy();
        return false;
    }
    return true;
}

}  // namespace mb
