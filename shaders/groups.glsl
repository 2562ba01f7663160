// groups.glsl — the copies of a repeated group, for the loops src/gl/scene_compiler.cpp writes.
//
// A repeated group is the sharp union of its copies: copy (i, j, k) moved by
// ((i − (n₁−1)/2)·s₁, (j − (n₂−1)/2)·s₂, (k − (n₃−1)/2)·s₃) in the group's frame, its members
// seeing the point moved back (groupImage in src/scene/sdf.cpp). A copy whose bounding sphere
// is no nearer than the best distance so far cannot lower it, so the loop visits first the copy
// whose cell holds the point, then only the box of copies whose spheres reach nearer than that
// copy's distance: those the CPU mirror does not cull. Far fewer than all of them near a
// surface, where a march spends its steps.

#if HAS_REPEAT
struct Copies {
    ivec3 n;        // copies along each axis
    ivec3 nearest;  // the copy whose cell holds the point, first in the loop
    ivec3 lo, size; // the box of copies the loop visits after it
    int count;      // the loop's length: 1 until widenCopies, then 1 + the box's copies
};

// Where q falls along each axis of the copies, in copy indices (not rounded, not clamped).
vec3 copyCoord(vec3 q, vec3 spacing, ivec3 n) { return q / spacing + 0.5 * (vec3(n) - 1.0); }

Copies nearestCopy(vec3 q, vec3 spacing, ivec3 n) {
    Copies c;
    c.n = n;
    c.nearest = ivec3(clamp(floor(copyCoord(q, spacing, n) + 0.5), vec3(0.0), vec3(n - 1)));
    c.lo = c.nearest;
    c.size = ivec3(1);
    c.count = 1;
    return c;
}

// Once the nearest copy gave `best`: the copies whose spheres (radius spacing.w) come nearer
// than best lie within best + spacing.w of q along every axis. Clamped as floats: a far best
// (1e10, nothing there) makes no integer overflow.
void widenCopies(inout Copies c, vec3 q, vec4 spacing, float best) {
    float reach = best + spacing.w;
    vec3 last = vec3(c.n - 1);
    vec3 lo = clamp(ceil(copyCoord(q - reach, spacing.xyz, c.n)), vec3(0.0), last);
    vec3 hi = clamp(floor(copyCoord(q + reach, spacing.xyz, c.n)), vec3(0.0), last);
    c.lo = ivec3(lo);
    c.size = max(ivec3(hi - lo) + 1, ivec3(0));
    c.count = 1 + c.size.x * c.size.y * c.size.z;
}

// Copy m of the loop, its point q in the group's frame moved into the copy's: the nearest copy
// for m = 0, then the box's. False where it is the nearest again or cannot come nearer than
// best (sdf.cpp's cull: its sphere no nearer).
bool copyAt(Copies c, int m, vec3 q, vec4 spacing, float best, out vec3 local) {
    ivec3 index = c.nearest;
    if (m > 0) {
        int k = m - 1;
        index = c.lo + ivec3(k % c.size.x, (k / c.size.x) % c.size.y, k / (c.size.x * c.size.y));
    }
    local = q - (vec3(index) - 0.5 * (vec3(c.n) - 1.0)) * spacing.xyz;
    return m == 0 || (index != c.nearest && length(local) - spacing.w < best);
}
#endif
