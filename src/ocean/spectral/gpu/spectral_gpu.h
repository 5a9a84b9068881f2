// The spectral model's GPU half (spectral_gpu.cpp), for
// SpectralModel::createGpu. Library-internal.
#pragma once

#include "ocean/spectral/breaking.h"
#include "ocean/spectral/spectral_field.h"
#include "swell/gl/shader_sources.h"
#include "swell/spectral_model.h"
#include "swell/wave_model_gpu.h"

#include <memory>

namespace swell::spectral {

struct CoastTrains;

// The GPU half of a spectral model: its textures, passes and foam steps for
// `field`, whitecaps on the breaking score's `ramps`, one a foam level
// (breaking.h); over a coast (null: none), its trains' field (spectral_cpu.h).
std::unique_ptr<WaveModelGpu> makeSpectralGpu(std::shared_ptr<const SpectralField> field,
                                              std::shared_ptr<const CoastTrains> coast,
                                              const SpectralSettings& settings, const spectral::BreakingRamps& ramps,
                                              const gl::ShaderSources& shaders);

} // namespace swell::spectral
