// The paper's linear fog, one function for world geometry, water and sky;
// with fog.model = "atmosphere", aerial perspective.
#ifndef SWELL_FOG_GLSL
#define SWELL_FOG_GLSL
#include "frame.glsl"
#include "sky.glsl"

// 0 at fogStart_m metres from the eye, 1 at fogEnd_m and beyond.
float fogAmount(float distance_m)
{
    return clamp((distance_m - fogStart_m) / max(fogEnd_m - fogStart_m, 1e-3), 0.0, 1.0);
}

// The colour distance veils towards along a direction: the scene's, or
// (aerial perspective) the sky's at the horizon in the direction's azimuth,
// the light a long level ray through the air gathers (the sun's disc left
// out; straight up or down, any azimuth).
vec3 fogColorAlong(vec3 direction)
{
    if (fogFromSky == 0)
        return fogColor;
    float level = length(direction.xz);
    vec3 horizon = level > 1e-6 ? vec3(direction.x / level, 0.0, direction.z / level) : vec3(1.0, 0.0, 0.0);
    return textureLod(skyCube, horizon, 0.0).rgb;
}

// What lies distance_m away along a direction from the eye. Aerial
// perspective (Bruneton & Neyret 2008, sec. 4: L = T L0 + S): over a
// near-level path through air of uniform density and light, the
// transmittance is T = exp(-extinction d) and the light scattered in is the
// horizon's radiance times 1 - T (Hoffman & Preetham 2002, eq. 8 with
// uniform in-scattering), the horizon being what an endless such path
// gathers. The linear ramp's share is veiled on top, so that the drawn sea
// is fully veiled at fogEnd_m as in the paper's fog.
vec3 applyFog(vec3 color, float distance_m, vec3 direction)
{
    if (fogFromSky == 0)
        return mix(color, fogColor, fogAmount(distance_m));
    vec3 veiled = 1.0 - exp(-fogExtinction_per_m * distance_m) * (1.0 - fogAmount(distance_m));
    return mix(color, fogColorAlong(direction), veiled);
}

// The sky has no distance; it is fogged as if the view ray met a layer of
// fog fogSkyLayer_m metres up, so the horizon (where that distance grows without
// bound) reaches full fog exactly where the water does.
float skyDistance(vec3 direction)
{
    return fogSkyLayer_m / max(direction.y, 1e-4);
}

// The sky along a direction, fogged: by the ramp alone (the physical sky
// already holds the air's own veil).
vec3 applySkyFog(vec3 color, vec3 direction)
{
    return mix(color, fogColorAlong(direction), fogAmount(skyDistance(direction)));
}
#endif
