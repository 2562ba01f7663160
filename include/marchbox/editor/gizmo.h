// marchbox/editor/gizmo.h — the handles drawn over the selection to move, turn and size it with
// the mouse: where they fall in the view, which one the mouse is over, what a drag of one does.
//
// [SECTION] Projection: world points to view pixels and back
// [SECTION] Handles: their frame in the world, and hit testing
// [SECTION] Drags: a handle held from press to release, and what it does to an object
// [SECTION] Selection: the handles the selected item gets, and the lights' markers
//
// Rules: pixels count from the bottom-left corner of the view, as picking.h's do; angles in
// radians; lengths in metres. Move and turn use the world's axes, size the object's own (a box
// grows along its own edges). Nothing here draws: the window draws what these place.
#pragma once

#include "marchbox/editor/selection.h"
#include "marchbox/scene/scene.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace mb {

enum class GizmoMode : int { Move = 0, Rotate = 1, Scale = 2 };
constexpr int kGizmoModeCount = 3;
const char* gizmoModeName(GizmoMode m);  // "move", "rotate", "scale"

struct GizmoSettings {
    float lengthPixels = 90.0f;  // an axis handle's length on screen, whatever the distance
    float pickPixels = 8.0f;     // how near a line the mouse must come to take it
    float axisFrom = 0.2f;       // axis handles start this far out (a fraction of the length):
                                 // near the centre the axes crowd together, and sizing there
                                 // would divide by almost nothing
    float planeFrom = 0.3f, planeTo = 0.5f;  // the move handles' plane squares, likewise
    // Seen end on, an axis shrinks to a dot over the others and a plane to a sliver, too small
    // to aim at and too steep to drag along: such handles are hidden while the view is so.
    float endOnAxis = 0.95f;         // |cos| of the axis to the view above this: hidden (18°)
    float edgeOnPlane = 0.2f;        // |cos| of the plane's normal to the view below this: hidden
    float snapMetres = 0.1f;         // Ctrl held: moves by whole steps
    float snapRadians = 0.2617994f;  // 15°
    float snapFactor = 0.1f;         // sizes by whole tenths
    float minSize = 0.01f;           // no radius, size or height shrinks below this
    float markerPixels = 9.0f;       // a point light's marker: a disc this radius
};

//-----------------------------------------------------------------------------
// [SECTION] Projection
//-----------------------------------------------------------------------------
// The pixel of `viewSize` that shows world point p: cameraRay() through it points at p. False
// for a point behind the camera (or in its plane), which no pixel shows.
bool projectToPixel(const Camera& c, glm::vec3 p, glm::vec2 viewSize, glm::vec2* pixel);

// The length in metres, at point p, that spans one pixel of a view viewHeight pixels tall.
float metresPerPixel(const Camera& c, glm::vec3 p, float viewHeight);

//-----------------------------------------------------------------------------
// [SECTION] Handles
//-----------------------------------------------------------------------------
enum class HandleKind : int {
    None,
    Axis,   // move: an arrow along axes[axis]
    Plane,  // move: a square on the plane whose normal is axes[axis]
    Ring,   // rotate: the circle about axes[axis]
    Scale,  // scale: a line along axes[axis] ending in a box
};

struct GizmoHandle {
    HandleKind kind = HandleKind::None;
    int axis = 0;  // 0, 1, 2: x, y, z
    bool operator==(const GizmoHandle&) const = default;
};

// The handles' place in the world: at the selection's centre, along its axes (unit, a right-
// handed set), each `length` metres long, which is lengthPixels on screen.
struct GizmoFrame {
    glm::vec3 centre{0.0f};
    glm::mat3 axes{1.0f};  // axes[i] is column i
    float length = 1.0f;
};

// World axes for move and turn; the object's own (o.orientation()) for scale.
GizmoFrame gizmoFrame(const Camera& c, glm::vec3 centre, const glm::mat3& axes, glm::vec2 viewSize,
                      const GizmoSettings& k = {});

// The point at `angle` on the ring about axes[axis] (radius `length`): angle 0 lies on the next
// axis, and angles grow as a positive turn about the ring's axis carries it (x takes y to z).
glm::vec3 ringPoint(const GizmoFrame& f, int axis, float angle);

// Whether handle h faces the camera enough to show (see endOnAxis); rings always do.
bool handleShown(const Camera& c, const GizmoFrame& f, GizmoHandle h, const GizmoSettings& k = {});

// The handle of `mode` under `pixel`, or kind None: planes first (they are areas), then the
// nearest line within pickPixels; only those shown.
GizmoHandle hitGizmo(const Camera& c, const GizmoFrame& f, GizmoMode mode, glm::vec2 pixel,
                     glm::vec2 viewSize, const GizmoSettings& k = {});

