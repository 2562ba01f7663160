// controls.cpp — the editor's keys and mouse actions, in the order Help > Controls shows them.
#include "marchbox/editor/controls.h"

namespace mb {

static const Control kControls[] = {
    {"Left drag", "orbit the camera about its target"},
    {"Wheel", "zoom; over a panel, scroll it"},
    {"Middle drag", "pan (or Shift with the left button)"},
    {"W A S D, Q E", "fly"},
    {"1", "orbit preview on or off"},
    {"Click", "select the object; again, its group, then the next up"},
    {"Shift+click", "add the object to the selection, or take it out"},
    {"Right click", "edit the object under the mouse"},
    {"Drag a handle", "move, rotate or scale the selection"},
    {"G, R, T", "move, rotate or scale handles"},
    {"Ctrl on handle", "snap: 0.1 m, 15 degrees, a tenth of the size"},
    {"Click a light", "select it and show Lights; its handles move it"},
    {"Ctrl drag", "move the object (or its selected group) on the ground"},
    {"Ctrl box drag", "select the objects whose centres it covers; Shift adds"},
    {"Ctrl+A", "select every top-level object and group"},
    {"[", "select the group holding the selection"},
    {"Ctrl+G", "group the selection"},
    {"Ctrl+Alt+G", "ungroup the selected groups, each where it stands"},
    {"Shift+D", "duplicate; the copies follow the mouse until a click"},
    {"Ctrl+C, Ctrl+V", "copy, paste the selection as scene text"},
    {"Delete", "delete the selection, a group with all inside it"},
    {"Click a number", "type a value; a drag changes it"},
    {"J", "random velocities for the dynamic bodies"},
    {"Space", "play or pause; playing stops once all is at rest"},
    {"Shift+Left", "back to t = 0 (Home over the timeline too)"},
    {"Home, numpad .", "frame all, frame the selection, beside the panels"},
    {"Ctrl+Z, Ctrl+Y", "undo, redo (Ctrl+Shift+Z too); a run is one step"},
    {"Ctrl+N, Ctrl+O", "new, open"},
    {"Ctrl+S", "save; asks first if the file changed on disk"},
    {"Ctrl+Shift+S", "save as"},
    {"F", "fog on or off, in a scene with fog"},
    {"P", "FXAA on or off"},
    {"F12", "screenshot (PNG)"},
    {"Esc", "close the open menu, popup or dialog; never quits"},
    {"Ctrl+Q", "quit, asking first about unsaved changes"},
    {"Drop a file", "open the scene file dropped on the window"},
};

std::span<const Control> editorControls() { return kControls; }

}  // namespace mb
