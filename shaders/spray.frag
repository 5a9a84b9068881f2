// The spray's streaks (spray.geom): fine water drops, lit by the sky and
// the sun (drops scatter nearly all the light they meet, most of it
// forward), fogged with the distance as the world is; blended over the
// frame.
#include "frame.glsl"
#include "fog.glsl"

in vec2 gRibbon;
in vec3 gPosition;
in float gOpacity;

layout(location = 0) out vec4 fragColor;

void main()
{
    // Across: a Gaussian profile, no edge. Along: the tail fades in (the
    // streak's oldest part has spread into the air), the head ends softly.
    float across = exp(-3.0 * gRibbon.y * gRibbon.y) - exp(-3.0);
    float along = smoothstep(0.0, 0.7, gRibbon.x) * (1.0 - 0.6 * smoothstep(0.8, 1.0, gRibbon.x));
    // Lit as the whitecaps are (water.frag), the sun's share brighter
    // looking towards it (drops scatter forwards), with an albedo of 1
    // (drops absorb next to nothing; the foam's 0.55 to 0.65 is a layer the
    // water shows through): chosen by eye.
    vec3 toEye = normalize(eyePosition - gPosition);
    float forward = max(dot(-toEye, sunDirection), 0.0);
    vec3 sunLight = sunColor * sunIntensity * max(sunDirection.y, 0.0);
    vec3 light = sunLight * (0.6 + 0.4 * forward * forward) + skyHorizon * 0.5;
    vec3 color = applyFog(light, distance(gPosition, eyePosition));
    fragColor = vec4(passOutput(color).rgb, gOpacity * across * along / (1.0 - exp(-3.0)));
}
