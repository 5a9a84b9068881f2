#include "ocean/spectral/spectral_warp.h"

#include "swell/constants.h"

#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <random>

namespace swell::spectral {

namespace {

// The sinusoids of every cascade's warp, in units of its patch L: the
// direction of the wave vector, the wavelength over L, and the direction of
// the offset. Wave vectors every 30 degrees (from 5, off the x and z axes),
// so every shift changes most of them; offsets across their own wave
// vectors (shear: the warp moves no area together or apart, so the waves'
// energy per square metre is untouched), so every wave direction is turned
// by some. Wavelengths of 4.5 to 5.6 L: over one patch the offset changes
// almost as much as its gradient allows (by r*sin(pi/r) of pi: 2.9 at r = 5,
// 2.6 at r = 3), so the strain paid per radian of decorrelation is least;
// the ratios are far from integers and from each other, so no shift of a
// few patches brings them back in phase together. Chosen among layouts
// compared by the strain each needs to bring the worst expected correlation
// of a wave a tenth of the patch long (prod J0 over the sinusoids, over
// every wave direction and shifts of 1 to 3 patches along x, z and the
// diagonals) to 0.25: this one 3.8% rms (8.1% at most); with every other
// offset along its wave vector instead 4.4% (7.7%); the best of 300 random
// layouts 4.6% (8.9%); offsets all along the wave vectors, wavelengths
// 3.5-4.6 L, 7.0% (13%).
struct WarpShape {
    double waveDirection_deg, wavelengthOverPatch, offsetDirection_deg;
};
constexpr WarpShape kShapes[kWarpWaves] = {
    {5.0, 4.7, 95.0}, {35.0, 5.3, 125.0}, {65.0, 4.9, 155.0},
    {95.0, 5.6, 185.0}, {125.0, 5.1, 215.0}, {155.0, 4.5, 245.0},
};
static_assert(sizeof(kShapes) / sizeof(kShapes[0]) == kWarpWaves);

// The amplitude of each sinusoid over the cascade's variance-weighted mean
// wavelength: what turns its waves by k.(w(x + L) - w(x)) enough that the
// heightfield's autocorrelation one patch away, along x, z or a diagonal,
// is at most 0.26 for every sea tested (0.3 is the criterion;
// tests/cpu/test_spectral_tiling.cpp measures it, and the strain it costs).
constexpr double kAmplitudeOverWavelength = 0.32;

glm::dvec2 unit(double angle_deg)
{
    const double a = angle_deg * kPi / 180.0;
    return {std::cos(a), std::sin(a)};
}

} // namespace

std::array<CascadeWarp, kWarpCascades> makeWarps(const std::array<double, kWarpCascades>& patches_m,
                                                 const std::array<double, kWarpCascades>& characteristicWavelength_m,
                                                 std::uint32_t seed, double strength)
{
    // Its own stream, so the warp's phases do not depend on the spectrum's draws.
    std::mt19937 rng(seed ^ 0x9e3779b9u);
    std::array<CascadeWarp, kWarpCascades> warps{};
    for (int c = 0; c < kWarpCascades; ++c) {
        const double patch_m = patches_m[size_t(c)];
        const double amplitude_m = strength * kAmplitudeOverWavelength * characteristicWavelength_m[size_t(c)];
        for (int i = 0; i < kWarpWaves; ++i) {
            const WarpShape& shape = kShapes[i];
            WarpWave& w = warps[size_t(c)][size_t(i)];
            w.wavevector_radpm = unit(shape.waveDirection_deg) * (kTwoPi / (shape.wavelengthOverPatch * patch_m));
            w.amplitude_m = unit(shape.offsetDirection_deg) * amplitude_m;
            w.phase_rad = kTwoPi * (double(rng()) / 4294967296.0);
        }
    }
    return warps;
}

double warpPhaseAt(const WarpWave& wave, glm::dvec2 point_m)
{
    const double phase = std::fmod(glm::dot(wave.wavevector_radpm, point_m) + wave.phase_rad, kTwoPi);
    return phase < 0.0 ? phase + kTwoPi : phase;
}

WarpSample warpAt(const CascadeWarp& warp, glm::dvec2 point_m)
{
    WarpSample s;
    for (const WarpWave& w : warp) {
        const double phase = warpPhaseAt(w, point_m);
        s.offset_m += w.amplitude_m * std::sin(phase);
        // d/dx_j of a*sin(q.x + phi) = a*q_j*cos(...): column j is a*q_j.
        s.jacobian += glm::outerProduct(w.amplitude_m, w.wavevector_radpm) * std::cos(phase);
    }
    return s;
}

double strainAt(const CascadeWarp& warp, glm::dvec2 point_m)
{
    const glm::dmat2 m = warpAt(warp, point_m).jacobian;
    // Singular values of a 2x2 matrix from its Frobenius norm and determinant.
    const double f2 = m[0][0] * m[0][0] + m[0][1] * m[0][1] + m[1][0] * m[1][0] + m[1][1] * m[1][1];
    const double det = glm::determinant(m);
    const double root = std::sqrt(std::max(f2 * f2 - 4.0 * det * det, 0.0));
    const double largest = std::sqrt(0.5 * (f2 + root)), smallest = std::sqrt(std::max(0.5 * (f2 - root), 0.0));
    return std::max(largest - 1.0, 1.0 - smallest);
}

} // namespace swell::spectral
