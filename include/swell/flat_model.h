// Flat water: the ocean at rest, a perfect mirror. The simplest wave model;
// useful for mirror-reflection checks and as the example of adding a model
// (this header, src/ocean/flat/gpu/flat_model.cpp and shaders/ocean/flat.glsl).
#pragma once

#include "swell/export.h"

#include "swell/wave_model.h"

namespace swell {

class SWELL_API FlatModel final : public WaveModel {
public:
    std::string_view name() const override;
    std::string summary() const override;
    WaveReach reach() const override { return {}; }
    double heightDeviation_m() const override { return 0.0; }
    SurfacePoint surfaceAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter = {}) const override;
    glm::dvec2 restPointUnder(glm::dvec2 worldPoint_m, double time_s, const SurfaceFilter& filter = {}) const override;
    std::unique_ptr<WaveModelGpu> createGpu(const gl::ShaderSources& shaders) const override;
};

} // namespace swell
