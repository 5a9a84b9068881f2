// The temporal resolve's first step (docs/RENDERING.md "Temporal resolve"),
// at the size the frame was drawn: for each drawn pixel, the box its 3x3
// neighbourhood spans in YCoCg (the mean, and SWELL_TEMPORAL_CLIP_SIGMAS
// standard deviations about it: Salvi 2016, variance clipping), the drawn
// pixel's own water mark and its depth. Every output pixel whose nearest
// drawn sample this is clips its history to that box
// (shaders/temporal_resolve.frag). Below the output's size many output
// pixels share one drawn sample, so the neighbourhood is gathered once per
// drawn pixel here instead of once per output pixel there: at a render
// scale of 0.3 that is 11 times fewer reads.
#include "swell/gpu/bindings.h"
#include "swell/gpu/temporal.h"
#include "temporal_colour.glsl"

layout(binding = SWELL_UNIT_POST_SOURCE) uniform sampler2D frameColor;
layout(binding = SWELL_UNIT_TEMPORAL_DEPTH) uniform sampler2D frameDepth;

// rgb: the box's centre (YCoCg); a: the drawn pixel's alpha (0 on the water).
layout(location = 0) out vec4 boxCentre;
// rgb: the box's half extent (YCoCg); a: the drawn pixel's window depth.
layout(location = 1) out vec4 boxExtent;

void main()
{
    ivec2 at = ivec2(gl_FragCoord.xy);
    ivec2 last = textureSize(frameColor, 0) - 1;
    vec3 m1 = vec3(0.0), m2 = vec3(0.0);
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            vec3 y = toYCoCg(texelFetch(frameColor, clamp(at + ivec2(dx, dy), ivec2(0), last), 0).rgb);
            m1 += y;
            m2 += y * y;
        }
    }
    vec3 mean = m1 / 9.0;
    vec3 sigma = sqrt(max(m2 / 9.0 - mean * mean, vec3(0.0)));
    boxCentre = vec4(mean, texelFetch(frameColor, at, 0).a);
    boxExtent = vec4(SWELL_TEMPORAL_CLIP_SIGMAS * sigma, texelFetch(frameDepth, at, 0).r);
}
