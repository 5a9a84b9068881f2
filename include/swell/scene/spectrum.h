// The sea's wave spectrum, from the wind (and optionally a distant swell):
// the frequency spectrum, how its energy spreads over directions, and the
// directional wave-number spectrum an FFT ocean samples; plus Gerstner wave
// sets drawn from it, seeded, so the same settings always give the same waves.
//
// Sources (each formula cites its own in src/ocean/):
//   JONSWAP spectrum and fetch laws   Hasselmann et al. 1973
//   Pierson-Moskowitz (fully developed) Pierson & Moskowitz 1964
//   TMA finite-depth factor           Bouws et al. 1985 (Kitaigorodskii et al. 1975)
//   cos^2s(theta/2) spreading         Mitsuyasu et al. 1975, s(omega) of Hasselmann et al. 1980
//   sech^2(beta*theta) spreading      Donelan et al. 1985, Banner 1990
#pragma once

#include "swell/export.h"

#include "swell/scene/sea_state.h"
#include "swell/scene/waves.h"

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

namespace swell {

// A JONSWAP frequency spectrum (Hasselmann et al. 1973), in finite depth with
// the TMA factor (Bouws et al. 1985). gamma = 1 is Pierson-Moskowitz.
struct SWELL_API SpectrumParameters {
    double alpha = 0.0081;            // Phillips constant, dimensionless
    double peakFrequency_radps = 1.0; // omega_p, rad/s
    double gamma = 3.3;               // peak enhancement, dimensionless
    double depth_m = std::numeric_limits<double>::infinity(); // water depth, m
};

// ---------------------------------------------------------------------------
// Frequency spectra

// The wind speed 19.5 m above the sea, which Pierson & Moskowitz used, from
// the 10 m wind: the power law U(z) ~ z^0.11 over the sea (about 1.076*U10).
SWELL_API double windSpeedAt19_5m(double windSpeed10_mps);

// The fully developed sea (Pierson & Moskowitz 1964): alpha = 0.0081,
// omega_p = 0.877*g/U19.5, gamma = 1; Hs = 0.21*U19.5^2/g.
SWELL_API SpectrumParameters piersonMoskowitzParameters(double windSpeed10_mps);

// The wind sea for a wind, after the clamping generateWaves() applies.
// Fetch-limited (chi = g*F/U10^2): Hs and omega_p follow the JONSWAP growth
// laws g*Hs/U10^2 = 1.6e-3*sqrt(chi) and omega_p = 22*(g/U10)*chi^(-1/3),
// gamma follows from Hs and the peak period (DNV-RP-C205), and alpha is
// whatever makes the spectrum carry exactly that Hs. Each law stops at the
// Pierson-Moskowitz value; once both have, the sea is fully developed and the
// spectrum is Pierson-Moskowitz's.
SWELL_API SpectrumParameters jonswapParameters(const WindSettings& wind);

// The swell's spectrum: peak at 2*pi/period_s, the given gamma, alpha that
// gives height_m in deep water. Throws std::invalid_argument on non-finite input.
SWELL_API SpectrumParameters swellParameters(const SwellSettings& swell, double depth_m);

// The JONSWAP peak enhancement DNV-RP-C205 (2010, sec. 3.5.5.5) recommends
// for a sea of significant height Hs and peak period Tp: 5 up to
// Tp/sqrt(Hs) = 3.6 s/sqrt(m), exp(5.75 - 1.15*Tp/sqrt(Hs)) between, 1 from 5 on.
SWELL_API double dnvPeakEnhancement(double peakPeriod_s, double significantHeight_m);

// The alpha that makes a deep-water JONSWAP spectrum of this peak and gamma
// carry significant wave height Hs (4*sqrt(m0) = Hs), from the integral of its shape.
SWELL_API double jonswapAlphaFor(double significantHeight_m, double peakFrequency_radps, double gamma);

// Energy density S(omega), m^2*s/rad, at angular frequency omega_radps > 0
// (0 elsewhere), TMA factor included.
SWELL_API double spectralDensity(const SpectrumParameters& spectrum, double omega_radps);

// The TMA factor Phi(omega, h) (Kitaigorodskii et al. 1975, used by Bouws et
// al. 1985): how much of the deep-water spectrum depth h leaves at omega.
// 1 in deep water, omega^2*h/(2g) in very shallow water.
SWELL_API double tmaFactor(double omega_radps, double depth_m);

// Wavenumber, rad/m, of angular frequency omega in water of depth h: the
// root of omega^2 = g*k*tanh(k*h). Inverse of angularFrequency().
SWELL_API double wavenumberOf(double omega_radps, double depth_m);

// Group velocity d(omega)/dk, m/s, of wavenumber k in depth h.
SWELL_API double groupVelocity(double wavenumber_radpm, double depth_m);

// ---------------------------------------------------------------------------
// Directional spreading

// How one component of the sea spreads over directions. D(theta; omega) is in
// 1/rad and integrates to 1 over theta in (-pi, pi]; theta is measured from
// the component's mean direction. Outside |theta| <= cut_rad it is 0, and
// inside it is scaled up so that it still integrates to 1.
struct SWELL_API Spreading {
    SpreadingModel model = SpreadingModel::Mitsuyasu;
    double peakFrequency_radps = 1.0;
    // U10/c_p, the inverse wave age at the peak; sets how fast a wind sea's
    // cos^2s spreading widens above the peak (Hasselmann et al. 1980).
    double windOverPeakSpeed = 1.0;
    // > 0: a swell, cos^2s with s = swellPeakExponent*(omega/omega_p)^5 below
    // the peak and ^-2.5 above (Mitsuyasu et al. 1975); model is ignored.
    double swellPeakExponent = 0.0;
    double cut_rad = 3.14159265358979323846; // pi: no cut
};

// The exponent s of cos^2s(theta/2) at omega (Mitsuyasu spreading or a swell).
SWELL_API double spreadingExponent(const Spreading& spreading, double omega_radps);

// beta of the sech^2(beta*theta) spreading at omega (Donelan et al. 1985; Banner 1990).
SWELL_API double donelanBannerBeta(double omegaOverPeak);

// D(theta; omega), 1/rad.
SWELL_API double spreadingDensity(const Spreading& spreading, double omega_radps, double theta_rad);

// ---------------------------------------------------------------------------
// The sea: wind sea plus swell

// One part of the sea: a frequency spectrum travelling around a mean direction.
struct SWELL_API SeaComponent {
    SpectrumParameters spectrum;
    double direction_rad = 0.0; // mean direction of travel, from +x towards +z
    Spreading spreading;
};

// The directional spectrum of the sea a WindSettings describes, for samplers
// such as an FFT ocean. Directions are angles from +x towards +z (the
// direction a wave travels); a wave vector (k_x, k_z) travels at atan2(k_z, k_x).
class SWELL_API SeaSpectrum {
public:
    // Clamps and checks the wind as generateWaves() does (throws
    // std::invalid_argument on NaN or infinite input, and on depth <= 0).
    explicit SeaSpectrum(const WindSettings& wind);

