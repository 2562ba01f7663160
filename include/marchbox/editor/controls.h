// marchbox/editor/controls.h — every key and mouse action of the editor window, once: Help >
// Controls draws this table and docs/editor.md lists the same rows (a test holds the
// two together).
#pragma once

#include <span>

namespace mb {

struct Control {
    const char* keys;    // "Ctrl+Z, Ctrl+Y"
    const char* action;  // "undo, redo (a simulation run is one step)"
};

std::span<const Control> editorControls();

}  // namespace mb
