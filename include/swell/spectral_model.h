// The spectral ocean: the sea's wave-number spectrum (swell/scene/spectrum.h)
// sampled on SWELL_FFT_CASCADES periodic patches of incommensurate sizes,
// evolved with the dispersion relation and inverse transformed each frame,
// on the GPU with compute shaders and, for CPU queries of the same frame,
// with kissfft (src/ocean/spectral/). Choppy: the horizontal displacement is
// choppiness times the spectrum's own (Tessendorf 2001).
#pragma once

#include "swell/export.h"
#include "swell/gpu/ocean.h"

#include "swell/scene/spectrum.h"
#include "swell/surface_query.h"
#include "swell/wave_model.h"

#include <array>
#include <cstdint>
#include <limits>
#include <memory>

namespace swell {

namespace spectral {
struct SpectralField;
class CpuSurface;
struct CoastTrains;
} // namespace spectral

class Seabed;

struct SWELL_API SpectralSettings {
    WindSettings wind;       // the sea: wind, fetch, depth, spreading, swell
    // lambda, dimensionless, 0..2: how far crests lean and troughs widen; 0
    // is the linear (Airy) sea, 1 Tessendorf's choppy waves.
    double choppiness = 1.0;
    std::uint32_t seed = 1;  // the random field's seed
    // Whitecaps: foam is made where the surface folds most (the Jacobian of
    // the horizontal displacement, src/ocean/spectral/whitecaps.h), as much
    // as the wind's whitecap climatology says, and fades as
    // exp(-t/foamLifetime_s) (3.85 s: salt-water foam, Monahan &
    // O'Muircheartaigh 1986). 0: no foam.
    double foamLifetime_s = 3.85; // s, 0..60
    // When the foam's history starts, s (Scene::historyStart_s): no foam
    // before it, and a still replays none from before it. -inf: the foam has
    // always been made (a still at any time shows it in its steady state).
    double historyStart_s = -std::numeric_limits<double>::infinity();
};

// The spectral ocean's CPU queries: its field, and the CPU twin that
// transforms it for each new time asked (all the CPU needs).
class SWELL_API SpectralSurface : public virtual SurfaceQuery {
public:
    // Throws std::invalid_argument as SeaSpectrum does for bad settings.
    explicit SpectralSurface(const SpectralSettings& settings);
    // Over a sea floor (docs/RENDERING.md "Waves that feel the bottom"):
    // near the coast the longest band is carried by a few trains that feel
    // the bottom, and no wave stands on dry land. A flat floor: the open sea.
    SpectralSurface(const SpectralSettings& settings, const Seabed& seabed);
    ~SpectralSurface() override;

    const SpectralSettings& settings() const { return settings_; }

    WaveReach reach() const override;
    // From the CPU twin's height fields at t = 0 (the sea is stationary).
    double heightDeviation_m() const override { return heightDeviation_m_; }
    SurfacePoint surfaceAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter = {}) const override;
    // Transforms only the displacement fields for a new time: half the cost.
    glm::dvec3 displacementAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter = {}) const override;

protected:
    SpectralSettings settings_;
    // Each foam level's breaking score below which foam is made
    // (src/ocean/spectral/breaking.h).
    std::array<float, SWELL_FOAM_LEVELS> breakingStart_{};
    std::shared_ptr<const spectral::SpectralField> field_;
    // The trains over the floor's coast field; null: the open sea.
    std::shared_ptr<const spectral::CoastTrains> coast_;

private:
    SpectralSurface(const SpectralSettings& settings, const Seabed* seabed);

    std::unique_ptr<spectral::CpuSurface> cpu_;
    double heightDeviation_m_ = 0.0;
};

// SpectralSurface's queries with its GPU half: the same field on the GPU.
class SWELL_API SpectralModel final : public SpectralSurface, public WaveModel {
public:
    // Throws std::invalid_argument as SeaSpectrum does for bad settings.
    explicit SpectralModel(const SpectralSettings& settings);
    // Over a sea floor, as SpectralSurface's.
    SpectralModel(const SpectralSettings& settings, const Seabed& seabed);
    ~SpectralModel() override;

    std::unique_ptr<WaveModelGpu> createGpu(const gl::ShaderSources& shaders) const override;
    std::string_view name() const override;
    std::string summary() const override;
};

} // namespace swell
