// Wave sets from the wind: the JONSWAP spectrum cut into log-spaced frequency
// bands, one Gerstner wave per band carrying that band's energy. The random
// draws go through distributions written here so that a seed gives the same
// waves with every standard library.
#include "swell/spectrum.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace swell {

namespace {


// Uniform in [0, 1) with 53 random bits from two 32-bit draws.
double uniform01(std::mt19937& rng)
{
    const std::uint32_t a = rng() >> 5; // 27 bits
    const std::uint32_t b = rng() >> 6; // 26 bits
    return (a * 67108864.0 + b) * (1.0 / 9007199254740992.0);
}

// Triangular on [-1, 1], peaked at 0: most waves run with the wind, a few
// across it, none outside the spread.
double triangular(std::mt19937& rng)
{
    const double u1 = uniform01(rng);
    const double u2 = uniform01(rng);
    return u1 + u2 - 1.0;
}

double requireFinite(double value, const char* field)
{
    if (!std::isfinite(value))
        throw std::invalid_argument(fmt::format("swell::generateWaves(): {} must be finite (got {})", field, value));
    return value;
}

// The wind with every field inside its documented range.
WindSettings clamped(const WindSettings& wind)
{
    WindSettings w = wind;
    w.windSpeed_mps = std::clamp(requireFinite(wind.windSpeed_mps, "windSpeed_mps"), 0.5, 40.0);
    w.windDirection_deg = requireFinite(wind.windDirection_deg, "windDirection_deg");
    w.spread_deg = std::clamp(requireFinite(wind.spread_deg, "spread_deg"), 0.0, 180.0);
    w.fetch_km = std::clamp(requireFinite(wind.fetch_km, "fetch_km"), 1.0, 10000.0);
    w.waveCount = std::clamp(wind.waveCount, 1, SWELL_MAX_WAVES);
    // Below ~2 cm surface tension, not gravity, sets the speed of a wave.
    w.minWavelength_m = std::clamp(requireFinite(wind.minWavelength_m, "minWavelength_m"), 0.05, 1000.0);
    w.steepness = std::clamp(requireFinite(wind.steepness, "steepness"), 0.0, 1.0);
    if (!(wind.depth_m > 0.0)) // also NaN
        throw std::invalid_argument(
            fmt::format("swell::generateWaves(): depth_m must be > 0 or infinity (got {})", wind.depth_m));
    w.depth_m = std::max(wind.depth_m, 0.1);
    return w;
}

// TMA depth factor, the usual piecewise fit to Kitaigorodskii's ratio: 1 in
// deep water, falling as omega*sqrt(h/g) drops below 2, like (omega*sqrt(h/g))^2/2
// in very shallow water.
double tmaFactor(double omega_radps, double depth_m)
{
    if (std::isinf(depth_m))
        return 1.0;
    const double wh = omega_radps * std::sqrt(depth_m / kGravity);
    if (wh <= 1.0)
        return 0.5 * wh * wh;
    if (wh < 2.0)
        return 1.0 - 0.5 * (2.0 - wh) * (2.0 - wh);
    return 1.0;
}

// Wavenumber, rad/m, of angular frequency omega in water of depth h: the
// root of g*k*tanh(k*h) = omega^2, which increases with k. It lies between
// the larger of the deep (omega^2/g) and shallow (omega/sqrt(g*h)) answers,
// both lower bounds, and omega^2/(g*tanh(kLow*h)); bisection to the last bit.
double wavenumberOf(double omega_radps, double depth_m)
{
    const double deep = omega_radps * omega_radps / kGravity;
    if (std::isinf(depth_m))
        return deep;
    double low = std::max(deep, omega_radps / std::sqrt(kGravity * depth_m));
    double high = deep / std::tanh(low * depth_m);
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (low + high);
        if (mid <= low || mid >= high)
            break;
        (angularFrequency(mid, depth_m) < omega_radps ? low : high) = mid;
    }
    return 0.5 * (low + high);
}

