// The waterline mask (see underwater.glsl): the water surface alone, depth
// tested against itself, keeps for each pixel the side from which its
// nearest fragment beyond the near plane is seen.
#include "swell/gpu/underwater.h"
#include "frame.glsl"
#include "underwater.glsl"

in vec3 vPosition;
out vec4 fragColor;

void main()
{
    fragColor = vec4(facetSeenFromBelow(vPosition) ? SWELL_WATERLINE_BELOW : SWELL_WATERLINE_ABOVE);
}
