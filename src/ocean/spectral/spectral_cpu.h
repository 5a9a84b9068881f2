// The spectral ocean's CPU twin: the same spectra the GPU evolves, inverse
// transformed with kissfft, sampled with the same bilinear weights and the
// same per-cascade LOD weights as shaders/ocean/spectral.glsl. The fields
// for one time are computed when first asked for and kept until another
// time is asked for.
#pragma once

#include "ocean/spectral/spectral_field.h"
#include "swell/wave_model.h"

#include <memory>
#include <mutex>

namespace swell::spectral {

// The weight of cascade c where samples lie footprint_m apart: the GLSL
// twin is cascadeWeight() in shaders/ocean/spectral.glsl. A cascade is drawn
// in geometry only where its shortest wave is resolved (swell::waveLodWeight
// of that wavelength); 1 for a footprint of 0.
double cascadeWeight(const Cascade& cascade, double footprint_m);

class CpuSurface {
public:
    explicit CpuSurface(std::shared_ptr<const SpectralField> field);
    ~CpuSurface();

    // The displacement and normal at a rest point (world x,z) and time.
    // Thread-safe; transforms the fields when `time_s` differs from the last.
    SurfacePoint surfaceAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter) const;

    // The 8 spatial fields of every cascade at time_s (Dx, Dy, Dz, dDx/dz,
    // dDy/dx, dDy/dz, dDx/dx, dDz/dz), N*N each, row = z: for tests.
    struct Fields {
        double time_s = 0.0;
        std::array<std::array<std::vector<float>, 8>, kCascades> values;
    };
    const Fields& fieldsAt(double time_s) const;

private:
    std::shared_ptr<const SpectralField> field_;
    mutable std::mutex mutex_;
    mutable std::unique_ptr<Fields> fields_;
    void* fft_ = nullptr; // kiss_fftnd_cfg
};

} // namespace swell::spectral
