// SpectralModel: the spectral field's GPU half beside its CPU queries
// (SpectralSurface, ocean/spectral/spectral_surface.cpp); the GPU half
// itself is ocean/spectral/gpu/spectral_gpu.cpp.
#include "swell/spectral_model.h"

#include "ocean/spectral/gpu/spectral_gpu.h"
#include "ocean/spectral/spectral_field.h"
#include "swell/wave_model_gpu.h"

#include <fmt/format.h>

namespace swell {

using namespace spectral;

SpectralModel::SpectralModel(const SpectralSettings& settings) : SpectralSurface(settings) {}

SpectralModel::SpectralModel(const SpectralSettings& settings, const Seabed& seabed)
    : SpectralSurface(settings, seabed)
{
}

SpectralModel::~SpectralModel() = default;

std::string_view SpectralModel::name() const { return "spectral"; }

std::string SpectralModel::summary() const
{
    return fmt::format("spectral ocean, {} cascades of {}^2, {:.3g} m .. {:.2g} m, wind {:.3g} m/s", kCascades, kSize,
                       field_->cascades.front().patch_m, field_->cascades.back().shortestWavelength_m(),
                       settings_.wind.windSpeed_mps);
}

std::unique_ptr<WaveModelGpu> SpectralModel::createGpu(const gl::ShaderSources& shaders) const
{
    return makeSpectralGpu(field_, coast_, settings_, spectral::breakingRampsStartingAt(breakingStart_), shaders);
}

} // namespace swell
