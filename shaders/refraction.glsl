// What is seen through the water: the world below the surface from pass 1b,
// bent by the normal and absorbed per channel with the path length (Beer-Lambert).
// Together with the world's own shading under the water (mesh.frag: the
// light reaching a point below the surface attenuated on its way down) it
// is the shallow-water reflectance model of Lee et al. (1998, "Hyperspectral
// remote sensing for shallow waters. I. A semianalytical model", Appl. Opt.
// 37(27), 6329-6338), r = r_deep (1 - exp(-(K_d + K_u) H)) + (rho / pi)
// exp(-(K_d + K_u) H): the bottom's share attenuated along the way down
// and up, plus the column's own, the deep water's reflectance for the
// share of the column the light crosses both ways; the water's absorption
// stands for both K, along each leg's path (tests/gl/test_shallows.cpp
// holds the renderer to it).
#ifndef SWELL_REFRACTION_GLSL
#define SWELL_REFRACTION_GLSL
#include "swell/gpu/bindings.h"
#include "frame.glsl"

layout(binding = SWELL_UNIT_REFRACTION_COLOR) uniform sampler2D refractionColor;
layout(binding = SWELL_UNIT_REFRACTION_DEPTH) uniform sampler2D refractionDepth;

// Light reaching the eye through the water surface at `surface`.
// Deep water where no geometry lies below gives the water's own colour.
vec3 refractedRadiance(vec3 surface, vec3 normal, vec2 screenUv, out float pathLength_m)
{
    vec2 uv = clamp(screenUv + normal.xz * refractionDistortion, vec2(0.001), vec2(0.999));
    float depth = texture(refractionDepth, uv).r;
    // The bent lookup must land on something under the water, not in front of it.
    vec3 below = worldFromScreen(uv, depth);
    if (depthHasGeometry(depth) && below.y > surface.y) {
        uv = screenUv;
        depth = texture(refractionDepth, uv).r;
        below = worldFromScreen(uv, depth);
    }
    pathLength_m = !depthHasGeometry(depth) ? 1e6 : max(distance(surface, below), 0.0);
    // The way up, and the daylight's way down to what is seen (straight
    // down, as mesh.frag attenuates the sky's light): the column scatters
    // back only what has come down as far as the bottom and back up again.
    vec3 transmitted = exp(-waterAbsorption * pathLength_m);
    float downPath_m = !depthHasGeometry(depth) ? 1e6 : max(surface.y - below.y, 0.0);
    vec3 bothWays = transmitted * exp(-waterAbsorption * downPath_m);
    vec3 seen = !depthHasGeometry(depth) ? vec3(0.0) : texture(refractionColor, uv).rgb;
    return seen * transmitted + waterDeep * (1.0 - bothWays);
}
#endif
