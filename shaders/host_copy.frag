// draw()'s picture moved between the host's framebuffer and a view's own
// target (render/view_passes.h), for a view drawn through that target (a
// render scale, antialiasing or the temporal resolve): the host's colour
// and depth under the viewport drawn into the target before the water is
// drawn over it; and, once the target is presented, its depth written back
// into the host's (colour writes off), so the host's later passes are
// tested against the water. Bilinear for the colour, the nearest texel for
// the depth (depths are never blended).
#include "swell/gpu/bindings.h"

layout(binding = SWELL_UNIT_POST_SOURCE) uniform sampler2D copyColour;
layout(binding = SWELL_UNIT_HOST_DEPTH) uniform sampler2D copyDepth;
// The drawn viewport's lower-left corner (pixels) and the reciprocals of
// its width and height: a pixel's place in the copies, 0..1.
uniform vec4 copyViewport;

out vec4 fragColor;

void main()
{
    vec2 uv = (gl_FragCoord.xy - copyViewport.xy) * copyViewport.zw;
    fragColor = texture(copyColour, uv);
    ivec2 size = textureSize(copyDepth, 0);
    gl_FragDepth = texelFetch(copyDepth, min(ivec2(uv * vec2(size)), size - 1), 0).r;
}
