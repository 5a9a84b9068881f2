// The wake the floating bodies leave (src/objects/scene_wake.h): a square
// grid of cells, each holding the wake's height, its slopes and its foam,
// uploaded by src/render/wake_texture.cpp for the frame. Between cell
// centres it is interpolated bilinearly with the weights of
// swell::detail::bilinearOverCells (src/objects/wake_frame.h), fetched
// texel by texel so that no filtering hardware rounds them differently:
// the drawn surface the CPU queries (swell/drawn_surface.h) is this one.
#ifndef SWELL_WAKE_GLSL
#define SWELL_WAKE_GLSL
#include "swell/shader_constants.h"

// Mirrored by swell::detail::WakeUniforms (src/render/wake_texture.h).
layout(std140, binding = SWELL_BINDING_WAKE) uniform Wake {
    vec2 wakeCorner_m;    // centre of cell (0, 0) relative to the render origin, x, z, m
    float wakeCellSize_m; // m
    int wakeCells;        // per side; 0: no wake this frame
    ivec2 wakeCornerCell; // cell (0, 0)'s index in the world, modulo SWELL_WAKE_NOISE_PERIOD (for the foam's texture)
};
layout(binding = SWELL_UNIT_WAKE) uniform sampler2D wakeTexels; // RGBA32F: height m, d/dx, d/dz, foam 0..1

vec4 wakeTexel(ivec2 cell)
{
    if (any(lessThan(cell, ivec2(0))) || any(greaterThanEqual(cell, ivec2(wakeCells))))
        return vec4(0.0);
    return texelFetch(wakeTexels, cell, 0);
}

// The wake at a point relative to the render origin: height, slopes, foam.
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

// Foam's texture: a layer of bubbles broken into patches. Value noise on
// the wake's own cells, anchored to the world (it does not swim as the grid
// moves) and periodic over SWELL_WAKE_NOISE_PERIOD cells so that the corner
// index can wrap.
float wakeHash(vec2 cell, float period)
{
    cell = mod(cell, period);
    return fract(sin(dot(cell, vec2(127.1, 311.7))) * 43758.5453);
}
float wakeNoise(vec2 p, float period)
{
    vec2 cell = floor(p);
    vec2 u = smoothstep(0.0, 1.0, p - cell);
    return mix(mix(wakeHash(cell, period), wakeHash(cell + vec2(1.0, 0.0), period), u.x),
               mix(wakeHash(cell + vec2(0.0, 1.0), period), wakeHash(cell + vec2(1.0, 1.0), period), u.x), u.y);
}

// The wake's foam at a point relative to the render origin, 0..1: the
// cover the simulation gives, broken up by three octaves of noise (patches
// of about 1, 1/2 and 1/4 cell) so a stern wash reads as bubbles, not paint:
// thin cover leaves only the densest patches, full cover a few holes.
float wakeFoamAt(vec2 p_m, float cover)
{
    vec2 g = (p_m - wakeCorner_m) / wakeCellSize_m + vec2(wakeCornerCell);
    float period = float(SWELL_WAKE_NOISE_PERIOD);
    float texture = 0.5 * wakeNoise(g, period) + 0.3 * wakeNoise(2.0 * g, 2.0 * period) +
                    0.2 * wakeNoise(4.0 * g, 4.0 * period);
    // As the share of the pixel covered (water.frag's foamCover): the
    // patches' soft edges made sharp, so thin cover leaves bubbles rather
    // than a haze over the whole wake.
    return smoothstep(0.35, 0.65, cover * (1.6 * texture - 0.1));
}

#endif
