// Per-pass uniforms: the Frame block, declared from its C++ struct
// (swell::detail::FrameUniforms, src/render/gpu/blocks.h) at build time.
// Positions are relative to the render origin: the camera's x,z at y = 0,
// so float precision is spent near the viewer wherever the world is.
#ifndef SWELL_FRAME_GLSL
#define SWELL_FRAME_GLSL

// 1 in the label pass's programs (swell/dataset/labels.h): fragments write labels
// (labels.glsl) in place of a colour.
#ifndef SWELL_LABEL_PASS
#define SWELL_LABEL_PASS 0
#endif

// The Frame block: what each member holds is said in
// src/render/gpu/blocks.h (swell::detail::FrameUniforms), from which this is
// generated.
#include "gpu/frame_block.glsl"

// The point the real camera sees at texture coordinate uv and window depth.
vec3 worldFromScreen(vec2 uv, float depth)
{
    vec4 p = cameraInvViewProj * vec4(uv * 2.0 - 1.0, depth * depthNdcScale + depthNdcOffset, 1.0);
    return p.xyz / p.w;
}

// The window depth of an NDC z, in the view's depth convention.
float windowDepth(float ndcZ)
{
    return (ndcZ - depthNdcOffset) / depthNdcScale;
}

// Whether a window depth read back from a pass holds geometry (is nearer
// than the far plane it was cleared to).
bool depthHasGeometry(float depth)
{
    return depthFar > 0.5 ? depth < 1.0 : depth > 0.0;
}

// This pixel's coordinate in the pass's viewport, 0..1 (a macro: vertex
// shaders include this file too, and have no gl_FragCoord).
#define viewportUv() ((gl_FragCoord.xy - viewportOrigin) * viewportInvSize)

// The world point (relative to the render origin) on this pass's near plane
// at an NDC xy, and the unit direction of the eye's ray through it.
vec3 nearPlanePoint(vec2 ndc)
{
    vec4 p = passInvViewProj * vec4(ndc, nearNdcZ, 1.0);
    return p.xyz / p.w;
}
vec3 pixelRayDirection(vec2 ndc)
{
    return normalize(nearPlanePoint(ndc) - eyePosition);
}

// The far end of the ray through ndc: on the far plane, or 10^7 m along the
// ray where the far plane is at infinity (or past that).
vec3 farPlanePoint(vec2 ndc)
{
    vec3 near = nearPlanePoint(ndc);
    vec4 p = passInvViewProj * vec4(ndc, farNdcZ, 1.0);
    vec3 limit = near + pixelRayDirection(ndc) * 1.0e7;
    if (p.w <= 0.0 || distance(p.xyz, near * p.w) >= 1.0e7 * p.w)
        return limit;
    return p.xyz / p.w;
}

// Linear colour as this pass must store it: sRGB-encoded for display, as is otherwise.
vec4 passOutput(vec3 linear)
{
    if (passEncodesSrgb != 0)
        linear = mix(12.92 * linear, 1.055 * pow(max(linear, 0.0), vec3(1.0 / 2.4)) - 0.055, step(0.0031308, linear));
    return vec4(linear, 1.0);
}

#endif
