// The built-in procedural sky (gradient and sun), and the cubemap sky.
#ifndef SWELL_SKY_GLSL
#define SWELL_SKY_GLSL
#include "frame.glsl"

layout(binding = SWELL_UNIT_SKY) uniform samplerCube skyCube;

vec3 skyRadiance(vec3 direction)
{
    vec3 d = normalize(direction);
#if SWELL_SKY_CUBEMAP
    vec3 color = texture(skyCube, d).rgb;
#else
    float elevation = clamp(d.y, 0.0, 1.0);
    vec3 color = mix(skyHorizon.rgb, skyZenith.rgb, pow(elevation, 0.45));
    // Below the horizon the sky shows the horizon colour (the reflection
    // pass can look there through wave slopes).
    if (d.y < 0.0)
        color = skyHorizon.rgb;
#endif
    // Sun disk (about 0.5 degrees, softened) and a glow around it.
    float cosToSun = dot(d, sunDirection.xyz);
    float disk = smoothstep(0.99996, 0.99999, cosToSun);
    float glow = pow(max(cosToSun, 0.0), 200.0) * 0.35 + pow(max(cosToSun, 0.0), 8.0) * 0.12;
    return color + sunColor.rgb * sunDirection.w * (disk * 20.0 + glow);
}
#endif
