// Wave sets generated from the wind: wavelengths and amplitudes drawn from a
// real ocean spectrum, directions spread around the wind. Seeded, so the same
// settings always give the same waves.
#pragma once

#include "swell/export.h"

#include "swell/waves.h"

#include <cstdint>

namespace swell {

struct SWELL_API WindSettings {
    double windSpeed_mps = 8.0;       // wind speed 10 m above the sea, m/s, 0.5..40
    double windDirection_deg = 0.0;   // direction the wind blows towards, degrees from +x towards +z
    double spread_deg = 35.0;         // half-width of the directional spread, degrees, 0..180
    double fetch_km = 300.0;          // distance over which the wind has blown, km, 1..10000
    int waveCount = 32;               // how many waves, 1..SWELL_MAX_WAVES
    double minWavelength_m = 0.5;     // shortest wave generated, m, > 0
    std::uint32_t seed = 1;           // random seed
    double steepness = 0.6;           // overall choppiness, 0..1 (scaled to stay fold-free)
    double depth_m = std::numeric_limits<double>::infinity(); // water depth, m
};

// The JONSWAP spectrum of a wind (Hasselmann et al. 1973), in finite depth
// with the TMA factor (Bouws et al. 1985).
struct SWELL_API SpectrumParameters {
    double alpha = 0.0081;            // Phillips constant, dimensionless
    double peakFrequency_radps = 1.0; // omega_p, rad/s
    double gamma = 3.3;               // peak enhancement, dimensionless
    double depth_m = std::numeric_limits<double>::infinity(); // water depth, m
};

// Parameters for a wind, after the clamping generateWaves() applies.
// Fetch-limited: alpha = 0.076*chi^-0.22 and omega_p = 22*(g/U)*chi^(-1/3)
// with chi = g*fetch/U^2. chi is capped where omega_p reaches the fully
// developed Pierson-Moskowitz peak 0.877*g/U (chi ~ 15800, 160 km of fetch
// at 10 m/s): longer fetch adds nothing.
SWELL_API SpectrumParameters jonswapParameters(const WindSettings& wind);

// Energy density S(omega), m^2*s/rad, at angular frequency omega_radps > 0.
SWELL_API double spectralDensity(const SpectrumParameters& spectrum, double omega_radps);

// Significant wave height 4*sqrt(m0), m, of a wave set, where m0 = sum(A^2/2)
// is the variance of the surface height.
SWELL_API double significantWaveHeight(const WaveSet& set);

// Draws a wave set whose energy follows the JONSWAP spectrum for the given
// wind, fetch and depth, split over waveCount waves. The result passes
// validate() and has foldMeasure() <= 1.
//
// The frequency range runs from 0.7*omega_p (below it lies 0.5% of the
// energy) to the frequency of minWavelength_m, cut into waveCount bands of
// equal width in log(omega); each wave carries its band's energy,
// A = sqrt(2*integral of S), at a frequency drawn inside the band. Directions
// spread around the wind with a triangular distribution of half-width
// spread_deg; phases are uniform. Every wave gets Q = steepness, then
// limitSteepness() scales them all to stay fold-free. If minWavelength_m is
// longer than the waves near the peak, the range is the octave below it.
//
// Inputs out of their documented ranges are clamped into them (wind speed to
// 0.5..40 m/s, spread to 0..180 deg, fetch to 1..10000 km, waveCount to
// 1..SWELL_MAX_WAVES, minWavelength_m to 0.05..1000 m, steepness to 0..1,
// depth_m up to at least 0.1 m). NaN or infinite inputs (other than an
// infinite depth), and a depth <= 0, throw std::invalid_argument.
//
// The same settings give bit-identical waves: the random numbers come from
// std::mt19937, whose sequence the C++ standard fixes, through distributions
// written here, not the standard library's implementation-defined ones.
SWELL_API WaveSet generateWaves(const WindSettings& wind);

} // namespace swell
