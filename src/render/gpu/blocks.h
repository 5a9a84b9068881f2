// The renderer's std140 uniform blocks: each C++ struct, what each member
// holds, and its description (gl/block_layout.h), from which the GLSL
// declaration is generated at build time (gpu/<name>_block.glsl, listed in
// render/gpu/glsl_files.h). Positions are relative to the render origin:
// the camera's x, z at the sea's mean level, so float precision is spent
// near the viewer wherever the world is.
//
// To add a block: its struct and blockStructOf() here (or next to the code
// that fills it, e.g. a wave model's), its binding point in
// swell/gpu/bindings.h, a line in glslBlocks() (render/gpu/glsl_files.h),
// and #include "gpu/<its file>" where the shaders read it;
// tests/gl/test_uniform_layout.cpp then checks it with the driver.
#pragma once

#include "gl/block_layout.h"
#include "ocean/foam/gpu/foam_noise_block.h"
#include "swell/gpu/limits.h"
#include "swell/gpu/ocean.h"
#include "swell/gpu/sky.h"
#include "swell/gpu/underwater.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstddef>

namespace swell::detail {

// A box holding world geometry, relative to the render origin, m (the
// reflection's ray march skips what lies outside every box).
struct alignas(16) WorldBoxUniform {
    glm::vec3 min_m;
    float unused0; // (padding: GLSL's vec3 leaves it empty)
    glm::vec3 max_m;
    float unused1;
};

// One snap level of the LOD grid (see shaders/grid.glsl).
struct alignas(16) GridLevelUniform {
    glm::vec2 snapOffset_m;       // grid centre (absolute) modulo this level's snap step, m
    glm::vec2 coarseSnapOffset_m; // the same for the next coarser scale's grid (its own centre and steps), m
    float firstRing;              // geometric layout: the first ring that snaps to this level
    float coarseFirstRing;        // the same for the next coarser scale's rings
};

// The Frame block (shaders/frame.glsl): what one pass's programs share.
struct alignas(16) FrameUniforms {
    glm::mat4 passViewProj;      // this pass's camera (mirrored in the reflection pass)
    glm::mat4 passInvViewProj;
    glm::mat4 cameraViewProj;    // the real camera, for screen-space lookups
    glm::mat4 cameraInvViewProj;
    glm::vec4 clipPlane;         // world geometry keeps dot(clipPlane, (p, 1)) >= 0
    glm::vec3 eyePosition;       // the eye relative to the render origin, m
    float fresnelF0;             // reflectance looking straight down, 0..1
    glm::vec3 sunDirection;      // towards the sun, unit
    float sunIntensity;          // multiplier
    glm::vec3 sunColor;          // linear RGB
    float fogSkyLayer_m;         // height of the fog layer the sky is fogged through, m
    glm::vec3 fogColor;          // linear RGB
    float fogStart_m;            // fog begins, m from the eye
    glm::vec3 skyZenith;         // linear RGB
    float fogEnd_m;              // fog is complete, m
    glm::vec3 skyHorizon;        // linear RGB
    float shininess;             // Phong exponent of the sun glint
    glm::vec3 waterDeep;         // linear RGB scattered back by deep water
    float specularStrength;      // sun glint multiplier
    glm::vec3 waterAbsorption;   // Beer-Lambert coefficient per channel, 1/m
    float refractionDistortion;  // how far the normal bends the refraction lookup
    glm::vec2 gridCenter;        // x,z of the grid centre relative to the render origin, m
    float gridRadius_m;          // reach of the detailed grid (paper layout), m
    float gridCells;             // cells per side
    float gridSkirt_m;           // distance of the outer skirt, m
    float gridFinestStep_m;      // finest snap step (scaled), m
    float gridFadeStart_m;       // wave heights fade to 0 between these distances, m
    float gridFadeEnd_m;
    float gridInnerScale_m;      // geometric layout: inner scale r0 times the grid scale, m
    float gridGrowth;            // geometric layout: growth k of this scale
    float reflectionFixedDistance_m; // the paper's lookup: step along the reflected ray, m
    int worldBoxCount;           // boxes in use; -1: unbounded (every ray is marched)
    glm::vec2 viewportSize;      // pixels
    glm::vec2 viewportInvSize;   // 1 / pixels
    int passEncodesSrgb;         // 1 when this pass writes display colours (sRGB), 0 for linear targets
    float waveHeightDeviation_m; // the wave model's height standard deviation, m
    float waveMeanSquareSlope;   // the sea's mean |grad eta|^2, for the reflection's masking
    float gridMorph;             // geometric layout: 0..1, how far vertices have slid toward the next coarser scale
    glm::vec2 gridCoarseCenterShift; // the next coarser scale's grid centre relative to gridCenter, m
    float gridCoarseGrowth;      // geometric layout: the next coarser scale's growth (its inner scale is twice this one's)
    float waveReachVertical_m;   // the surface (waves and wake) stays within +- this of the mean level this frame, m
    int eyeUnderwater;           // 1 when the eye is below the surface under it (the refraction pass's choice), else 0
    float depthNdcScale;         // NDC z = window depth * depthNdcScale + depthNdcOffset (2, -1 or 1, 0)
    glm::vec2 viewportOrigin;    // the pass's viewport's lower-left corner in its framebuffer, pixels
    float depthNdcOffset;
    float depthFar;              // the window depth of nothing drawn: 1, or 0 for reversed-Z
    float nearNdcZ;              // NDC z of the near plane (-1, 0, or 1 reversed) and of the far one
    float farNdcZ;
    float projectionFocalY;      // the projection's [1][1]: 1 / tan(half the vertical field of view)
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
    // The offshore sea's significant height times the deep-water wavelength
    // of its peak period, m^2 (Stockdon et al. 2006's H0 L0): how far up the
    // beaches the swash wets the sand (shaders/swash.glsl); 0: a calm sea.
    float swashH0L0_m2;
    GridLevelUniform gridLevels[SWELL_GRID_LEVELS];
    WorldBoxUniform worldBoxes[SWELL_MAX_WORLD_BOXES];
    // World objects' ambient light: order-2 spherical harmonics of the sky's
    // irradiance (rgb; Ramamoorthi & Hanrahan 2001), see skyAmbient() in lighting.glsl.
    glm::vec4 ambientSh[9];
    // Aerial perspective (fog.model = "atmosphere"; fog.glsl): the clear
    // air's extinction at the sea, 1/m per channel (0 without the physical
    // sky), and 1 when the fog takes the sky's colour at the horizon.
    glm::vec3 fogExtinction_per_m;
    int fogFromSky;
    // The contact foam's map (render/contact_map.h, shaders/contact.glsl):
    // its texel (0, 0)'s outer corner relative to the render origin (x, z,
    // m) and its side (m); the foam band's e-folding width (m) and the
    // distance at which it has faded out (m); 1 when the map holds contacts
    // this view, else 0 (no contact foam anywhere).
    glm::vec2 contactCorner_m;
    float contactSize_m;
    float contactBand_m;
    float contactReach_m;
    int contactOn;
    glm::vec2 contactUnused;
};

// The Caustics block (shaders/caustics.glsl; render/caustics_map.h).
struct alignas(16) CausticsUniforms {
    glm::vec3 sun{0.0f, 1.0f, 0.0f}; // towards the sun, unit (the scene's)
    float mapSize_m = float(SWELL_CAUSTICS_EXTENT_M); // the map's side, m
    glm::vec2 mapCorner_m{0.0f};     // its texel (0, 0)'s outer corner relative to the render origin, x, z, m
    glm::vec2 sourceCorner_m{0.0f};  // the source grid's vertex (0, 0), rest point relative to the render origin, m
    glm::vec2 gridCenter_m{0.0f};    // the wave model's grid centre relative to the render origin, m
    float cellSize_m = 1.0f;         // the source grid's spacing, m
    int cells = SWELL_CAUSTICS_CELLS; // source grid cells per side
    glm::vec4 sliceDepth_m{0.0f};    // xyz: each slice's depth below the mean level, m
};

// The CloudShadow block (shaders/cloud_shadow.glsl; render/cloud_shadow_map.h).
struct alignas(16) CloudShadowUniforms {
    glm::vec2 corner_m{0.0f}; // the map's texel (0, 0)'s outer corner relative to the render origin, x, z, m
    float size_m = float(SWELL_CLOUD_SHADOW_EXTENT_M); // the map's side, m
    // The layer's transmittance towards the sun from the baked sky's
    // observer (cloudTransmittance): the sun's disc the sky shows.
    float skySun = 1.0f;
};

// The Wake block (shaders/wake.glsl; render/wake_texture.h).
struct alignas(16) WakeUniforms {
    glm::vec2 corner_m{0.0f}; // centre of cell (0, 0) relative to the render origin, x, z, m
    float cellSize_m = 1.0f;  // m
    int cells = 0;            // per side; 0: no wake this frame
};

// The SurfaceSources block of the renderer's generated surface_sources.glsl
// (render/surface_sources.h).
struct alignas(16) SurfaceSourcesUniforms {
    glm::vec4 parameters[SWELL_MAX_SURFACE_SOURCES * 4]; // four a source (SurfaceSource::gpuParameters)
    // The sources' foam's texture: the whitecaps' lattices, anchored to the
    // world at the render origin (p_m = 0), not drawn out along any wind.
    FoamNoiseUniform foamNoise[SWELL_FOAM_NOISE_MAPS];
    float breakingFoamAmount = 0.0f; // source foam above this amount is a breaking's own (1 s old)
};

inline const gl::BlockStruct& blockStructOf(const WorldBoxUniform*)
{
    using S = WorldBoxUniform;
    static const gl::BlockStruct s{"WorldBox", "swell::detail::WorldBoxUniform", sizeof(S),
                                   {SWELL_BLOCK_MEMBER(S, min_m), SWELL_BLOCK_PADDING(S, unused0),
                                    SWELL_BLOCK_MEMBER(S, max_m), SWELL_BLOCK_PADDING(S, unused1)}};
    return s;
}

inline const gl::BlockStruct& blockStructOf(const GridLevelUniform*)
{
    using S = GridLevelUniform;
    static const gl::BlockStruct s{"GridLevel", "swell::detail::GridLevelUniform", sizeof(S),
                                   {SWELL_BLOCK_MEMBER(S, snapOffset_m), SWELL_BLOCK_MEMBER(S, coarseSnapOffset_m),
                                    SWELL_BLOCK_MEMBER(S, firstRing), SWELL_BLOCK_MEMBER(S, coarseFirstRing)}};
    return s;
}

inline const gl::BlockStruct& blockStructOf(const FrameUniforms*)
{
    using S = FrameUniforms;
    static const gl::BlockStruct s{"Frame", "swell::detail::FrameUniforms", sizeof(S), {
        SWELL_BLOCK_MEMBER(S, passViewProj),
        SWELL_BLOCK_MEMBER(S, passInvViewProj),
        SWELL_BLOCK_MEMBER(S, cameraViewProj),
        SWELL_BLOCK_MEMBER(S, cameraInvViewProj),
        SWELL_BLOCK_MEMBER(S, clipPlane),
        SWELL_BLOCK_MEMBER(S, eyePosition),
        SWELL_BLOCK_MEMBER(S, fresnelF0),
        SWELL_BLOCK_MEMBER(S, sunDirection),
        SWELL_BLOCK_MEMBER(S, sunIntensity),
        SWELL_BLOCK_MEMBER(S, sunColor),
        SWELL_BLOCK_MEMBER(S, fogSkyLayer_m),
        SWELL_BLOCK_MEMBER(S, fogColor),
        SWELL_BLOCK_MEMBER(S, fogStart_m),
        SWELL_BLOCK_MEMBER(S, skyZenith),
        SWELL_BLOCK_MEMBER(S, fogEnd_m),
        SWELL_BLOCK_MEMBER(S, skyHorizon),
        SWELL_BLOCK_MEMBER(S, shininess),
        SWELL_BLOCK_MEMBER(S, waterDeep),
        SWELL_BLOCK_MEMBER(S, specularStrength),
        SWELL_BLOCK_MEMBER(S, waterAbsorption),
        SWELL_BLOCK_MEMBER(S, refractionDistortion),
        SWELL_BLOCK_MEMBER(S, gridCenter),
        SWELL_BLOCK_MEMBER(S, gridRadius_m),
        SWELL_BLOCK_MEMBER(S, gridCells),
        SWELL_BLOCK_MEMBER(S, gridSkirt_m),
        SWELL_BLOCK_MEMBER(S, gridFinestStep_m),
        SWELL_BLOCK_MEMBER(S, gridFadeStart_m),
        SWELL_BLOCK_MEMBER(S, gridFadeEnd_m),
        SWELL_BLOCK_MEMBER(S, gridInnerScale_m),
        SWELL_BLOCK_MEMBER(S, gridGrowth),
        SWELL_BLOCK_MEMBER(S, reflectionFixedDistance_m),
        SWELL_BLOCK_MEMBER(S, worldBoxCount),
        SWELL_BLOCK_MEMBER(S, viewportSize),
        SWELL_BLOCK_MEMBER(S, viewportInvSize),
        SWELL_BLOCK_MEMBER(S, passEncodesSrgb),
        SWELL_BLOCK_MEMBER(S, waveHeightDeviation_m),
        SWELL_BLOCK_MEMBER(S, waveMeanSquareSlope),
        SWELL_BLOCK_MEMBER(S, gridMorph),
        SWELL_BLOCK_MEMBER(S, gridCoarseCenterShift),
        SWELL_BLOCK_MEMBER(S, gridCoarseGrowth),
        SWELL_BLOCK_MEMBER(S, waveReachVertical_m),
        SWELL_BLOCK_MEMBER(S, eyeUnderwater),
        SWELL_BLOCK_MEMBER(S, depthNdcScale),
        SWELL_BLOCK_MEMBER(S, viewportOrigin),
        SWELL_BLOCK_MEMBER(S, depthNdcOffset),
        SWELL_BLOCK_MEMBER(S, depthFar),
        SWELL_BLOCK_MEMBER(S, nearNdcZ),
        SWELL_BLOCK_MEMBER(S, farNdcZ),
        SWELL_BLOCK_MEMBER(S, projectionFocalY),
        SWELL_BLOCK_MEMBER(S, footprintScale),
        SWELL_BLOCK_MEMBER(S, passMarksWater),
        SWELL_BLOCK_MEMBER(S, swashH0L0_m2),
        SWELL_BLOCK_MEMBER(S, gridLevels),
        SWELL_BLOCK_MEMBER(S, worldBoxes),
        SWELL_BLOCK_MEMBER(S, ambientSh),
        SWELL_BLOCK_MEMBER(S, fogExtinction_per_m),
        SWELL_BLOCK_MEMBER(S, fogFromSky),
        SWELL_BLOCK_MEMBER(S, contactCorner_m),
        SWELL_BLOCK_MEMBER(S, contactSize_m),
        SWELL_BLOCK_MEMBER(S, contactBand_m),
        SWELL_BLOCK_MEMBER(S, contactReach_m),
        SWELL_BLOCK_MEMBER(S, contactOn),
        SWELL_BLOCK_PADDING(S, contactUnused)}};
    return s;
}

inline const gl::BlockStruct& blockStructOf(const CausticsUniforms*)
{
    using S = CausticsUniforms;
    static const gl::BlockStruct s{
        "Caustics", "swell::detail::CausticsUniforms", sizeof(S),
        {SWELL_BLOCK_MEMBER_AS(S, sun, "causticsSun"), SWELL_BLOCK_MEMBER_AS(S, mapSize_m, "causticsMapSize_m"),
         SWELL_BLOCK_MEMBER_AS(S, mapCorner_m, "causticsMapCorner_m"),
         SWELL_BLOCK_MEMBER_AS(S, sourceCorner_m, "causticsSourceCorner_m"),
         SWELL_BLOCK_MEMBER_AS(S, gridCenter_m, "causticsGridCenter_m"),
         SWELL_BLOCK_MEMBER_AS(S, cellSize_m, "causticsCellSize_m"), SWELL_BLOCK_MEMBER_AS(S, cells, "causticsCells"),
         SWELL_BLOCK_MEMBER_AS(S, sliceDepth_m, "causticsSliceDepth_m")}};
    return s;
}

inline const gl::BlockStruct& blockStructOf(const CloudShadowUniforms*)
{
    using S = CloudShadowUniforms;
    static const gl::BlockStruct s{"CloudShadow", "swell::detail::CloudShadowUniforms", sizeof(S),
                                   {SWELL_BLOCK_MEMBER_AS(S, corner_m, "cloudShadowCorner_m"),
                                    SWELL_BLOCK_MEMBER_AS(S, size_m, "cloudShadowSize_m"),
                                    SWELL_BLOCK_MEMBER_AS(S, skySun, "cloudShadowSkySun")}};
    return s;
}

inline const gl::BlockStruct& blockStructOf(const WakeUniforms*)
{
    using S = WakeUniforms;
    static const gl::BlockStruct s{"Wake", "swell::detail::WakeUniforms", sizeof(S),
                                   {SWELL_BLOCK_MEMBER_AS(S, corner_m, "wakeCorner_m"),
                                    SWELL_BLOCK_MEMBER_AS(S, cellSize_m, "wakeCellSize_m"),
                                    SWELL_BLOCK_MEMBER_AS(S, cells, "wakeCells")}};
    return s;
}

inline const gl::BlockStruct& blockStructOf(const SurfaceSourcesUniforms*)
{
    using S = SurfaceSourcesUniforms;
    static const gl::BlockStruct s{"SurfaceSources", "swell::detail::SurfaceSourcesUniforms", sizeof(S),
                                   {SWELL_BLOCK_MEMBER_AS(S, parameters, "surfaceSourceParameters"),
                                    SWELL_BLOCK_MEMBER_AS(S, foamNoise, "sourceFoamNoise"),
                                    SWELL_BLOCK_MEMBER_AS(S, breakingFoamAmount, "sourceBreakingFoamAmount")}};
    return s;
}

} // namespace swell::detail
