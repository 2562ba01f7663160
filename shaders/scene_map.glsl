// scene_map.glsl — the scene's objects, compiled or looped over, the object grid, and the
// ground. map() is sdf.h's mapScene(), mapObjects() its mapObjects().

// Whether a march's object id (an object's index, HIT_GROUND or HIT_NONE, all whole numbers)
// is HIT_NONE: nothing was met.
bool missed(float id) { return id < HIT_NONE + 0.5; }

#include "intersect.glsl"
#include "penumbra.glsl"
#include "groups.glsl"

// Replaced by src/gl/scene_compiler.cpp: a compiled scene's loadObjects() and mapObjects(),
// with mapRest() and hitPlainMembers() where it has plain members (intersect.glsl), then the per-type SDF switch (the loop's, and the outline's), a case for each type present.
#pragma marchbox scene

#if !COMPILED
// Joins object i to the chain so far (x: distance, y: surface's object index).
vec2 chainStep(vec2 res, int i, vec3 p) {
    int op = uObjects[i].info.y;
    float k = uObjects[i].shape.z;
    vec3 rel = p - uObjects[i].posBound.xyz;
    // dObj >= bound: union and subtract keep their value when the object is k beyond it.
    float bound = length(rel) - uObjects[i].posBound.w;
    if (op == 0 && bound >= res.x + k) return res;
#if HAS_SUBTRACT
    if (op == 1 && bound >= k - res.x) return res;
#endif
    float d = sdObjectLocal(i, uObjects[i].toLocal * rel);
    float id = float(i);
#if HAS_SUBTRACT
    if (op == 1) return joinSubtract(res, d, k, id);
#endif
#if HAS_INTERSECT
    if (op == 2) return joinIntersect(res, d, k, id);
#endif
    return joinUnion(res, d, k, id);
}

#if !USE_GRID || UBER
// x: distance; y: index of the surface's object, HIT_NONE for nothing.
vec2 mapObjects(vec3 p) {
    vec2 res = vec2(1e10, HIT_NONE);
    for (int i = 0; i < OBJECT_COUNT; ++i) res = chainStep(res, i, p);
    return res;
}
#endif
#endif

#if USE_GRID
// The uniform object grid of src/scene/object_grid.cpp: each cell lists, in file order, the
// objects that can change the chain inside it; every other object lies beyond its boundary.
vec3 gridLo() { return uGridOrigin; }
vec3 gridHi() { return uGridOrigin + vec3(uGridDims) * uGridCell; }

ivec3 gridCellOf(vec3 p) {
    return clamp(ivec3(floor((p - uGridOrigin) / uGridCell)), ivec3(0), uGridDims - 1);
}

vec2 mapCell(ivec3 c, vec3 p) {
    int cell = (c.z * uGridDims.y + c.y) * uGridDims.x + c.x;
    int first = int(texelFetch(uGridCells, cell).r), last = int(texelFetch(uGridCells, cell + 1).r);
    vec2 res = vec2(1e10, HIT_NONE);
    for (int k = first; k < last; ++k) res = chainStep(res, int(texelFetch(uGridItems, k).r), p);
    return res;
}

float gridBoxDistance(vec3 p) {  // exact box distance (sdBox), here for every scene
    vec3 q = abs(p - 0.5 * (gridLo() + gridHi())) - 0.5 * (gridHi() - gridLo());
    return length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
}

// For normals and occlusion, not for stepping: just outside the grid the nearest cell holds
// the objects there, where the box's own distance would tilt the floor's normals.
vec2 mapGrid(vec3 p) { return mapCell(gridCellOf(p), p); }

// x: a safe step along rd; y: the object; z: the cell's own distance, for penumbrae. The step
// ends just past the cell's exit, since what lies beyond is at least that far; the extra
// `bump` (over 2 epsilon) carries the ray into the next cell without counting as a hit.
vec3 mapGridAlong(vec3 p, vec3 rd) {
    float bump = max(2.0 * uEpsilon, 1e-4 * min(uGridCell.x, min(uGridCell.y, uGridCell.z)));
    float outside = gridBoxDistance(p);
    if (outside > 0.0) return vec3(outside + bump, HIT_NONE, 1e10);
    ivec3 c = gridCellOf(p);
    vec2 res = mapCell(c, p);
    vec3 lo = uGridOrigin + vec3(c) * uGridCell;
    vec3 safeRd = vec3(rd.x >= 0.0 ? 1.0 : -1.0, rd.y >= 0.0 ? 1.0 : -1.0, rd.z >= 0.0 ? 1.0 : -1.0) * max(abs(rd), vec3(1e-8));
    vec3 tExit = (lo + step(0.0, rd) * uGridCell - p) / safeRd;
    float exit = max(min(tExit.x, min(tExit.y, tExit.z)), 0.0) + bump;
    return exit < res.x ? vec3(exit, HIT_NONE, res.x) : vec3(res, res.x);
}
#endif

// The ground plane, unioned last: what normals and occlusion see. Rays meet it analytically.
vec2 withGround(vec2 res, vec3 p) {
#if HAS_GROUND
    if (GROUND_ON && p.y - uFloor < res.x) res = vec2(p.y - uFloor, HIT_GROUND);
#endif
    return res;
}

vec2 mapAnyObjects(vec3 p) {
#if USE_GRID && !UBER
    return mapGrid(p);
#else
#if USE_GRID
    if (uUseGrid) return mapGrid(p);
#endif
    return mapObjects(p);
#endif
}

vec2 map(vec3 p) { return withGround(mapAnyObjects(p), p); }

// The objects alone, for stepping along rd: x a safe step, y the object, z the true distance
// (for penumbrae). On the grid a step also ends at its cell's exit.
vec3 mapObjectsAlong(vec3 p, vec3 rd) {
#if USE_GRID && !UBER
    return mapGridAlong(p, rd);
#else
#if USE_GRID
    if (uUseGrid) return mapGridAlong(p, rd);
#endif
    vec2 res = mapObjects(p);
    return vec3(res, res.x);
#endif
}

// A compiled chain's sample for stepping: its distance is the step and the penumbra's too.
vec3 chainAlong(vec2 res) { return vec3(res, res.x); }

// The marched part of the scene, for stepping along rd as mapObjectsAlong. A compiled scene
// marches its objects but the plain members; the grid and uber march them all, but only inside
// the box of the rest (uRestLo, uRestHi), and a plain member's exact hit ends the march anyway.
vec3 mapRestAlong(vec3 p, vec3 rd) {
#if PLAIN == 1
    return chainAlong(mapRest(p));
#else
    return mapObjectsAlong(p, rd);
#endif
}
