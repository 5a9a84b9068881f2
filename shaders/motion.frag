// The host's motion vectors for a drawn surface (the water's grid, the
// world's meshes): the previous clip position, interpolated perspective-
// correctly over the triangle, is the previous place of the very point the
// fragment's centre shows (motion.glsl).
#include "motion.glsl"

in vec4 vPreviousClip;
layout(location = 0) out vec4 fragMotion;

void main()
{
    fragMotion = vec4(motionToPrevious(vPreviousClip), 0.0, 0.0);
}