    // The wind sea first, then the swell when there is one.
    std::span<const SeaComponent> components() const { return components_; }
    double depth_m() const { return depth_m_; }

    // Omnidirectional S(omega), m^2*s/rad: the sum over the components.
    double frequencyDensity(double omega_radps) const;

    // F(omega, theta) = sum of S_i(omega)*D_i(theta - theta_i; omega), m^2*s/rad^2.
    double directionalDensity(double omega_radps, double direction_rad) const;

    // The wave-number spectrum Psi(k_x, k_z), m^4 (m^2 of height variance per
    // (rad/m)^2 of wave-vector area), so that the variance of the surface is
    // the integral of Psi over the k plane. With omega = omega(|k|) from
    // omega^2 = g*k*tanh(k*h): Psi = F(omega, theta) * (d(omega)/dk) / k,
    // where d(omega)/dk (the group velocity) carries the spectrum from
    // frequency to wavenumber and 1/k from polar (k, theta) to Cartesian
    // (k_x, k_z), since dk_x*dk_z = k*dk*dtheta. 0 at k = 0.
    double wavenumberDensity(double kx_radpm, double kz_radpm) const;

private:
    std::vector<SeaComponent> components_;
    double depth_m_ = std::numeric_limits<double>::infinity();
};

// ---------------------------------------------------------------------------
// Gerstner wave sets

// Significant wave height 4*sqrt(m0), m, of a wave set, where m0 = sum(A^2/2)
// is the variance of the surface height.
SWELL_API double significantWaveHeight(const WaveSet& set);

// Draws a wave set whose energy follows the sea's spectrum (SeaSpectrum of
// the wind), waveCount waves for the wind sea and, with a swell,
// swell->waveCount more after them. The result passes validate() and has
// foldMeasure() <= 1.
//
// Wind sea: the frequency range runs from 0.7*omega_p (below it lies 0.5% of
// the energy) to the frequency of minWavelength_m, cut into waveCount bands
// of equal width in log(omega); each wave carries its band's energy,
// A = sqrt(2*integral of S), at a frequency drawn inside the band. If
// minWavelength_m is longer than the waves near the peak, the range is the
// octave below it. Swell: the same from 0.7 to 3 times its peak frequency
// (over 99% of its energy), never past the frequency of minWavelength_m.
// Each wave's direction is drawn from its component's spreading D(theta;
// omega) at the wave's frequency (for the wind sea cut at spread_deg); phases
// are uniform. Every wave gets Q = steepness, then limitSteepness() scales
// them all to stay fold-free.
//
// Inputs out of their documented ranges are clamped into them (wind speed to
// 0.5..40 m/s, spread to 0..180 deg, fetch to 1..10000 km, waveCount to
// 1..SWELL_MAX_WAVES, minWavelength_m to 0.05..1000 m, steepness to 0..1,
// depth_m up to at least 0.1 m; swell height to 0..15 m, period to 3..25 s,
// gamma to 1..10, sMax to 1..200, its waveCount to 1..SWELL_MAX_WAVES - 1 and
// then the wind's count to at most SWELL_MAX_WAVES minus the swell's). NaN or
// infinite inputs (other than an infinite depth), and a depth <= 0, throw
// std::invalid_argument.
//
// The same settings give bit-identical waves: the random numbers come from
// std::mt19937, whose sequence the C++ standard fixes, through distributions
// written here, not the standard library's implementation-defined ones.
SWELL_API WaveSet generateWaves(const WindSettings& wind);

} // namespace swell
