// The host's motion vectors on Swell's sky: a direction, infinitely far,
// moves with the camera's turn alone (motion.glsl). Drawn straight into the
// host's framebuffer, where the depth is still at the far plane (sky.vert's
// triangle); drawn through the view's own target, first, wherever the
// host's own depth before the draw (its copy) was at the far plane, so that
// a pixel whose depth written back neither the sky nor the grid passes at
// this resolution (the horizon's edge) keeps the sky's vector.
#include "motion.glsl"
#include "swell/gpu/bindings.h"

layout(early_fragment_tests) in;

in vec2 vNdc;
layout(location = 0) out vec4 fragMotion;

// 1: test the host's depth copy below (the depth test then passes always).
uniform int motionSkyReadsHostDepth;
layout(binding = SWELL_UNIT_HOST_DEPTH) uniform sampler2D motionHostDepth;

void main()
{
    if (motionSkyReadsHostDepth != 0 &&
        depthHasGeometry(texelFetch(motionHostDepth, ivec2(gl_FragCoord.xy - viewportOrigin), 0).r))
        discard;
    vec3 direction = pixelRayDirection(vNdc);
    fragMotion = vec4(motionToPrevious(motionPreviousViewProj * vec4(direction, 0.0)), 0.0, 0.0);
}
