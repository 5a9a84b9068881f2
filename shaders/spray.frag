// The spray's puffs (spray.vert): white mist, lit by the sky and the sun
// (water drops scatter nearly all the light they meet, most of it forward),
// fogged with the distance as the world is; blended over the frame.
#include "frame.glsl"
#include "fog.glsl"

in vec2 gCorner;
in vec3 gPosition;
in float gOpacity;

layout(location = 0) out vec4 fragColor;

void main()
{
    float r2 = dot(gCorner, gCorner);
    if (r2 >= 1.0)
        discard;
    // A Gaussian puff: densest at its heart, no edge.
    float density = exp(-3.0 * r2) - exp(-3.0);
    // Lit as the whitecaps are (water.frag), the sun's share brighter
    // looking towards it (drops scatter forwards), with an albedo of 1
    // (drops absorb next to nothing; the foam's 0.55 to 0.65 is a layer the
    // water shows through): chosen by eye.
    vec3 toEye = normalize(eyePosition - gPosition);
    float forward = max(dot(-toEye, sunDirection), 0.0);
    vec3 sunLight = sunColor * sunIntensity * max(sunDirection.y, 0.0);
    vec3 light = sunLight * (0.6 + 0.4 * forward * forward) + skyHorizon * 0.5;
    vec3 color = applyFog(1.0 * light, distance(gPosition, eyePosition));
    fragColor = vec4(passOutput(color).rgb, gOpacity * density);
}
