// A wave model with surface sources added (swell/surface_source.h): what floating
// bodies float on when a host added sources of its own. Heights (and their
// slopes, in the normal) add at the rest point, as the drawn water adds
// them, so the rest point under a world point is the waves' own.
#pragma once

#include "swell/wave_model.h"
#include "swell/surface_source.h"

#include <memory>
#include <vector>

namespace swell::detail {

class WavesWithSources final : public WaveModel {
public:
    WavesWithSources(std::shared_ptr<const WaveModel> waves, std::vector<std::shared_ptr<const SurfaceSource>> sources);

    std::string_view name() const override;
    std::string summary() const override;
    WaveReach reach() const override;
    double heightDeviation_m() const override;
    SurfacePoint surfaceAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter = {}) const override;
    glm::dvec3 displacementAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter = {}) const override;
    glm::dvec2 restPointUnder(glm::dvec2 worldPoint_m, double time_s, const SurfaceFilter& filter = {}) const override;
    std::unique_ptr<WaveModelGpu> createGpu(const gl::ShaderSources& shaders) const override;

private:
    std::shared_ptr<const WaveModel> waves_;
    std::vector<std::shared_ptr<const SurfaceSource>> sources_;
};

} // namespace swell::detail
