// SpectralModel: the spectral field behind swell::WaveModel, with its CPU
// twin for queries; its GPU half is ocean/spectral/spectral_gpu_model.cpp.
#include "swell/spectral_model.h"

#include "ocean/spectral/spectral_cpu.h"
#include "ocean/spectral/spectral_gpu.h"
#include "ocean/spectral/whitecaps.h"
#include "ocean/spectral/world_foam.h"
#include "swell/wave_model_gpu.h"

#include <fmt/format.h>

#include <cmath>

namespace swell {

using namespace spectral;

SpectralSurface::SpectralSurface(const SpectralSettings& settings)
    : settings_(settings),
      field_(std::make_shared<const SpectralField>(
          makeSpectralField(SeaSpectrum(settings.wind), settings.choppiness, settings.seed))),
      cpu_(std::make_unique<CpuSurface>(field_))
{
    // (fieldsAt is not thread-safe; nothing else can reach cpu_ while it is
    // being built.)
    const CpuSurface::Fields& fields = cpu_->fieldsAt(0.0);
    // The cascades' bands are disjoint, so their height variances add.
    double variance = 0.0;
    for (int c = 0; c < kCascades; ++c) {
        double sum = 0.0;
        for (const float h : fields.values[size_t(c)][1])
            sum += double(h) * double(h);
        variance += sum / double(fields.values[size_t(c)][1].size());
    }
    heightDeviation_m_ = std::sqrt(variance);
    // The fold threshold from the field itself, at t = 0: its J
    // distribution is stationary, so any time would do.
    foldThreshold_ = foldThresholdFor(*cpu_, *field_, breakingFraction(settings.wind.windSpeed_mps));
}

SpectralSurface::~SpectralSurface() = default;

SpectralModel::SpectralModel(const SpectralSettings& settings) : SpectralSurface(settings) {}

SpectralModel::~SpectralModel() = default;

std::string_view SpectralModel::name() const { return "spectral"; }

std::string SpectralModel::summary() const
{
    return fmt::format("spectral ocean, {} cascades of {}^2, {:.3g} m .. {:.2g} m, wind {:.3g} m/s", kCascades, kSize,
                       field_->cascades.front().patch_m, field_->cascades.back().shortestWavelength_m(),
                       settings_.wind.windSpeed_mps);
}

WaveReach SpectralSurface::reach() const { return {field_->verticalReach_m, field_->horizontalReach_m}; }

SurfacePoint SpectralSurface::surfaceAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter) const
{
    return cpu_->surfaceAt(restPoint_m, time_s, filter);
}

glm::dvec3 SpectralSurface::displacementAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter) const
{
    return cpu_->displacementAt(restPoint_m, time_s, filter);
}

std::unique_ptr<WaveModelGpu> SpectralModel::createGpu(const gl::ShaderSources& shaders) const
{
    return makeSpectralGpu(field_, settings_, foldThreshold_, shaders);
}

} // namespace swell
