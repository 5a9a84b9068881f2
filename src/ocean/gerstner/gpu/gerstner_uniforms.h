// C++ mirror of the std140 block GerstnerWaves in shaders/ocean/gerstner.glsl,
// field by field; tests/gl/test_uniform_layout.cpp compares the offsets.
#pragma once

#include "swell/shader_constants.h"

#include <glm/vec4.hpp>

namespace swell::detail {

struct alignas(16) GerstnerUniforms {
    glm::vec4 waveShape[SWELL_MAX_WAVES]; // xy: unit direction, z: k, rad/m, w: amplitude, m
    glm::vec4 wavePhase[SWELL_MAX_WAVES]; // x: steepness Q, y: phase at the grid centre, rad, z: wavelength, m,
                                          // w: mean square slope of this wave and every shorter one
    glm::ivec4 waveCount;                 // x: waves in use
};

} // namespace swell::detail
