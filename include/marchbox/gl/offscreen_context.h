// marchbox/gl/offscreen_context.h — an OpenGL core context with no window, through OSMesa.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace mb {

// Owns one OSMesa context and its RGBA colour buffer. Move-only; current after create().
class OffscreenContext {
public:
    OffscreenContext() = default;
    ~OffscreenContext();
    OffscreenContext(OffscreenContext&& o) noexcept;
    OffscreenContext& operator=(OffscreenContext&& o) noexcept;
    OffscreenContext(const OffscreenContext&) = delete;
    OffscreenContext& operator=(const OffscreenContext&) = delete;

    // Creates a core-profile context with a width×height buffer, makes it current and loads GL.
    bool create(int width, int height, std::string* error);
    bool valid() const { return context_ != nullptr; }

private:
    void destroy();
    void* context_ = nullptr;          // OSMesaContext
    std::vector<unsigned char> buffer_;
};

// Called by glXGetProcAddressARB while an OSMesa context is current, else null.
void* offscreenProcAddress(const char* name);

}  // namespace mb
