// The Gerstner sum (swell/scene/waves.h) as a surface and as a wave model: CPU
// queries in double (GerstnerSurface, all the CPU needs), and on the GPU a
// uniform block of up to SWELL_MAX_WAVES waves summed by
// shaders/ocean/gerstner.glsl (GerstnerModel, which the renderer draws).
#pragma once

#include "swell/export.h"

#include "swell/scene/waves.h"
#include "swell/surface_query.h"
#include "swell/wave_model.h"

namespace swell {

class SWELL_API GerstnerSurface : public virtual SurfaceQuery {
public:
    // Throws swell::InputError naming the problem when validate(waves) fails.
    explicit GerstnerSurface(WaveSet waves);

    const WaveSet& waves() const { return waves_; }

    WaveReach reach() const override { return reach_; }
    // sqrt(sum a^2 / 2): independent sinusoids' variances add.
    double heightDeviation_m() const override { return heightDeviation_m_; }
    SurfacePoint surfaceAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter = {}) const override;
    // Newton's method with the analytic Jacobian (swell::restPointUnder).
    glm::dvec2 restPointUnder(glm::dvec2 worldPoint_m, double time_s, const SurfaceFilter& filter = {}) const override;

private:
    WaveSet waves_;
    WaveReach reach_;
    double heightDeviation_m_ = 0.0;
};

// GerstnerSurface's queries with its GPU half.
class SWELL_API GerstnerModel final : public GerstnerSurface, public WaveModel {
public:
    // Throws swell::InputError naming the problem when validate(waves) fails.
    explicit GerstnerModel(WaveSet waves);

    std::unique_ptr<WaveModelGpu> createGpu(const gl::ShaderSources& shaders) const override;
    std::string_view name() const override;
    std::string summary() const override;
};

} // namespace swell
