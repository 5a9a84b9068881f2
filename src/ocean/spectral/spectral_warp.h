// The spectral ocean's anti-tiling warp: each cascade is looked up at a
// warped point s = x + w_c(x) instead of at its rest point x, where w_c is a
// smooth horizontal offset field that does not repeat with the patch (a sum
// of SWELL_FFT_WARP_WAVES sinusoids with wave vectors off every cascade's
// lattice). One patch L apart, the lookups differ by w_c(x + L) - w_c(x),
// which turns a wave k by k.(w_c(x + L) - w_c(x)): with that spread over a
// radian or more, the field no longer correlates with itself at its period.
// This is domain warping (Perlin 1985, "An Image Synthesizer", SIGGRAPH:
// the marble texture sin(x + turbulence(x)) looks a function up at a
// perturbed point; Quilez 2002, "Domain warping"), the usual cure for a
// repeating texture; here it is
// sized to the cascade's energetic waves and kept to a few percent of local
// strain (waves locally a few percent longer or shorter, or turned by a few
// degrees), measured in tests/cpu/test_spectral_tiling.cpp.
//
// The CPU twin (spectral_cpu.cpp) and the GPU (shaders/ocean/spectral.glsl)
// evaluate the same sinusoids: the CPU in double from the world origin, the
// GPU in float from the grid centre, with each phase at the centre reduced
// modulo 2*pi in double here and uploaded each frame, so the two agree far
// from the origin.
#pragma once

#include "swell/gpu/ocean.h"

#include <glm/mat2x2.hpp>
#include <glm/vec2.hpp>

#include <array>
#include <cstdint>

namespace swell::spectral {

inline constexpr int kWarpWaves = SWELL_FFT_WARP_WAVES;
inline constexpr int kWarpCascades = SWELL_FFT_CASCADES;

// w(x) += amplitude_m * sin(wavevector_radpm . x + phase_rad).
struct WarpWave {
    glm::dvec2 wavevector_radpm{0.0}; // q, rad/m (x, z)
    glm::dvec2 amplitude_m{0.0};      // the offset at the crest of the sinusoid, m (x, z)
    double phase_rad = 0.0;           // at the world origin, rad
};
using CascadeWarp = std::array<WarpWave, kWarpWaves>;

// The warps of a field's cascades, of patches patch_m[c] (m).
// characteristicWavelength_m[c] is the wavelength that carries cascade c's
// variance (what the warp must turn by a radian or more); the warp's
// amplitude scales with it, its wavelengths with the patch, its phases come
// from the seed. strength 0 gives no warp.
std::array<CascadeWarp, kWarpCascades> makeWarps(const std::array<double, kWarpCascades>& patch_m,
                                                 const std::array<double, kWarpCascades>& characteristicWavelength_m,
                                                 std::uint32_t seed, double strength = 1.0);

// A warp at a point: the offset w(x), m, and the Jacobian of the lookup
// point, I + dw/dx (column j: d(x + w)/dx_j), dimensionless.
struct WarpSample {
    glm::dvec2 offset_m{0.0};
    glm::dmat2 jacobian{1.0};
};
WarpSample warpAt(const CascadeWarp& warp, glm::dvec2 point_m);

// A sinusoid's phase at a point, reduced to [0, 2*pi): what the GPU gets for
// the grid centre.
double warpPhaseAt(const WarpWave& wave, glm::dvec2 point_m);

// The local strain of the warp at a point: the largest |singular value of
// the Jacobian - 1|, i.e. how much longer or shorter it makes a wave there
// (in the direction it stretches or squeezes most), dimensionless.
double strainAt(const CascadeWarp& warp, glm::dvec2 point_m);

} // namespace swell::spectral
