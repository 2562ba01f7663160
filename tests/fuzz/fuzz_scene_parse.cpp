// fuzz_scene_parse.cpp — libFuzzer target: parseScene on arbitrary bytes.
//
// The parser must return, without a sanitizer report, and either succeed with no errors or
// fail with at least one error, in line order, each within the text's line count.
#include "marchbox/scene/scene_io.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    mb::Scene scene;
    std::vector<mb::SceneError> errors;
    bool ok = mb::parseScene(text, &scene, &errors);
    // abort() turns a broken promise into a finding libFuzzer saves, like a crash.
    if (ok != errors.empty()) std::abort();
    const int lines = int(std::count(text.begin(), text.end(), '\n')) + 1;
    int last = 0;
    for (const mb::SceneError& e : errors) {
        if (e.line < last || e.line < 1 || e.line > lines || e.message.empty()) std::abort();
        last = e.line;
    }
    return 0;
}