// Integral of S over [a, b] by Simpson's rule: 16 intervals resolve the
// JONSWAP peak (relative width 0.07) in bands of up to ~40% of omega.
double bandEnergy(const SpectrumParameters& spectrum, double a, double b)
{
    constexpr int kIntervals = 16;
    const double h = (b - a) / kIntervals;
    double sum = spectralDensity(spectrum, a) + spectralDensity(spectrum, b);
    for (int i = 1; i < kIntervals; ++i)
        sum += (i % 2 == 1 ? 4.0 : 2.0) * spectralDensity(spectrum, a + i * h);
    return sum * h / 3.0;
}

} // namespace

SpectrumParameters jonswapParameters(const WindSettings& wind)
{
    const WindSettings w = clamped(wind);
    const double u = w.windSpeed_mps;
    // Dimensionless fetch, capped where the fetch-limited peak reaches the
    // fully developed Pierson-Moskowitz peak 0.877*g/U: chi = (22/0.877)^3,
    // about 15800 (160 km at 10 m/s). Beyond it the sea no longer grows.
    constexpr double kChiFullyDeveloped = (22.0 / 0.877) * (22.0 / 0.877) * (22.0 / 0.877);
    const double chi = std::min(kGravity * w.fetch_km * 1000.0 / (u * u), kChiFullyDeveloped);
    SpectrumParameters p;
    p.alpha = 0.076 * std::pow(chi, -0.22);
    p.peakFrequency_radps = 22.0 * kGravity / u * std::cbrt(1.0 / chi);
    p.gamma = 3.3;
    p.depth_m = w.depth_m;
    return p;
}

double spectralDensity(const SpectrumParameters& spectrum, double omega_radps)
{
    if (!(omega_radps > 0.0))
        return 0.0;
    const double wp = spectrum.peakFrequency_radps;
    const double ratio = wp / omega_radps;
    const double sigma = omega_radps <= wp ? 0.07 : 0.09;
    const double offPeak = (omega_radps - wp) / (sigma * wp);
    const double peakEnhancement = std::pow(spectrum.gamma, std::exp(-0.5 * offPeak * offPeak));
    const double pm = spectrum.alpha * kGravity * kGravity / std::pow(omega_radps, 5.0)
                    * std::exp(-1.25 * std::pow(ratio, 4.0));
    return pm * peakEnhancement * tmaFactor(omega_radps, spectrum.depth_m);
}

double significantWaveHeight(const WaveSet& set)
{
    double variance = 0.0;
    for (const Wave& wave : set.waves)
        variance += 0.5 * wave.amplitude_m * wave.amplitude_m;
    return 4.0 * std::sqrt(variance);
}

WaveSet generateWaves(const WindSettings& wind)
{
    const WindSettings w = clamped(wind);
    const SpectrumParameters spectrum = jonswapParameters(w);

    const double omegaHigh = angularFrequency(2.0 * kPi / w.minWavelength_m, w.depth_m);
    const double omegaLow = std::min(0.7 * spectrum.peakFrequency_radps, 0.5 * omegaHigh);
    const double logSpan = std::log(omegaHigh / omegaLow);

    WaveSet set;
    set.depth_m = w.depth_m;
    std::mt19937 rng(w.seed);
    const double windDirection_rad = w.windDirection_deg * (kPi / 180.0);
    const double spread_rad = w.spread_deg * (kPi / 180.0);
    for (int i = 0; i < w.waveCount; ++i) {
        // A fixed order of draws per wave keeps every seed reproducible.
        const double uFrequency = uniform01(rng);
        const double uDirection = triangular(rng);
        const double uPhase = uniform01(rng);

        const double a = omegaLow * std::exp(logSpan * i / w.waveCount);
        const double b = omegaLow * std::exp(logSpan * (i + 1) / w.waveCount);
        const double omega = a * std::pow(b / a, uFrequency);

        Wave wave;
        const double angle = windDirection_rad + spread_rad * uDirection;
        wave.direction = {std::cos(angle), std::sin(angle)};
        wave.wavelength_m = std::max(2.0 * kPi / wavenumberOf(omega, w.depth_m), w.minWavelength_m);
        wave.amplitude_m = std::sqrt(2.0 * bandEnergy(spectrum, a, b));
        wave.steepness = w.steepness;
        wave.phase_rad = 2.0 * kPi * uPhase - kPi;
        set.waves.push_back(wave);
    }
    limitSteepness(set);
    return set;
}

} // namespace swell
