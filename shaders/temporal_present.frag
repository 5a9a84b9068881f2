// The temporal resolve's result (shaders/temporal_resolve.frag) into the
// output: its colour, opaque (its alpha holds the history's weight).
#include "swell/shader_constants.h"

layout(binding = SWELL_UNIT_TEMPORAL_HISTORY) uniform sampler2D history;

out vec4 fragColor;

void main()
{
    fragColor = vec4(texelFetch(history, ivec2(gl_FragCoord.xy), 0).rgb, 1.0);
}
