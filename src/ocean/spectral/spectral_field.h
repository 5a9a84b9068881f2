// The spectral ocean's fields, shared by its CPU twin and its GPU half: the
// cascades (patch sizes and the wavenumber band each holds), the seeded
// initial amplitudes h0(k), and each sample's angular frequency. Both halves
// evolve and transform the same numbers, so the CPU queries equal what the
// GPU draws.
//
// The surface is the sum over cascades c of periodic fields on patches
// L_c metres square, sampled at N = SWELL_FFT_SIZE points a side:
//   eta(x, t) = sum_k hhat(k, t) * exp(i k.x),  k = 2*pi*(f_x, f_z)/L_c,
//   hhat(k, t) = h0(k) exp(-i w t) + conj(h0(-k)) exp(i w t)
// (Tessendorf 2001, "Simulating Ocean Water", eq. 26, with the sign of the
// time term chosen so that a component travels along +k), with
//   h0(k) = (xi_r + i xi_i) / 2 * sqrt(Psi(k)) * dk,  xi ~ N(0, 1), dk = 2*pi/L_c,
// so that the height variance is the integral of the wave-number spectrum
// Psi (swell::SeaSpectrum::wavenumberDensity) over the band. The horizontal
// displacement is D = i * lambda * (k/|k|) * hhat (Tessendorf 2001, eq. 29,
// with the sign that moves points towards the crests, as Gerstner waves do).
#pragma once

#include "ocean/spectral/spectral_warp.h"
#include "swell/gpu/ocean.h"
#include "swell/scene/spectrum.h"

#include <array>
#include <complex>
#include <cstdint>
#include <vector>

namespace swell::spectral {

inline constexpr int kSize = SWELL_FFT_SIZE;
inline constexpr int kLog2Size = SWELL_FFT_LOG2_SIZE; // levels above a cascade's base in its mip chains
inline constexpr int kCascades = SWELL_FFT_CASCADES;

// One cascade: a patch and the ring of wavenumbers it holds.
struct Cascade {
    double patch_m = 0.0;          // L_c, m
    double minWavenumber_radpm = 0.0; // |k| >= this, rad/m
    double maxWavenumber_radpm = 0.0; // |k| < this, rad/m
    // The shortest wavelength it holds, m: what the LOD filter weighs it by.
    double shortestWavelength_m() const;
    // Whether its sample of frequency (f_z, f_x), f in -N/2..N/2-1, carries
    // a wave: |k| in the band, and neither on the Nyquist row or column (no
    // partner of opposite frequency there) nor k = 0.
    bool holds(int fz, int fx) const;
};

// Patch sizes L_0 / 6.65^c, L_0 ten peak wavelengths (at least 100 m): a
// ratio far from any integer, so the patches never repeat together, and a
// largest patch that samples the spectral peak ten times over in each
// direction. Cascade c keeps wavelengths of at least 8 of its texels
// (|k| < 2*pi*32/L_c) and the next one starts there, so the bands are
// disjoint; the last keeps down to 4 texels per wavelength (1.2 cm at 5 m/s,
// 4 cm at 10 m/s, 15 cm at 20 m/s in a fully developed sea).
std::array<Cascade, kCascades> cascadeLayout(double peakWavelength_m);

// Which sample (row, column) of a cascade holds frequency (f_z, f_x),
// f in -N/2..N/2-1: f mod N, the FFT's order.
inline int sampleIndex(int fz, int fx) { return ((fz + kSize) % kSize) * kSize + (fx + kSize) % kSize; }

// The frequency a sample index holds: 0..N/2-1, then -N/2..-1.
inline int frequencyOf(int index) { return index < kSize / 2 ? index : index - kSize; }

// The time-independent part of the field, per cascade, N*N samples each in
// FFT order (row = z frequency, column = x frequency).
struct SpectralField {
    std::array<Cascade, kCascades> cascades{};
    // h0(k) and conj(h0(-k)), m.
    std::array<std::vector<std::complex<float>>, kCascades> h0, h0MinusConj;
    // w(|k|) from w^2 = g*k*tanh(k*d), rad/s, in double: the phase w*t must
    // stay exact after days of simulated time.
    std::array<std::vector<double>, kCascades> omega_radps;
    double choppiness = 1.0; // lambda, dimensionless
    // Bounds on the displacement: the sum of |hhat| over every sample (up
    // or down) and lambda times it (sideways), m. Rigorous: no sum of these
    // components can exceed them.
    double verticalReach_m = 0.0, horizontalReach_m = 0.0;
    // Mean square slope of the waves shorter than the last cascade holds
    // (unresolvedSlopeVariance()), dimensionless: shading adds it as roughness.
    double unresolvedSlopeVariance = 0.0;
    // Each cascade is looked up at x + w_c(x) (spectral_warp.h), so the sum
    // does not repeat with any patch.
    std::array<CascadeWarp, kCascades> warps{};
};

// Draws the field of a sea. The same spectrum, choppiness and seed give
// bit-identical fields (std::mt19937 and a Box-Muller written here).
// warpStrength scales the anti-tiling warp (0: none, each cascade repeats
// with its patch; tests compare the two).
SpectralField makeSpectralField(const SeaSpectrum& sea, double choppiness, std::uint32_t seed,
                                double warpStrength = 1.0);

// The complex spectra of one cascade at time t, packed two real fields to a
// complex sample (the real part of the transform is the first field, the
// imaginary part the second): (Dx, Dy), (Dz, dDx/dz), (dDy/dx, dDy/dz),
// (dDx/dx, dDz/dz). phase = w*t is reduced modulo 2*pi in double before it
// becomes float, exactly as the GPU does it.
struct Spectra {
    std::array<std::vector<std::complex<float>>, 4> packed;
};
void evolve(const SpectralField& field, int cascade, double time_s, Spectra& out);

// ---------------------------------------------------------------------------
// What the discrete field holds, from the spectrum alone (no random draws)

// The expected height variance of the field, m^2: the sum over every
// cascade's band of Psi(k)*dk^2 (each sample stands for a dk^2 cell of the k
// plane). 16 times it is the square of the significant wave height it gives.
double sampledHeightVariance_m2(const SeaSpectrum& sea, const std::array<Cascade, kCascades>& cascades);

// The expected mean square slope of the resolved surface, dimensionless:
// the sum over every band of |k|^2*Psi(k)*dk^2 (the variance of dy/dx plus
// that of dy/dz).
double sampledSlopeVariance(const SeaSpectrum& sea, const std::array<Cascade, kCascades>& cascades);

// The mean square slope of the waves shorter than the field's shortest,
// dimensionless: that of Elfouhaily et al. 1997's spectrum beyond
// k1 = 2*pi/shortestResolvedWavelength_m (ocean/short_waves.h), for the wind
// sea's U10 and inverse wave age. JONSWAP's gravity range holds far too little
// there (Cox & Munk's slopes grow with the wind through the capillary-gravity
// waves). What shading must add for the slopes the geometry lacks.
double unresolvedSlopeVariance(const SeaSpectrum& sea, double shortestResolvedWavelength_m);

} // namespace swell::spectral
