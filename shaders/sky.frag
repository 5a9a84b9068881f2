// The sky behind everything, fogged toward the horizon with the same fog as the water.
#include "frame.glsl"
#include "fog.glsl"
#include "sky.glsl"
#include "underwater.glsl"

// Depth-tested before shading: drawn last, the sky is shaded only where
// nothing else was drawn (software rasterisers otherwise test after shading).
layout(early_fragment_tests) in;

in vec2 vNdc;
out vec4 fragColor;

void main()
{
    vec3 direction = pixelRayDirection(vNdc);
    vec3 color = applyFog(skyRadianceFiltered(direction), skyDistance(direction));
    // Underwater hook: below the surface, what no geometry covers is the
    // water's depths (underwater.glsl).
    if (pixelUnderwater())
        color = underwaterBackground(direction, -eyePosition.y);
    fragColor = passOutput(color);
}
