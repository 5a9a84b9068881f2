// A still's foam history replayed on the CPU: the C++ twin of
// shaders/ocean/spectral_foam.comp for the replay's steps before the last.
// Each step needs only the fold Jacobian of the folding cascades, which
// needs only three of the eight fields a frame transforms (dDx/dx, dDz/dz,
// dDx/dz): three inverse FFTs a step for the two folding cascades (one
// packs both cascades' dDx/dz), against the GPU replay's transform of every
// field. The windows do not move during a replay, so each texel's warped
// sample points and the warp's Jacobian are computed once, not every step.
// On llvmpipe the GPU's steps cost about 0.19 s of CPU each, these about
// 0.011 s (docs/PERFORMANCE.md); a GPU keeps its own steps.
#pragma once

#include "ocean/spectral/spectral_field.h"
#include "ocean/spectral/whitecaps.h"
#include "ocean/spectral/world_foam.h"

#include <glm/vec2.hpp>

#include <array>
#include <complex>
#include <cstdint>
#include <memory>
#include <vector>

namespace swell::spectral {

class FoamReplay {
public:
    // The foam is made where J < foldThreshold, fading over foldSoftness
    // above it, as spectral_foam.comp makes it.
    FoamReplay(std::shared_ptr<const SpectralField> field, float foldThreshold, float foldSoftness);
    ~FoamReplay();
    FoamReplay(const FoamReplay&) = delete;
    FoamReplay& operator=(const FoamReplay&) = delete;

    // Steps the foam of every level's window at times_s (ascending), the
    // first starting afresh: foam = max(foam * exp(-dt / lifetime_s), made).
    // Returns each level's kFoamSize^2 texels in the window's storage order
    // (texel p holds world texel origin + ((p - origin) mod N)), row = z.
    const std::array<std::vector<float>, kFoamLevels>& run(glm::dvec2 gridCenter_m,
                                                            const std::array<FoamWindow, kFoamLevels>& windows,
                                                            const std::vector<double>& times_s, double lifetime_s);

    // The fold Jacobian of the folding cascades at a level's stored texel
    // after the last step of run() (for the test against the CPU twin).
    float lastJacobian(int level, int x, int z) const;

private:
    // Where a stored texel samples one cascade: the four neighbours of its
    // warped point, the bilinear weights, and the warp's Jacobian (column j:
    // d(x + w)/dx_j).
    struct Tap {
        std::uint32_t i00, i01, i10, i11;
        float fx, fz;
        float j00, j01, j10, j11; // jacobian[0].x, [0].y, [1].x, [1].y
    };
    void placeTaps(glm::dvec2 gridCenter_m, const std::array<FoamWindow, kFoamLevels>& windows);
    void evolveTo(double time_s);
    float jacobianAt(size_t texel) const;

    std::shared_ptr<const SpectralField> field_;
    float foldThreshold_, foldSoftness_;
    void* fft_ = nullptr; // kiss_fftnd_cfg, inverse, N x N
    // Per folding cascade and sample: the coefficients that turn h into
    // dDx/dx, dDz/dz and dDx/dz, and the phasor exp(i w t) now.
    std::array<std::vector<float>, kFoamCascades> cxx_, czz_, cxz_;
    std::array<std::vector<std::complex<double>>, kFoamCascades> phasor_;
    // exp(i w dt) for the replay's step dt (lastStep_s_).
    std::array<std::vector<std::complex<double>>, kFoamCascades> rotation_;
    double phasorTime_s_ = 0.0, lastStep_s_ = 0.0;
    bool phasorSet_ = false;
    // The spectra, then the fields: (dDx/dx + i dDz/dz) of each folding
    // cascade, and (dDx/dz of cascade 0 + i dDx/dz of cascade 1).
    std::array<std::vector<std::complex<float>>, kFoamCascades> alongSpectrum_, along_;
    std::vector<std::complex<float>> crossSpectrum_, cross_;
    // Taps of every stored texel of every level (level-major), per cascade.
    std::array<std::vector<Tap>, kFoamCascades> taps_;
    std::array<std::vector<float>, kFoamLevels> foam_;
};

} // namespace swell::spectral
