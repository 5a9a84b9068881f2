// A still's foam history replayed on the CPU: the C++ twin of
// shaders/ocean/spectral_foam.comp for the replay's steps before the last.
// Each step needs only the fold Jacobian of the folding cascades (over each
// window and its breaking boxes' margin, breaking.h), which
// needs only three of the eight fields a frame transforms (dDx/dx, dDz/dz,
// dDx/dz): three inverse FFTs a step for the two folding cascades (one
// packs both cascades' dDx/dz), against the GPU replay's transform of every
// field. The windows do not move during a replay, so each texel's warped
// sample points and the warp's Jacobian are computed once, not every step.
// On llvmpipe the GPU's steps cost about 0.19 s of CPU each, these about
// 0.011 s (docs/design/performance-log.md); a GPU keeps its own steps.
#pragma once

#include "ocean/spectral/breaking.h"
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
    // The foam is made on the breaking score's ramps (breaking.h), as
    // spectral_foam.comp makes it.
    FoamReplay(std::shared_ptr<const SpectralField> field, const BreakingRamps& ramps);
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

    // The lowest breaking score within each stored texel's spread (the foam
    // a ramp makes there is foamMadeAt of it) at each of times_s, for every
    // level: [level][step][texel, in the window's storage order]. What the
    // ramps are found from (calibratedBreakingRamps, breaking.h).
    std::array<std::vector<std::vector<float>>, kFoamLevels> lowestScores(
        glm::dvec2 gridCenter_m, const std::array<FoamWindow, kFoamLevels>& windows, const std::vector<double>& times_s);

    // The fold Jacobian of the folding cascades at a level's stored texel
    // after the last step of run() (for the test against the CPU twin).
    float lastJacobian(int level, int x, int z) const;

private:
    // Each level's texels with the margin the boxes and the spread reach:
    // world texels origin - R - S .. origin + N + R + S - 1 each way, row by
    // row; the foam made on the texels origin - S .. origin + N + S - 1.
    static constexpr int kMargin = kBreakingRadius + kBreakingSpread;
    static constexpr int kSpan = kFoamSize + 2 * kMargin;
    static constexpr int kMadeSpan = kFoamSize + 2 * kBreakingSpread;
    // Where a texel samples one cascade: the four neighbours of its
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
    // Evolves the folding cascades to time_s and takes J over every span.
    void stepJacobians(double time_s);
    // Each stored texel's lowest score within its spread, from the span's J.
    void lowestScoresOf(int level, float* lowest);
    // The J index (level-major, kSpan^2 a level) of the first texel of the
    // box around a level's stored texel.
    size_t spanIndexOf(int level, int x, int z) const;

    std::shared_ptr<const SpectralField> field_;
    BreakingRamps ramps_;
    std::array<FoamWindow, kFoamLevels> windows_{};
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
    // Taps of every texel of every level's span (level-major), per cascade,
    // and the J there at the last step.
    std::array<std::vector<Tap>, kFoamCascades> taps_;
    std::vector<float> jacobian_;
    std::vector<float> score_;  // one level's breaking scores, kMadeSpan^2
    std::vector<float> lowest_; // ... the lowest within each stored texel's spread
    std::array<std::vector<float>, kFoamLevels> foam_;
};

} // namespace swell::spectral
