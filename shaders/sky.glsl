// The sky as every pass sees it: a cubemap (the procedural sky baked at start,
// or the user's six images) plus the sun's disc drawn analytically on top.
#ifndef SWELL_SKY_GLSL
#define SWELL_SKY_GLSL
#include "swell/gpu/bindings.h"
#include "frame.glsl"
#ifndef SWELL_CLOUD_SHADOWS
#error "SWELL_CLOUD_SHADOWS is given by the program's flags (src/render/programs.h)"
#endif
#if SWELL_CLOUD_SHADOWS
#include "cloud_shadow.glsl"
#endif

layout(binding = SWELL_UNIT_SKY) uniform samplerCube skyCube;

// The sun's disc (about 0.5 degrees, softened), 20 times the sky's brightness.
// It stays analytic: at 1280x720 with a 60-degree field of view its core is
// six pixels across, while a texel of the baked sky is about a third of a
// degree, so a baked disc would be a blurred blob two or three texels wide.
vec3 sunDisc(vec3 d)
{
    float disk = smoothstep(0.99996, 0.99999, dot(d, sunDirection));
#if SWELL_CLOUD_SHADOWS
    // The frame's sun is the one above the layer (the shadow map shades
    // it point by point); the disc is seen through the layer from the
    // sky's observer, as the baked sky around it is.
    return sunColor * (sunIntensity * cloudShadowSkySun) * disk * 20.0;
#else
    return sunColor * sunIntensity * disk * 20.0;
#endif
}

// Linear sky radiance along a direction, from mip level 0. For callers in
// non-uniform control flow (the water's reflection lookups), where implicit
// derivatives, and so automatic mip selection, are undefined.
vec3 skyRadiance(vec3 direction)
{
    vec3 d = normalize(direction);
    return textureLod(skyCube, d, 0.0).rgb + sunDisc(d);
}

// The same with the mip level chosen from the pixel's footprint, for the sky
// pass (uniform control flow), so a detailed user cubemap does not alias.
vec3 skyRadianceFiltered(vec3 direction)
{
    vec3 d = normalize(direction);
    return texture(skyCube, d).rgb + sunDisc(d);
}
#endif
