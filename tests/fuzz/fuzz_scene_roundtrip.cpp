// fuzz_scene_roundtrip.cpp — libFuzzer target: whatever parses must survive a save.
//
// SCENE_FORMAT.md promises load → save → load gives the identical scene and saving twice gives
// identical bytes. formatScene's text is checked against both promises for every input that
// parses; a difference aborts, which libFuzzer records like a crash.
#include "marchbox/scene/scene_io.h"

#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    mb::Scene first;
    if (!mb::parseScene(text, &first, nullptr)) return 0;
    const std::string saved = mb::formatScene(first);
    mb::Scene second;
    if (!mb::parseScene(saved, &second, nullptr)) std::abort();  // the saver wrote bad text
    if (!(second == first)) std::abort();                        // a value changed on the way
    if (mb::formatScene(second) != saved) std::abort();          // bytes drift between saves
    return 0;
}
