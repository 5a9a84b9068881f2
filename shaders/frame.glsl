// Per-pass uniforms, mirrored field by field by swell::detail::FrameUniforms
// (src/render/gpu_types.h); a test checks the offsets agree.
// Positions are relative to the render origin: the camera's x,z at y = 0,
// so float precision is spent near the viewer wherever the world is.
#ifndef SWELL_FRAME_GLSL
#define SWELL_FRAME_GLSL
#include "swell/shader_constants.h"

layout(std140, binding = SWELL_BINDING_FRAME) uniform Frame {
    mat4 passViewProj;      // this pass's camera (mirrored in the reflection pass)
    mat4 passInvViewProj;
    mat4 cameraViewProj;    // the real camera, for screen-space lookups
    mat4 cameraInvViewProj;
    vec4 clipPlane;         // world geometry keeps dot(clipPlane, (p, 1)) >= 0
    vec4 eyePosition;       // xyz: eye relative to the render origin, m
    vec4 sunDirection;      // xyz: towards the sun (unit), w: intensity
    vec4 sunColor;          // rgb: linear colour
    vec4 fogColor;          // rgb: linear colour, w: height of the fog layer for the sky, m
    vec4 fogRange;          // x: start, y: end, m
    vec4 skyZenith;         // rgb
    vec4 skyHorizon;        // rgb
    vec4 waterDeep;         // rgb: scattering colour of deep water
    vec4 waterAbsorption;   // rgb: Beer-Lambert coefficient, 1/m
    vec4 waterOptics;       // x: Fresnel F0, y: shininess, z: specular strength, w: refraction distortion
    vec4 gridShape;         // x: radius, m; y: cells per side; z: distance of the outer skirt, m; w: finest snap step (scaled), m
    vec4 gridFade;          // x: fade start, y: fade end, m
    vec4 gridCenter;        // xz: grid centre relative to the render origin, m
    vec4 gridLayout;        // x: 0 geometric, 1 paper; y: inner scale r0 times the scale, m; z: growth k; w: scale
    vec4 snapOffsets[SWELL_GRID_LEVELS]; // xy: grid centre (absolute) modulo each level's snap step, m; z: first ring of the level (geometric)
    vec4 reflectionParams;  // x: fixed distance, m; y: clip offset, m; z: mode (0 fixed, 1 ray march); w: world boxes in use (-1: unbounded)
    vec4 worldBoxes[2 * SWELL_MAX_WORLD_BOXES]; // min.xyz, max.xyz of boxes holding all world geometry, relative to the render origin, m
    vec4 viewport;          // xy: size in pixels, zw: 1 / size
    vec4 passFlags;         // x: 1 when this pass writes display colours (sRGB), 0 for linear targets
};

// The point the real camera sees at texture coordinate uv and window depth.
vec3 worldFromScreen(vec2 uv, float depth)
{
    vec4 p = cameraInvViewProj * vec4(vec3(uv, depth) * 2.0 - 1.0, 1.0);
    return p.xyz / p.w;
}

// Linear colour as this pass must store it: sRGB-encoded for display, as is otherwise.
vec4 passOutput(vec3 linear)
{
    if (passFlags.x > 0.5)
        linear = mix(12.92 * linear, 1.055 * pow(max(linear, 0.0), vec3(1.0 / 2.4)) - 0.055, step(0.0031308, linear));
    return vec4(linear, 1.0);
}

#endif
