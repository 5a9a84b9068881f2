// The temporal resolve's result (shaders/temporal_resolve.frag) into an
// output that a blit of its 8-bit copy cannot fill as well: a multisampled
// one (a blit there needs the same format on both sides), a float one (it
// would lose the history's precision), one with several colour buffers.
// Its colour, opaque (the history's alpha holds its weight).
#include "swell/gpu/bindings.h"

layout(binding = SWELL_UNIT_TEMPORAL_HISTORY) uniform sampler2D history;
// The output viewport's lower-left corner, pixels (draw()'s views may lie
// anywhere in the host's framebuffer; the history starts at its corner).
uniform ivec2 presentOrigin;

out vec4 fragColor;

void main()
{
    fragColor = vec4(texelFetch(history, ivec2(gl_FragCoord.xy) - presentOrigin, 0).rgb, 1.0);
}
