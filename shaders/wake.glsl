// The wake the floating bodies leave (src/objects/scene_wake.h): a square
// grid of cells, each holding the wake's height, its slopes and its foam,
// uploaded by src/render/wake_texture.cpp for the frame. Between cell
// centres it is interpolated bilinearly with the weights of
// swell::detail::bilinearOverCells (src/objects/wake_frame.h), fetched
// texel by texel so that no filtering hardware rounds them differently:
// the drawn surface the CPU queries (swell/drawn_surface.h) is this one.
#ifndef SWELL_WAKE_GLSL
#define SWELL_WAKE_GLSL
#include "swell/gpu/bindings.h"

// The Wake block (swell::detail::WakeUniforms, src/render/gpu/blocks.h).
#include "gpu/wake_block.glsl"
layout(binding = SWELL_UNIT_WAKE) uniform sampler2D wakeTexels; // RGBA32F: height m, d/dx, d/dz, foam 0..1

vec4 wakeTexel(ivec2 cell)
{
    if (any(lessThan(cell, ivec2(0))) || any(greaterThanEqual(cell, ivec2(wakeCells))))
        return vec4(0.0);
    return texelFetch(wakeTexels, cell, 0);
}

// The wake at a point relative to the render origin: height, slopes, and
// the amount of foam (1 where it breaks now, fading as the whitecaps' foam
// does), which water.frag draws with the whitecaps' look (whitecap_foam.glsl).
vec4 wakeAt(vec2 p_m)
{
    if (wakeCells <= 0)
        return vec4(0.0);
    vec2 g = (p_m - wakeCorner_m) / wakeCellSize_m;
    vec2 base = floor(g);
    vec2 f = g - base;
    ivec2 c = ivec2(base);
    return (1.0 - f.y) * ((1.0 - f.x) * wakeTexel(c) + f.x * wakeTexel(c + ivec2(1, 0))) +
           f.y * ((1.0 - f.x) * wakeTexel(c + ivec2(0, 1)) + f.x * wakeTexel(c + ivec2(1, 1)));
}

#endif
