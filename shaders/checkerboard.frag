// checkerboard.frag — the whole picture from a checkerboard half (draft; march.frag's
// CHECKERBOARD). Pixel (x, y) was shaded where x + y is even, and sits at (x / 2, y) of uHalf.
// A missing pixel's four neighbours were all shaded: it takes the mean of the pair, across or
// along, that differ less, so an edge is continued along itself rather than blurred across.
uniform sampler2D uHalf;
uniform ivec2 uSize;  // the whole picture's
out vec4 fragColor;

vec3 column(int i, int y) { return texelFetch(uHalf, ivec2(i, y), 0).rgb; }

// The neighbour at i + step along an axis of n pixels; past the border, the one opposite.
int neighbour(int i, int step, int n) { return clamp(i + step < 0 || i + step >= n ? i - step : i + step, 0, n - 1); }

// Four fetches serve both kinds of pixel, with no branch (llvmpipe would run both sides):
// packed column x / 2 holds the pixel itself where it was shaded, else its neighbour on the
// side x's parity points to; the column beside holds the one on the other side.
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int i = p.x >> 1;
    vec3 here = column(i, p.y), beside = column(neighbour(p.x, 2 * (p.x & 1) - 1, uSize.x) >> 1, p.y);
    vec3 l = p.x + 1 < uSize.x ? here : beside, r = beside;  // at the right border: the left one
    vec3 d = column(i, neighbour(p.y, -1, uSize.y)), u = column(i, neighbour(p.y, 1, uSize.y));
    // A pair with a neighbour past the border is not a pair: on the border the other one wins,
    // in a corner both count. A picture one pixel wide or high has no pair that way at all: one
    // pixel wide, `here` is the pixel past the border that the march shades to fill its column.
    const float kApart = 1e9, kNone = 2e9;
    float across = uSize.x == 1 ? kNone : p.x > 0 && p.x + 1 < uSize.x ? dot(abs(l - r), vec3(1.0)) : kApart;
    float along = uSize.y == 1 ? kNone : p.y > 0 && p.y + 1 < uSize.y ? dot(abs(d - u), vec3(1.0)) : kApart;
    vec3 h = 0.5 * (l + r), v = 0.5 * (d + u);
    vec3 filled = across < along ? h : along < across ? v : 0.5 * (h + v);
    fragColor = vec4(((p.x + p.y) & 1) == 0 ? here : filled, 1.0);
}
