#include "ocean/short_waves.h"

#include "swell/constants.h"

#include <algorithm>
#include <cmath>

namespace swell::detail {

double frictionVelocity_mps(double windSpeed10_mps)
{
    const double drag = (0.8 + 0.065 * windSpeed10_mps) * 1.0e-3;
    return std::sqrt(drag) * windSpeed10_mps;
}

double ShortWaveSpectrum::minimumPhaseSpeedWavenumber_radpm()
{
    return 2.0 * kGravity / (kMinimumPhaseSpeed_mps * kMinimumPhaseSpeed_mps);
}

double ShortWaveSpectrum::phaseSpeed_mps(double k)
{
    const double km = minimumPhaseSpeedWavenumber_radpm();
    return std::sqrt(kGravity / k * (1.0 + (k / km) * (k / km)));
}

ShortWaveSpectrum::ShortWaveSpectrum(double windSpeed10_mps, double inverseWaveAge)
    : windSpeed10_mps_(windSpeed10_mps), inverseWaveAge_(std::clamp(inverseWaveAge, 0.84, 5.0))
{
    const double omega = inverseWaveAge_;
    frictionVelocity_mps_ = detail::frictionVelocity_mps(windSpeed10_mps);
    // Eq. 44: the short waves' equilibrium parameter grows with u*/c_m.
    const double ratio = frictionVelocity_mps_ / kMinimumPhaseSpeed_mps;
    alphaM_ = 0.01 * (ratio <= 1.0 ? 1.0 + std::log(ratio) : 1.0 + 3.0 * std::log(ratio));
    // Eq. 34: the long waves' (generalised Phillips-Kitaigorodskii) parameter.
    alphaP_ = 6.0e-3 * std::pow(omega, 0.55);
    // Eqs. 3 and 37: the peak from the sea's age, k_p = g*Omega^2/U10^2.
    peakWavenumber_radpm_ = kGravity * omega * omega / (windSpeed10_mps * windSpeed10_mps);
    peakPhaseSpeed_mps_ = std::sqrt(kGravity / peakWavenumber_radpm_);
    // Eq. 3 (JONSWAP peak enhancement as the paper takes it).
    gamma_ = omega <= 1.0 ? 1.7 : 1.7 + 6.0 * std::log10(omega);
    sigma_ = 0.08 * (1.0 + 4.0 * std::pow(omega, -3.0));
}

double ShortWaveSpectrum::curvature(double k) const
{
    const double kp = peakWavenumber_radpm_;
    const double c = phaseSpeed_mps(k);
    // Eqs. 32-33: the long-wave side effect function, a JONSWAP shape in k.
    const double pm = std::exp(-1.25 * (kp / k) * (kp / k));
    const double x = std::sqrt(k / kp) - 1.0;
    const double peak = std::pow(gamma_, std::exp(-x * x / (2.0 * sigma_ * sigma_)));
    const double fp = pm * peak * std::exp(-inverseWaveAge_ / std::sqrt(10.0) * x);
    const double longWaves = 0.5 * alphaP_ * (peakPhaseSpeed_mps_ / c) * fp;
    return longWaves + shortWaveCurvature(k);
}

double ShortWaveSpectrum::shortWaveCurvature(double k) const
{
    const double km = minimumPhaseSpeedWavenumber_radpm();
    const double kp = peakWavenumber_radpm_;
    // Eq. 41, with the long-wave cut-off L_PM that later uses of the spectrum
    // apply so the short-wave part does not reach down to the peak (it is 1
    // wherever short waves matter, k >> k_p).
    const double pm = std::exp(-1.25 * (kp / k) * (kp / k));
    const double fm = pm * std::exp(-0.25 * (k / km - 1.0) * (k / km - 1.0));
    return 0.5 * alphaM_ * (kMinimumPhaseSpeed_mps / phaseSpeed_mps(k)) * fm;
}

double ShortWaveSpectrum::slopeVariance(double k1, double k2) const
{
    if (!(k1 < k2))
        return 0.0;
    // Simpson's rule in u = ln k: the integrand B(k) is smooth in ln k, and
    // 1024 intervals resolve the gravity-capillary peak over any span.
    const double a = std::log(k1), b = std::log(k2);
    constexpr int n = 1024;
    const double h = (b - a) / n;
    double sum = curvature(k1) + curvature(k2);
    for (int i = 1; i < n; ++i)
        sum += (i % 2 == 1 ? 4.0 : 2.0) * curvature(std::exp(a + i * h));
    return sum * h / 3.0;
}

} // namespace swell::detail
