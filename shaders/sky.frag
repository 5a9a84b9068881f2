// The sky behind everything, fogged toward the horizon with the same fog as the water.
#include "swell/gpu/label_classes.h"
#include "frame.glsl"
#include "fog.glsl"
#include "sky.glsl"
#include "underwater.glsl"

// Depth-tested before shading: drawn last, the sky is shaded only where
// nothing else was drawn (software rasterisers otherwise test after shading).
layout(early_fragment_tests) in;

in vec2 vNdc;
#if SWELL_LABEL_PASS
#define SWELL_LABEL_RAYS
#include "labels.glsl"
#else
out vec4 fragColor;
#endif

void main()
{
    vec3 direction = pixelRayDirection(vNdc);
#if SWELL_LABEL_PASS
    // Nothing drawn here. From below the surface: the water's depths. From
    // above, below the horizon: the unbounded sea past the drawn grid, a
    // plane at the mean level (the ray's distance to it, exact for calm
    // water); else the sky, infinitely far.
    const float infinity = uintBitsToFloat(0x7f800000u);
    dvec3 ray = labelPixelRay();
    if (pixelUnderwater())
        writeLabels(infinity, vec3(0.0), SWELL_LABEL_WATER, 0u);
    else if (ray.y < 0.0 && eyePosition.y > 0.0)
        writeLabels(float(double(eyePosition.y) / -ray.y), vec3(0.0, 1.0, 0.0), SWELL_LABEL_WATER, 0u);
    else
        writeLabels(infinity, vec3(0.0), SWELL_LABEL_SKY, 0u);
    return;
#endif
    vec3 color = applySkyFog(skyRadianceFiltered(direction), direction);
    // Underwater hook: below the surface, what no geometry covers is the
    // water's depths (underwater.glsl), and the shafts of light in them.
    if (pixelUnderwater())
        color = underwaterBackground(direction, -eyePosition.y) + underwaterShafts(eyePosition, direction, 1.0e6);
    fragColor = passOutput(color);
}
