// egl_context.h — the EGL side of OffscreenContext (private to src/gl): a core context with no
// surface, on the GPU's device platform when there is one, else Mesa's surfaceless platform.
#pragma once

#include <string>

namespace mb::egl {

bool create(void** context, std::string* platform, std::string* error);
void destroy(void* context);
void* procAddress(const char* name);  // null unless an EGL context is current

}  // namespace mb::egl
