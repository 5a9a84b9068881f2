// World geometry: Phong diffuse from the sun, the sky's ambient light, fog.
#include "frame.glsl"
#include "fog.glsl"
#include "lighting.glsl"
#include "underwater.glsl"

in vec3 vPosition;
in vec3 vNormal;
in vec3 vColor;
#if SWELL_LABEL_PASS
#include "labels.glsl"
// This draw's semantic class and instance (0: none, the terrain).
uniform uvec2 label;
#else
out vec4 fragColor;
#endif

void main()
{
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing)
        n = -n;
#if SWELL_LABEL_PASS
    writeLabels(distance(vPosition, eyePosition), n, label.x, label.y);
    return;
#endif
    vec3 ambient = max(skyAmbient(n), vec3(0.0));
    vec3 light = ambient + sunColor * sunIntensity * phongDiffuse(n);
    vec3 color = vColor * light;
#if SWELL_DEBUG_VIEW == SWELL_VIEW_NORMALS
    color = n * 0.5 + 0.5;
#endif
    // Fog measured from the real eye, also in the mirrored pass (where the
    // mirrored point is as far from the eye as the real one's reflection).
    color = applyFog(color, distance(vPosition, eyePosition));
#if SWELL_DEBUG_VIEW == SWELL_VIEW_SHADED
    // Underwater hook: seen from below the surface, the water's absorption
    // and in-scattering replace the air's fog (underwater.glsl).
    if (pixelUnderwater())
        color = underwaterGeometry(vColor * light, vPosition);
#endif
    fragColor = passOutput(color);
}
