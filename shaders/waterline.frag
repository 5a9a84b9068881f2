// The waterline mask (see underwater.glsl): the water surface alone, depth
// tested against itself, keeps for each pixel the side from which its
// nearest fragment beyond the near plane is seen.
#include "swell/gpu/underwater.h"
#include "frame.glsl"
#include "underwater.glsl"

in vec3 vPosition;
out vec4 fragColor;

// Metres to the mask's depth: the distance scaled into [0, 1], so the
// depth test compares distances to float precision (a part in 10^7 of
// each), where a standard depth buffer at a near plane of 0.1 m tells
// fragments 800 m off apart only 0.2 m or more in depth. A far crest's
// faces, front and back, meet at its ridge closer than that: with the
// frame's depth the back face won pixels along the ridge, and the mask
// said the water there was seen from below (a speck of the depths' colour
// on the horizon's waves). 10^8 m: beyond any far plane a scene accepts.
const float kMaskDepthPerMetre = 1e-8;

void main()
{
    gl_FragDepth = clamp(distance(vPosition, eyePosition) * kMaskDepthPerMetre, 0.0, 1.0);
    fragColor = vec4(facetSeenFromBelow(vPosition) ? SWELL_WATERLINE_BELOW : SWELL_WATERLINE_ABOVE);
}
