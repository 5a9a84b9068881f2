// World geometry: Phong diffuse from the sun, the sky's ambient light, fog.
#include "swell/gpu/label_classes.h"
#include "swell/gpu/variants.h"
#include "frame.glsl"
#include "fog.glsl"
#include "lighting.glsl"
#include "underwater.glsl"
#include "caustics.glsl"
#include "swash.glsl"
#ifndef SWELL_CLOUD_SHADOWS
#error "SWELL_CLOUD_SHADOWS is given by the program's flags (src/render/programs.h)"
#endif
#if SWELL_CLOUD_SHADOWS
#include "cloud_shadow.glsl"
#endif

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
// 1 for the ground the sea runs up (the island, the seabed), whose sand the
// swash wets (swash.glsl); 0 for objects.
uniform float swashWets;

void main()
{
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing)
        n = -n;
#if SWELL_LABEL_PASS
    // The ground the swash wets, where it is at least half wet (its sand
    // is drawn darker there, below); and, seen from above the sea, the
    // beach below the still water level that a trough leaves bare, which
    // the water has only just left (the shading keeps its dry albedo, as it
    // does the floor seen through the shallows, whose colour is the water's
    // own numbers). From below the sea the floor is under the water.
    uint semantic = label.x;
    bool bared = vPosition.y < 0.0 && n.y >= 0.7 && eyePosition.y > 0.0;
    float wetness = bared ? 1.0 : swashWetness(vPosition.y, n);
    if (semantic == SWELL_LABEL_TERRAIN && swashWets * wetness >= SWELL_LABEL_WET_SAND_WETNESS)
        semantic = SWELL_LABEL_WET_SAND;
    writeLabels(distance(vPosition, eyePosition), n, semantic, label.y);
    return;
#endif
    vec3 ambient = max(skyAmbient(n), vec3(0.0));
    vec3 sun = vec3(phongDiffuse(n));
#if SWELL_DEBUG_VIEW == SWELL_VIEW_SHADED
    // Below the mean level the light comes through the water, seen from
    // above or below alike: the sky's attenuated by the water above p (as
    // the in-scattered light is, underwater.glsl), the sun's refracted,
    // focused by the waves and absorbed along its ray (caustics.glsl).
    if (vPosition.y < 0.0) {
        ambient *= exp(-waterAbsorption * -vPosition.y);
        // The pixel's footprint at its distance (a level floor's, seen
        // face on), in the map's texels: its mip level.
        float footprint_m = 2.0 * distance(vPosition, eyePosition) / (viewportSize.y * projectionFocalY);
        sun = causticsSunlight(n, vPosition, waterAbsorption, log2(max(footprint_m / causticsTexel_m(), 1.0)));
    }
#endif
#if SWELL_CLOUD_SHADOWS
    // The cloud layer's shadow (cloud_shadow.glsl), over the pixel's
    // footprint at its distance.
    sun *= cloudShadowAt(vPosition, 2.0 * distance(vPosition, eyePosition) / (viewportSize.y * projectionFocalY));
#endif
    vec3 light = ambient + sunColor * sunIntensity * sun;
    vec3 albedo = vColor;
#if SWELL_DEBUG_VIEW == SWELL_VIEW_SHADED
    // The swash's wet sand, darker up to the run-up line.
    albedo *= mix(1.0, kWetSandAlbedo, swashWets * swashWetness(vPosition.y, n));
#endif
    vec3 color = albedo * light;
#if SWELL_DEBUG_VIEW == SWELL_VIEW_NORMALS
    color = n * 0.5 + 0.5;
#endif
    // Fog measured from the real eye, also in the mirrored pass (where the
    // mirrored point is as far from the eye as the real one's reflection).
    color = applyFog(color, distance(vPosition, eyePosition), vPosition - eyePosition);
#if SWELL_DEBUG_VIEW == SWELL_VIEW_SHADED
    // Underwater hook: seen from below the surface, the water's absorption
    // and in-scattering replace the air's fog (underwater.glsl).
    if (pixelUnderwater())
        color = underwaterGeometry(albedo * light, vPosition);
#endif
    fragColor = passOutput(color);
}
