// The cloud layer's shadow on whatever the sun lights: the layer's
// transmittance along the sun's ray from a point, looked up in the map the
// renderer bakes from clouds.glsl (cloud_shadow_bake.frag;
// src/render/cloud_shadow_map.h) where that ray meets the sea's mean level,
// averaged over the caller's footprint by the map's mip chain. Only in
// programs built with SWELL_CLOUD_SHADOWS 1 (the physical sky with clouds);
// without, the sun's light is the frame's alone, as it always was.
#ifndef SWELL_CLOUD_SHADOW_GLSL
#define SWELL_CLOUD_SHADOW_GLSL
#include "swell/gpu/bindings.h"
#include "swell/gpu/sky.h"
#include "frame.glsl"

// The CloudShadow block (swell::detail::CloudShadowUniforms, src/render/gpu/blocks.h).
#include "gpu/cloud_shadow_block.glsl"

layout(binding = SWELL_UNIT_CLOUD_SHADOW) uniform sampler2D cloudShadowMap;

// The layer's mean transmittance over the map (its last mip level).
float cloudShadowMean()
{
    return textureLod(cloudShadowMap, vec2(0.5), 16.0).r;
}

// The share of the sun's direct light the layer lets through to p
// (relative to the render origin; y over the mean level), averaged over a
// footprint of footprint_m: the map where the sun's ray through p meets
// the mean level (the map holds each such point's transmittance along its
// ray up to the layer). Towards the map's borders and beyond it, the
// map's mean (its last mip level).
float cloudShadowAt(vec3 p, float footprint_m)
{
    float up = max(sunDirection.y, float(SWELL_CLOUD_SHADOW_MIN_SUN_Y));
    vec2 q = p.xz - sunDirection.xz * (p.y / up);
    vec2 uv = (q - cloudShadowCorner_m) / cloudShadowSize_m;
    float texel_m = cloudShadowSize_m / float(SWELL_CLOUD_SHADOW_SIZE);
    float lod = log2(max(footprint_m / texel_m, 1.0));
    float mean = cloudShadowMean();
    vec2 edge = min(uv, 1.0 - uv);
    float inside = smoothstep(0.0, 0.05, min(edge.x, edge.y));
    return mix(mean, textureLod(cloudShadowMap, uv, lod).r, inside);
}
#endif
