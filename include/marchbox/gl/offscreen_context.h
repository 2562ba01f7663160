// marchbox/gl/offscreen_context.h — an OpenGL core context with no window, through OSMesa or EGL.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace mb {

// OSMesa renders on the CPU everywhere (CI's default); EGL reaches a GPU through its device
// platform, or Mesa's surfaceless platform without one (and on Mesa 25.1+, which has no OSMesa).
enum class OffscreenBackend { OsMesa, Egl };
bool parseBackend(const std::string& s, OffscreenBackend* out);  // "osmesa" or "egl"

// Owns one OSMesa or EGL context (and OSMesa's RGBA buffer). Move-only; current after create().
class OffscreenContext {
public:
    OffscreenContext() = default;
    ~OffscreenContext();
    OffscreenContext(OffscreenContext&& o) noexcept;
    OffscreenContext& operator=(OffscreenContext&& o) noexcept;
    OffscreenContext(const OffscreenContext&) = delete;
    OffscreenContext& operator=(const OffscreenContext&) = delete;

    // Creates a core-profile context, makes it current and loads GL. OSMesa draws the default
    // framebuffer into a width × height buffer; EGL has no default framebuffer at all.
    bool create(int width, int height, std::string* error,
                OffscreenBackend backend = OffscreenBackend::OsMesa);
    bool valid() const { return context_ != nullptr; }
    const std::string& platform() const { return platform_; }  // for reports: what drew

private:
    void destroy();
    void* context_ = nullptr;  // OSMesaContext or EGLContext
    OffscreenBackend backend_ = OffscreenBackend::OsMesa;
    std::string platform_;
    std::vector<unsigned char> buffer_;
};

// Called by glXGetProcAddressARB while an OSMesa or EGL context is current, else null.
void* offscreenProcAddress(const char* name);

}  // namespace mb
