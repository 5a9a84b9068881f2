// The paper's linear fog, one function for world geometry, water and sky.
#ifndef SWELL_FOG_GLSL
#define SWELL_FOG_GLSL
#include "frame.glsl"

// 0 at fogStart_m metres from the eye, 1 at fogEnd_m and beyond.
float fogAmount(float distance_m)
{
    return clamp((distance_m - fogStart_m) / max(fogEnd_m - fogStart_m, 1e-3), 0.0, 1.0);
}

vec3 applyFog(vec3 color, float distance_m)
{
    return mix(color, fogColor, fogAmount(distance_m));
}

// The sky has no distance; it is fogged as if the view ray met a layer of
// fog fogSkyLayer_m metres up, so the horizon (where that distance grows without
// bound) reaches full fog exactly where the water does.
float skyDistance(vec3 direction)
{
    return fogSkyLayer_m / max(direction.y, 1e-4);
}
#endif
