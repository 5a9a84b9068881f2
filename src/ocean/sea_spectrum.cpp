// SeaSpectrum: the wind sea and the swell as one directional spectrum, in
// frequency and direction or over the wave-vector plane.
#include "swell/scene/spectrum.h"

#include <cmath>
#include <numbers>

#include "ocean/clamped_settings.h"

namespace swell {

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

} // namespace

SeaSpectrum::SeaSpectrum(const WindSettings& wind)
{
    const WindSettings w = detail::clampedWind(wind, "swell::SeaSpectrum()");
    depth_m_ = w.depth_m;

    SeaComponent windSea;
    windSea.spectrum = jonswapParameters(w);
    windSea.direction_rad = w.windDirection_deg * kDegToRad;
    windSea.spreading.model = w.spreading;
    windSea.spreading.peakFrequency_radps = windSea.spectrum.peakFrequency_radps;
    // U10/c_p with the deep-water phase speed g/omega_p at the peak, as
    // Hasselmann et al. 1980 used it.
    windSea.spreading.windOverPeakSpeed = w.windSpeed_mps * windSea.spectrum.peakFrequency_radps / kGravity;
    windSea.spreading.cut_rad = w.spread_deg * kDegToRad;
    components_.push_back(windSea);

    if (w.swell) {
        SeaComponent swell;
        swell.spectrum = swellParameters(*w.swell, w.depth_m);
        swell.direction_rad = w.swell->direction_deg * kDegToRad;
        swell.spreading.peakFrequency_radps = swell.spectrum.peakFrequency_radps;
        swell.spreading.swellPeakExponent = w.swell->sMax;
        components_.push_back(swell);
    }
}

double SeaSpectrum::frequencyDensity(double omega_radps) const
{
    double sum = 0.0;
    for (const SeaComponent& c : components_)
        sum += spectralDensity(c.spectrum, omega_radps);
    return sum;
}

double SeaSpectrum::directionalDensity(double omega_radps, double direction_rad) const
{
    double sum = 0.0;
    for (const SeaComponent& c : components_)
        sum += spectralDensity(c.spectrum, omega_radps)
             * spreadingDensity(c.spreading, omega_radps, direction_rad - c.direction_rad);
    return sum;
}

double SeaSpectrum::wavenumberDensity(double kx_radpm, double kz_radpm) const
{
    const double k = std::hypot(kx_radpm, kz_radpm);
    if (!(k > 0.0))
        return 0.0;
    const double omega = angularFrequency(k, depth_m_);
    // F(omega, theta) d(omega) d(theta) = Psi(k) k dk d(theta).
    return directionalDensity(omega, std::atan2(kz_radpm, kx_radpm)) * groupVelocity(k, depth_m_) / k;
}

} // namespace swell
