// C++ mirror of the std140 uniform block Frame in shaders/frame.glsl, field
// by field (a float after a vec3 fills its fourth lane in both).
// tests/gl/test_uniform_layout.cpp asks the driver for each field's offset
// and compares with offsetof.
#pragma once

#include "swell/shader_constants.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace swell::detail {

struct alignas(16) WorldBoxUniform {
    glm::vec3 min_m;
    float unused0;
    glm::vec3 max_m;
    float unused1;
};

struct alignas(16) GridLevelUniform {
    glm::vec2 snapOffset_m;
    glm::vec2 coarseSnapOffset_m;
    float firstRing;
    float coarseFirstRing;
};

struct alignas(16) FrameUniforms {
    glm::mat4 passViewProj;
    glm::mat4 passInvViewProj;
    glm::mat4 cameraViewProj;
    glm::mat4 cameraInvViewProj;
    glm::vec4 clipPlane;
    glm::vec3 eyePosition;
    float fresnelF0;
    glm::vec3 sunDirection;
    float sunIntensity;
    glm::vec3 sunColor;
    float fogSkyLayer_m;
    glm::vec3 fogColor;
    float fogStart_m;
    glm::vec3 skyZenith;
    float fogEnd_m;
    glm::vec3 skyHorizon;
    float shininess;
    glm::vec3 waterDeep;
    float specularStrength;
    glm::vec3 waterAbsorption;
    float refractionDistortion;
    glm::vec2 gridCenter;
    float gridRadius_m;
    float gridCells;
    float gridSkirt_m;
    float gridFinestStep_m;
    float gridFadeStart_m;
    float gridFadeEnd_m;
    float gridInnerScale_m;
    float gridGrowth;
    float reflectionFixedDistance_m;
    int worldBoxCount;
    glm::vec2 viewportSize;
    glm::vec2 viewportInvSize;
    int passEncodesSrgb;
    float waveHeightDeviation_m;
    float waveMeanSquareSlope;
    float gridMorph;
    glm::vec2 gridCoarseCenterShift;
    float gridCoarseGrowth;
    float waveReachVertical_m;
    int eyeUnderwater;
    float depthNdcScale;
    glm::vec2 viewportOrigin;
    float depthNdcOffset;
    float depthFar;
    float nearNdcZ;
    float farNdcZ;
    float projectionFocalY;
    float footprintScale;
    int passMarksWater;
    GridLevelUniform gridLevels[SWELL_GRID_LEVELS];
    WorldBoxUniform worldBoxes[SWELL_MAX_WORLD_BOXES];
    glm::vec4 ambientSh[9];
    glm::vec3 fogExtinction_per_m;
    int fogFromSky;
};

} // namespace swell::detail
