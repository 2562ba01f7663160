// post.frag — resolves the accumulated supersamples, with optional FXAA (Lottes' FXAA,
// the compact console variant) and its debug views. The prefix defines POST_MODE:
// 0 copy, 1 FXAA, 2 FXAA edge mask, 3 FXAA search direction.
uniform sampler2D uImage;
out vec4 fragColor;

const float FXAA_REDUCE_MIN = 1.0 / 128.0;
const float FXAA_REDUCE_MUL = 1.0 / 8.0;
const float FXAA_SPAN_MAX = 8.0;
const float FXAA_EDGE_THRESHOLD = 1.0 / 16.0;

float luma(vec3 c) { return dot(c, vec3(0.299, 0.587, 0.114)); }

vec3 texel(vec2 pixel) { return texture(uImage, pixel / vec2(textureSize(uImage, 0))).rgb; }

void main() {
    vec2 p = gl_FragCoord.xy;
    vec3 m = texel(p);
#if POST_MODE == 0
    fragColor = vec4(clamp(m, 0.0, 1.0), 1.0);
#else
    float lNW = luma(texel(p + vec2(-1.0, 1.0))), lNE = luma(texel(p + vec2(1.0, 1.0)));
    float lSW = luma(texel(p + vec2(-1.0, -1.0))), lSE = luma(texel(p + vec2(1.0, -1.0)));
    float lM = luma(m);
    float lMin = min(lM, min(min(lNW, lNE), min(lSW, lSE)));
    float lMax = max(lM, max(max(lNW, lNE), max(lSW, lSE)));
    // The edge runs across the steepest luma gradient; blur along it.
    vec2 dir = vec2(-((lNW + lNE) - (lSW + lSE)), (lNW + lSW) - (lNE + lSE));
    float reduce = max((lNW + lNE + lSW + lSE) * 0.25 * FXAA_REDUCE_MUL, FXAA_REDUCE_MIN);
    dir = clamp(dir / (min(abs(dir.x), abs(dir.y)) + reduce), -FXAA_SPAN_MAX, FXAA_SPAN_MAX);
#if POST_MODE == 2
    fragColor = vec4(vec3(lMax - lMin > FXAA_EDGE_THRESHOLD ? 1.0 : 0.0), 1.0);
#elif POST_MODE == 3
    fragColor = vec4(clamp(dir / FXAA_SPAN_MAX * 0.5 + 0.5, 0.0, 1.0), 0.5, 1.0);
#else
    vec3 a = 0.5 * (texel(p + dir * (1.0 / 3.0 - 0.5)) + texel(p + dir * (2.0 / 3.0 - 0.5)));
    vec3 b = 0.5 * a + 0.25 * (texel(p - 0.5 * dir) + texel(p + 0.5 * dir));
    float lB = luma(b);
    fragColor = vec4(clamp(lB < lMin || lB > lMax ? a : b, 0.0, 1.0), 1.0);
#endif
#endif
}