//-----------------------------------------------------------------------------
// [SECTION] Drags
//-----------------------------------------------------------------------------
// Where the line p + t·a (a unit) comes nearest the ray o + s·d (d unit): its t. False when
// the two run parallel, and the nearest point is anywhere along them.
bool closestOnLine(glm::vec3 p, glm::vec3 a, glm::vec3 o, glm::vec3 d, float* t);

// Where the ray o + s·d (s > 0) meets the plane through p with normal n. False when it misses.
bool rayOnPlane(glm::vec3 p, glm::vec3 n, glm::vec3 o, glm::vec3 d, glm::vec3* hit);

// v to the nearest multiple of step (step <= 0: v).
float snapTo(float v, float step);

// What a drag has done so far, from the moment it took hold.
struct GizmoDelta {
    glm::vec3 move{0.0f};                    // world metres
    glm::quat turn{1.0f, 0.0f, 0.0f, 0.0f};  // about the centre, in world axes
    int scaleAxis = -1;                      // the object's own axis sized, -1: none
    float scale = 1.0f;                      // the factor along it
};

// A handle held down: the state at the press, so each frame's result is measured from the start
// and rounding never builds up over a drag.
struct GizmoDrag {
    GizmoHandle handle;
    GizmoFrame frame;
    glm::vec3 grabbed{0.0f};  // axis, scale, plane: the point on it under the mouse
    float grabT = 0.0f;       // axis, scale: how far along the axis grabbed lies
    float grabAngle = 0.0f;   // ring: the mouse's angle about the centre on screen
    float sign = 1.0f;        // ring: +1 when its axis points at the camera

    // False when the mouse's ray cannot hold the handle (an axis pointing at the camera).
    bool begin(const Camera& c, const GizmoFrame& f, GizmoHandle h, glm::vec2 pixel,
               glm::vec2 viewSize);
    // The drag with the mouse at `pixel`; `snap`: Ctrl is held. False, and *d untouched, when
    // this pixel's ray cannot say (it runs along the axis or misses the plane).
    bool follow(const Camera& c, glm::vec2 pixel, glm::vec2 viewSize, bool snap, GizmoDelta* d,
                const GizmoSettings& k = {}) const;
};

// `start` with the drag applied: moved, turned about its centre, or sized along one of its
// own axes as its shape allows (see docs/editor.md: a sphere's radius, a box's or ellipsoid's
// half-extent, a torus's radius or tube, a capsule's, cylinder's or cone's radius or height; a
// cone's top with its radius). A turned body keeps its turn exactly in `orient` where it had
// one or moves (the file writes orient for those), and `rot` shows the same turn in degrees.
Object applyGizmo(Object start, const GizmoDelta& d, const GizmoSettings& k = {});

// Object o, or everything group g holds, sized by `factor` in every direction: lengths, the
// places of members in their groups, blends and spacings. No length shrinks below minSize.
void scaleObject(Object& o, float factor, const GizmoSettings& k = {});
void scaleGroup(Scene& s, int g, float factor, const GizmoSettings& k = {});

// The selection's objects and groups as the press found them: each frame applies the whole
// drag to these, so rounding never builds up over a drag.
struct GizmoHold {
    std::vector<Item> items;      // roots() of the selection: each moves once, with its members
    std::vector<Object> objects;  // the scene's, at the press
    std::vector<Group> groups;
    glm::vec3 centre{0.0f};   // the handles' centre: turns and uniform sizes go about it
    bool alone = false;       // one object: sized along its own axes, not uniformly
    float leastScale = 0.0f;  // no uniform size below this: every length stays >= minSize
};
GizmoHold holdSelection(const Scene& s, const Selection& sel, const GizmoSettings& k = {});

// The held items with the drag applied, in the world: moved, turned about the centre, and
// sized, one object alone along its own axis (as applyGizmo above), a group or several items
// uniformly by the drag's factor about the centre. A member's place converts to its group's
// frame. Nothing happens where the scene's lists no longer match the hold's.
void applyGizmo(Scene& s, const GizmoHold& h, const GizmoDelta& d, const GizmoSettings& k = {});

//-----------------------------------------------------------------------------
// [SECTION] Selection
//-----------------------------------------------------------------------------
// The handles of the selection in the view of the scene's camera, in `mode` (*shown = mode): an
// object's at its centre in the world, a group's at its origin, along its own axes for Scale;
// several items' at the mean of their centres, along the world's axes. A point light's always
// move it (*shown = Move: a point has no turn or size). False for nothing selected, a
// material, a directional light (it has no place) or a centre behind the camera.
bool selectionGizmo(const Scene& s, const Selection& sel, GizmoMode mode, glm::vec2 viewSize,
                    GizmoFrame* f, GizmoMode* shown, const GizmoSettings& k = {});

// The point light whose marker, a disc radiusPixels across at its place, is under `pixel`:
// the nearest to the camera where markers overlap; -1 for none.
int pickLightMarker(const Scene& s, glm::vec2 pixel, glm::vec2 viewSize, float radiusPixels);

}  // namespace mb
