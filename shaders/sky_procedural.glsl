// The built-in procedural sky: a gradient from horizon to zenith and a glow
// around the sun. It is not sampled per pixel: sky_bake.frag renders it into
// the faces of a cubemap once (and again when the sun or sky changes), and
// every sky lookup samples that cubemap, the same path a user's six images take.
#ifndef SWELL_SKY_PROCEDURAL_GLSL
#define SWELL_SKY_PROCEDURAL_GLSL
#include "frame.glsl"

// Linear radiance of the procedural sky along a unit direction, without fog
// and without the sun's disc (see sunDisc in sky.glsl).
vec3 proceduralSky(vec3 d)
{
    float elevation = clamp(d.y, 0.0, 1.0);
    vec3 color = mix(skyHorizon, skyZenith, pow(elevation, 0.45));
    // Below the horizon the sky shows the horizon colour (the reflection
    // pass can look there through wave slopes).
    if (d.y < 0.0)
        color = skyHorizon;
    // The glow around the sun: lobes 5 and 30 degrees wide, smooth enough for
    // the cubemap's texels (the narrow one spans about ten of them).
    float cosToSun = dot(d, sunDirection);
    float glow = pow(max(cosToSun, 0.0), 200.0) * 0.35 + pow(max(cosToSun, 0.0), 8.0) * 0.12;
    return color + sunColor * sunIntensity * glow;
}
#endif
