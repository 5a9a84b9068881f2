// What is seen through the water: the world below the surface from pass 1b,
// bent by the normal and absorbed per channel with the path length (Beer-Lambert).
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
    vec3 transmitted = exp(-waterAbsorption * pathLength_m);
    vec3 seen = !depthHasGeometry(depth) ? vec3(0.0) : texture(refractionColor, uv).rgb;
    return seen * transmitted + waterDeep * (1.0 - transmitted);
}
#endif
