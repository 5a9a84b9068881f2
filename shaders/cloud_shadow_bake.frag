// Bakes the cloud layer's shadow map (render/cloud_shadow_map.h; drawn with
// fullscreen.vert into its base level): per texel, the layer's
// transmittance along the sun's ray from the texel's centre on the sea's
// mean level (clouds.glsl's cloudShadowTransmittance, the twin of the C++
// model's), its octaves finer than a texel averaged away.
#include "clouds.glsl"

uniform vec2 bakeCorner_m; // texel (0, 0)'s outer corner, absolute world x, z, m
uniform float bakeTexel_m; // a texel's width, m
uniform vec3 bakeSun;      // towards the sun, unit

in vec2 vNdc;
out vec4 fragColor;

void main()
{
    vec2 xz = bakeCorner_m + (floor(gl_FragCoord.xy) + 0.5) * bakeTexel_m;
    fragColor = vec4(cloudShadowTransmittance(vec3(xz.x, 0.0, xz.y), bakeSun, bakeTexel_m), 0.0, 0.0, 1.0);
}
