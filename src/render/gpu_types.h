// C++ mirrors of the std140 uniform blocks in shaders/frame.glsl and
// shaders/waves.glsl, field by field. tests/gl/test_uniform_layout.cpp asks
// the driver for each field's offset and compares with offsetof.
#pragma once

#include "swell/shader_constants.h"

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace swell::detail {

struct alignas(16) FrameUniforms {
    glm::mat4 passViewProj;
    glm::mat4 passInvViewProj;
    glm::mat4 cameraViewProj;
    glm::mat4 cameraInvViewProj;
    glm::vec4 clipPlane;
    glm::vec4 eyePosition;
    glm::vec4 sunDirection;
    glm::vec4 sunColor;
    glm::vec4 fogColor;
    glm::vec4 fogRange;
    glm::vec4 skyZenith;
    glm::vec4 skyHorizon;
    glm::vec4 waterDeep;
    glm::vec4 waterAbsorption;
    glm::vec4 waterOptics;
    glm::vec4 gridShape;
    glm::vec4 gridFade;
    glm::vec4 gridCenter;
    glm::vec4 gridLayout;
    glm::vec4 snapOffsets[SWELL_GRID_LEVELS];
    glm::vec4 reflectionParams;
    glm::vec4 worldBoxes[2 * SWELL_MAX_WORLD_BOXES];
    glm::vec4 viewport;
    glm::vec4 passFlags;
};

struct alignas(16) WaveUniforms {
    glm::vec4 waveShape[SWELL_MAX_WAVES];
    glm::vec4 wavePhase[SWELL_MAX_WAVES];
    glm::ivec4 waveCount;
};

} // namespace swell::detail
