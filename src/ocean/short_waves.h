// The short end of the wind-sea spectrum, where surface tension joins gravity:
// the unified spectrum of Elfouhaily, Chapron, Katsaros & Vandemark (1997),
// "A unified directional spectrum for long and short wind-driven waves",
// J. Geophys. Res. 102(C7), 15781-15796. Its short-wave part rises with the
// wind's friction velocity, which JONSWAP's gravity range cannot do, and it
// was built to give Cox & Munk's (1954) mean square slopes. Swell samples
// the long waves from its own spectrum (swell/scene/spectrum.h) and takes from
// this one the slopes of the waves shorter than any it samples, for shading.
#pragma once

namespace swell::detail {

// Elfouhaily et al. 1997's omnidirectional curvature spectrum B(k) =
// k^3*S(k) for a wind and sea age.
class ShortWaveSpectrum {
public:
    // windSpeed10_mps: U10, m/s, > 0. inverseWaveAge: U10 / c_p, clamped to
    // the paper's 0.84 (fully developed) .. 5 (young).
    ShortWaveSpectrum(double windSpeed10_mps, double inverseWaveAge);

    // B(k) = B_l + B_h (eqs. 31-32, 40-41), dimensionless; k in rad/m.
    double curvature(double wavenumber_radpm) const;
    // The short-wave part B_h alone (eq. 40).
    double shortWaveCurvature(double wavenumber_radpm) const;
    // Mean square slope of the waves between k1 and k2 (rad/m): the integral
    // of k^2*S(k) = B(k)/k over k, dimensionless.
    double slopeVariance(double k1_radpm, double k2_radpm) const;

    double frictionVelocity_mps() const { return frictionVelocity_mps_; }
    // alpha_m, the short waves' equilibrium range parameter (eq. 44).
    double shortWaveAlpha() const { return alphaM_; }

    // Phase speed of capillary-gravity waves on clean deep water,
    // c = sqrt(g/k * (1 + (k/k_m)^2)) (eq. 30 with k_m from c_m), m/s.
    static double phaseSpeed_mps(double wavenumber_radpm);
    // The slowest wave: c_m = 0.23 m/s at k_m = 2g/c_m^2 = 370 rad/m (1.7 cm).
    static constexpr double kMinimumPhaseSpeed_mps = 0.23;
    static double minimumPhaseSpeedWavenumber_radpm();

private:
    double windSpeed10_mps_, inverseWaveAge_;
    double frictionVelocity_mps_, alphaM_, alphaP_;
    double peakWavenumber_radpm_, peakPhaseSpeed_mps_, gamma_, sigma_;
};

// U*: the wind's friction velocity on the sea, sqrt(C10)*U10, with the
// drag coefficient C10 = (0.8 + 0.065*U10)*1e-3 (Wu 1982, "Wind-stress
// coefficients over sea surface from breeze to hurricane", J. Geophys. Res.
// 87(C12), eq. 4), m/s.
double frictionVelocity_mps(double windSpeed10_mps);

} // namespace swell::detail
