// The host's motion vectors (DrawOptions::motionVectors, docs/LIBRARY.md
// "Motion vectors"): where the point a fragment shows lay in the view's
// previous draw, less the fragment's centre, in framebuffer pixels (GL's
// lower-left origin). The motion pass's viewport is the host's, so the
// frame block's viewportOrigin and viewportSize are the framebuffer's
// pixels of the NDC square.
#ifndef SWELL_MOTION_GLSL
#define SWELL_MOTION_GLSL
#include "frame.glsl"

// The previous draw's view and projection, taking positions relative to
// THIS draw's render origin (the shift between the two origins folded in,
// in double on the CPU) to the previous draw's clip space.
uniform mat4 motionPreviousViewProj;
// 1, or 0 where the view has no previous draw to move from: every vector
// exactly zero.
uniform float motionWeight;

// The vector from this fragment's centre to where `previousClip` (the
// point's previous clip position) was seen, pixels. A point at infinity
// (the sky: w of the position 0) gives the camera's turn alone. A macro:
// the vertex shaders include this file too, and have no gl_FragCoord.
#define motionToPrevious(previousClip) \
    (motionWeight * (viewportOrigin + ((previousClip).xy / (previousClip).w * 0.5 + 0.5) * viewportSize - gl_FragCoord.xy))
#endif
