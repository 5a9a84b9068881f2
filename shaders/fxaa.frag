// FXAA-style anti-aliasing of the main pass, after Lottes (2009, "FXAA",
// NVIDIA white paper; the "PC console" variant of FXAA 3): where the local
// luma contrast is high, the edge's direction is estimated from the four
// diagonal neighbours and the pixel is replaced by samples taken along the
// edge, which blends a stair step into a ramp. Reads and writes display-ready
// (sRGB-encoded) colour, the space in which steps are seen.
#include "swell/gpu/bindings.h"

layout(binding = SWELL_UNIT_POST_SOURCE) uniform sampler2D source;

out vec4 fragColor;

// Contrast below max(kEdgeMin, kEdgeRelative * brightest) is left alone:
// the paper's "quality" defaults (1/16 absolute, 1/8 relative).
const float kEdgeMin = 1.0 / 16.0;
const float kEdgeRelative = 1.0 / 8.0;
// Keeps the direction's scale finite on flat-ish edges (the paper: 1/128)
// and shortens it on bright ones (1/8).
const float kReduceMin = 1.0 / 128.0;
const float kReduceMul = 1.0 / 8.0;
// The farthest the samples reach along the edge, pixels (the paper: 8).
const float kSpanMax_px = 8.0;

float luma(vec3 c) { return dot(c, vec3(0.299, 0.587, 0.114)); }

void main()
{
    ivec2 size = textureSize(source, 0);
    vec2 texel = 1.0 / vec2(size);
    vec2 uv = gl_FragCoord.xy * texel;
    // The pixel and its diagonal neighbours lie on texel centres, where a
    // filtered lookup returns the texel itself: fetched unfiltered, which a
    // software rasteriser does at a fraction of the cost. The neighbours
    // clamp at the edges as the filtered lookups did (clamp-to-edge source).
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 last = size - 1;
    vec4 centre = texelFetch(source, p, 0);
    float lumaM = luma(centre.rgb);
    float lumaNW = luma(texelFetch(source, clamp(p + ivec2(-1, 1), ivec2(0), last), 0).rgb);
    float lumaNE = luma(texelFetch(source, clamp(p + ivec2(1, 1), ivec2(0), last), 0).rgb);
    float lumaSW = luma(texelFetch(source, clamp(p + ivec2(-1, -1), ivec2(0), last), 0).rgb);
    float lumaSE = luma(texelFetch(source, clamp(p + ivec2(1, -1), ivec2(0), last), 0).rgb);
    float lumaMin = min(lumaM, min(min(lumaNW, lumaNE), min(lumaSW, lumaSE)));
    float lumaMax = max(lumaM, max(max(lumaNW, lumaNE), max(lumaSW, lumaSE)));
    if (lumaMax - lumaMin < max(kEdgeMin, lumaMax * kEdgeRelative)) {
        fragColor = centre;
        return;
    }
    // The gradient's perpendicular: the direction the edge runs in.
    vec2 direction = vec2(-((lumaNW + lumaNE) - (lumaSW + lumaSE)), (lumaNW + lumaSW) - (lumaNE + lumaSE));
    float reduce = max((lumaNW + lumaNE + lumaSW + lumaSE) * 0.25 * kReduceMul, kReduceMin);
    float scale = 1.0 / (min(abs(direction.x), abs(direction.y)) + reduce);
    direction = clamp(direction * scale, vec2(-kSpanMax_px), vec2(kSpanMax_px)) * texel;
    // Two samples near the pixel along the edge, and two at the span's ends.
    vec3 inner = 0.5 * (texture(source, uv + direction * (1.0 / 3.0 - 0.5)).rgb
                        + texture(source, uv + direction * (2.0 / 3.0 - 0.5)).rgb);
    vec3 outer = 0.5 * inner + 0.25 * (texture(source, uv - direction * 0.5).rgb
                                       + texture(source, uv + direction * 0.5).rgb);
    // The longer reach may cross into another edge; then the short one is kept.
    float lumaOuter = luma(outer);
    fragColor = vec4((lumaOuter < lumaMin || lumaOuter > lumaMax) ? inner : outer, centre.a);
}
