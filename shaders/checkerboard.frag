// checkerboard.frag — the whole picture from a checkerboard half (draft; march.frag's
// CHECKERBOARD). Pixel (x, y) was shaded where x + y is even, and sits at (x / 2, y) of uHalf.
// A missing pixel's four neighbours were all shaded: it takes the mean of the pair, across or
// along, that differ less, so an edge is continued along itself rather than blurred across.
uniform sampler2D uHalf;
uniform ivec2 uSize;  // the whole picture's
out vec4 fragColor;

vec3 shaded(int x, int y) { return texelFetch(uHalf, ivec2(x >> 1, y), 0).rgb; }

// The neighbour at i + step along an axis of n pixels; past the border, the one opposite.
int neighbour(int i, int step, int n) { return clamp(i + step < 0 || i + step >= n ? i - step : i + step, 0, n - 1); }

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    if (((p.x + p.y) & 1) == 0) {
        fragColor = vec4(shaded(p.x, p.y), 1.0);
        return;
    }
    vec3 l = shaded(neighbour(p.x, -1, uSize.x), p.y), r = shaded(neighbour(p.x, 1, uSize.x), p.y);
    vec3 d = shaded(p.x, neighbour(p.y, -1, uSize.y)), u = shaded(p.x, neighbour(p.y, 1, uSize.y));
    // A pair with a neighbour past the border is not a pair: on the border the other one wins,
    // in a corner both count.
    const float kApart = 1e9;
    float across = p.x > 0 && p.x + 1 < uSize.x ? dot(abs(l - r), vec3(1.0)) : kApart;
    float along = p.y > 0 && p.y + 1 < uSize.y ? dot(abs(d - u), vec3(1.0)) : kApart;
    vec3 h = 0.5 * (l + r), v = 0.5 * (d + u);
    fragColor = vec4(across < along ? h : along < across ? v : 0.5 * (h + v), 1.0);
}
