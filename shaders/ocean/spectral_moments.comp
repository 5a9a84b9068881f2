// Second moments of the spectral ocean's slopes, mipmapped beside the slopes
// themselves (LEAN mapping: Olano & Baker 2010, "LEAN Mapping", I3D, sec. 3):
// over any footprint, E[s^2] - E[s]^2 from the two mip chains is the slope
// variance the footprint's mean slope leaves out, which shading turns into
// the spread of the highlight instead of losing it.
#include "swell/shader_constants.h"

layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = 3, rgba32f) uniform readonly image2DArray derivatives; // .x: dDy/dx, .y: dDy/dz
layout(binding = 5, rgba32f) uniform writeonly image2DArray moments;    // sx^2, sz^2, sx*sz, 0

void main()
{
    ivec3 p = ivec3(gl_GlobalInvocationID);
    vec2 s = imageLoad(derivatives, p).xy;
    imageStore(moments, p, vec4(s.x * s.x, s.y * s.y, s.x * s.y, 0.0));
}
