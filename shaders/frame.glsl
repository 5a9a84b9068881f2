// Per-pass uniforms, mirrored field by field by swell::detail::FrameUniforms
// (src/render/gpu_types.h); a test checks the offsets agree.
// Positions are relative to the render origin: the camera's x,z at y = 0,
// so float precision is spent near the viewer wherever the world is.
#ifndef SWELL_FRAME_GLSL
#define SWELL_FRAME_GLSL
#include "swell/shader_constants.h"

// 1 in the label pass's programs (swell/labels.h): fragments write labels
// (labels.glsl) in place of a colour.
#ifndef SWELL_LABEL_PASS
#define SWELL_LABEL_PASS 0
#endif

// 1 where the cloud layer's shadow map shades the sun's light point by
// point (cloud_shadow.glsl; the physical sky with clouds); 0: the frame's
// sunIntensity alone.
#ifndef SWELL_CLOUD_SHADOWS
#define SWELL_CLOUD_SHADOWS 0
#endif

// A box holding world geometry, relative to the render origin, m.
struct WorldBox {
    vec3 min_m;
    vec3 max_m;
};

// One snap level of the LOD grid (see grid.glsl).
struct GridLevel {
    vec2 snapOffset_m;       // grid centre (absolute) modulo this level's snap step, m
    vec2 coarseSnapOffset_m; // the same for the next coarser scale's grid (its own centre and steps), m
    float firstRing;         // geometric layout: the first ring that snaps to this level
    float coarseFirstRing;   // the same for the next coarser scale's rings
};

layout(std140, binding = SWELL_BINDING_FRAME) uniform Frame {
    mat4 passViewProj;      // this pass's camera (mirrored in the reflection pass)
    mat4 passInvViewProj;
    mat4 cameraViewProj;    // the real camera, for screen-space lookups
    mat4 cameraInvViewProj;
    vec4 clipPlane;         // world geometry keeps dot(clipPlane, (p, 1)) >= 0
    vec3 eyePosition;       // the eye relative to the render origin, m
    float fresnelF0;        // reflectance looking straight down, 0..1
    vec3 sunDirection;      // towards the sun, unit
    float sunIntensity;     // multiplier
    vec3 sunColor;          // linear RGB
    float fogSkyLayer_m;    // height of the fog layer the sky is fogged through, m
    vec3 fogColor;          // linear RGB
    float fogStart_m;       // fog begins, m from the eye
    vec3 skyZenith;         // linear RGB
    float fogEnd_m;         // fog is complete, m
    vec3 skyHorizon;        // linear RGB
    float shininess;        // Phong exponent of the sun glint
    vec3 waterDeep;         // linear RGB scattered back by deep water
    float specularStrength; // sun glint multiplier
    vec3 waterAbsorption;   // Beer-Lambert coefficient per channel, 1/m
    float refractionDistortion; // how far the normal bends the refraction lookup
    vec2 gridCenter;        // x,z of the grid centre relative to the render origin, m
    float gridRadius_m;     // reach of the detailed grid (paper layout), m
    float gridCells;        // cells per side
    float gridSkirt_m;      // distance of the outer skirt, m
    float gridFinestStep_m; // finest snap step (scaled), m
    float gridFadeStart_m;  // wave heights fade to 0 between these distances, m
    float gridFadeEnd_m;
    float gridInnerScale_m; // geometric layout: inner scale r0 times the grid scale, m
    float gridGrowth;       // geometric layout: growth k of this scale
    float reflectionFixedDistance_m; // the paper's lookup: step along the reflected ray, m
    int worldBoxCount;      // boxes in use; -1: unbounded (every ray is marched)
    vec2 viewportSize;      // pixels
    vec2 viewportInvSize;   // 1 / pixels
    int passEncodesSrgb;    // 1 when this pass writes display colours (sRGB), 0 for linear targets
    float waveHeightDeviation_m; // the wave model's height standard deviation, m
    float waveMeanSquareSlope; // the sea's mean |grad eta|^2, for the reflection's masking
    float gridMorph;        // geometric layout: 0..1, how far vertices have slid toward the next coarser scale
    vec2 gridCoarseCenterShift; // the next coarser scale's grid centre relative to gridCenter, m
    float gridCoarseGrowth; // geometric layout: the next coarser scale's growth (its inner scale is twice this one's)
    float waveReachVertical_m; // the surface (waves and wake) stays within +- this of the mean level this frame, m
    int eyeUnderwater;      // 1 when the eye is below the surface under it (the refraction pass's choice), else 0
    float depthNdcScale;    // NDC z = window depth * depthNdcScale + depthNdcOffset (2, -1 or 1, 0)
    vec2 viewportOrigin;    // the pass's viewport's lower-left corner in its framebuffer, pixels
    float depthNdcOffset;
    float depthFar;         // the window depth of nothing drawn: 1, or 0 for reversed-Z
    float nearNdcZ;         // NDC z of the near plane (-1, 0, or 1 reversed) and of the far one
    float farNdcZ;
    float projectionFocalY; // the projection's [1][1]: 1 / tan(half the vertical field of view)
    // The footprint the shading filters the water's detail by, over the
    // drawn pixel's: the output pixel's share of it (the render scale, below
    // 1) when a temporal resolve brings the frames to the output's
    // resolution, so that the jittered frames together hold the detail of
    // the output's pixels; else 1.
    float footprintScale;
    // 1 in a main pass drawn for the temporal resolve: the water writes alpha
    // 0 (everything else 1), which the resolve reads as "this pixel's
    // pattern moves with the waves, not with the camera".
    int passMarksWater;
    GridLevel gridLevels[SWELL_GRID_LEVELS];
    WorldBox worldBoxes[SWELL_MAX_WORLD_BOXES];
    // World objects' ambient light: order-2 spherical harmonics of the sky's
    // irradiance (rgb; Ramamoorthi & Hanrahan 2001), see skyAmbient() in lighting.glsl.
    vec4 ambientSh[9];
    // Aerial perspective (fog.model = "atmosphere"; fog.glsl): the clear
    // air's extinction at the sea, 1/m per channel (0 without the physical
    // sky), and 1 when the fog takes the sky's colour at the horizon.
    vec3 fogExtinction_per_m;
    int fogFromSky;
};

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
