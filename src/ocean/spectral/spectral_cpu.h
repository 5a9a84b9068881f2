// The spectral ocean's CPU twin: the same spectra the GPU evolves, inverse
// transformed with kissfft, sampled with the same bilinear weights and the
// same per-cascade LOD weights as shaders/ocean/spectral.glsl, each cascade
// at its anti-tiling warp's point (spectral_warp.h). The fields
// for one time are computed when first asked for and kept until another
// time is asked for; the derivative fields (for normals) only when a query
// needs them, which halves the cost of a frame whose queries are heights.
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

    // The displacement alone, m: the same as surfaceAt().displacement_m, but
    // transforms only the displacement fields (2 of the 4 transforms a
    // cascade) when `time_s` is new. What height queries and
    // restPointUnder() need.
    glm::dvec3 displacementAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter) const;

    // The Jacobian of the horizontal displacement of cascades
    // 0..cascadeCount-1 at a rest point and time, each weighed for the
    // filter's footprint as the surface is: where the surface folds, and
    // foam is made. The GLSL twin is foldJacobian() in
    // shaders/ocean/spectral.glsl. Thread-safe.
    double foldJacobianAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter, int cascadeCount) const;

    // The 8 spatial fields of every cascade at time_s (Dx, Dy, Dz, dDx/dz,
    // dDy/dx, dDy/dz, dDx/dx, dDz/dz), N*N each, row = z: for tests and the
    // model's constructor. Not thread-safe, unlike the queries: the
    // reference holds until the next call for another time.
    struct Fields {
        double time_s = 0.0;
        bool hasDerivatives = false; // fields 4..7 (and their spectra transformed)
        std::array<std::array<std::vector<float>, 8>, kCascades> values;
    };
    const Fields& fieldsAt(double time_s) const;
    // Only fields 0..3 (Dx, Dy, Dz, dDx/dz) are sure to be there.
    const Fields& displacementFieldsAt(double time_s) const;

private:
    std::shared_ptr<const SpectralField> field_;
    mutable std::mutex mutex_;
    mutable std::unique_ptr<Fields> fields_;
    // The frame's spectra, kept so the derivative fields can be transformed
    // later in the frame without evolving again.
    mutable std::array<Spectra, kCascades> spectra_;
    const Fields& fieldsFor(double time_s, bool derivatives) const;
    // Inverse-transforms packed spectra [first, last) of every cascade into fields_.
    void transform(int firstPacked, int lastPacked) const;
    // The displacement at a rest point and, with derivatives, its gradients
    // along rest x and z: every cascade's bilinear sample at its warped
    // point, LOD weights applied, gradients through the warp's Jacobian.
    struct Sample {
        glm::dvec3 displacement_m{0.0};                       // Dx, Dy, Dz, m
        glm::dvec2 gradDx{0.0}, gradDy{0.0}, gradDz{0.0}; // (d/dx, d/dz), dimensionless
    };
    void sample(const Fields& f, glm::dvec2 restPoint_m, const SurfaceFilter& filter, bool derivatives,
                Sample& out, int cascadeCount = kCascades) const;
    void* fft_ = nullptr; // kiss_fftnd_cfg
};

} // namespace swell::spectral
