// controls.cpp — the editor's keys and mouse actions, in the order Help > Controls shows them.
#include "marchbox/editor/controls.h"

namespace mb {

static const Control kControls[] = {
    {"Left drag", "orbit the camera about its target"},
    {"Wheel", "zoom; over a panel, scroll it"},
    {"Middle drag, Shift drag", "pan"},
    {"W A S D, Q E", "fly"},
    {"1", "orbit preview on or off"},
    {"Left click", "select the object under the mouse; again, its group, then the one above"},
    {"Shift+click", "add the object under the mouse to the selection, or take it out"},
    {"Right click", "edit the object under the mouse"},
    {"Left drag a handle", "move, rotate or scale the selection (one undo step per drag)"},
    {"G, R, T", "move, rotate or scale handles"},
    {"Ctrl, dragging a handle", "snap: 0.1 m, 15 degrees, a tenth of the size"},
    {"Click a light's marker", "select the light and show Lights; drag its handles to move it"},
    {"Ctrl drag",
     "move the object under the mouse, or the selected group holding it, over the ground"},
    {"Ctrl drag in empty space",
     "select the objects whose centres the box covers; Shift adds them"},
    {"Ctrl+A, [",
     "select every top-level object and group; select the group holding the selection"},
    {"Ctrl+G, Ctrl+Alt+G",
     "group the selection; ungroup the selected groups, each where it stands"},
    {"Delete", "delete the selection, a group with everything in it"},
    {"J", "random velocities for the dynamic bodies"},
    {"Space", "play or pause the simulation"},
    {"Shift+Left; Home over the timeline", "back to t = 0, keeping the run to scrub forward again"},
    {"Home, numpad .", "frame all objects, frame the selection (over the view)"},
    {"Ctrl+Z, Ctrl+Y", "undo, redo (a simulation run is one step); Ctrl+Shift+Z redoes too"},
    {"Ctrl+N, Ctrl+O, Ctrl+S", "new, open, save"},
    {"Ctrl+Shift+S", "save as"},
    {"F", "fog on or off, in a scene with fog (render fog above 0)"},
    {"P", "FXAA on or off"},
    {"F12", "screenshot (PNG)"},
    {"Esc", "close the open menu, popup or dialog; it never quits"},
    {"Ctrl+Q", "quit, asking first about unsaved changes, as the window's close button does"},
    {"Drop a file", "open the scene file dropped on the window"},
};

std::span<const Control> editorControls() { return kControls; }

}  // namespace mb
