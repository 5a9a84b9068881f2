// Gerstner wave sets drawn from the sea's spectrum: each component's
// frequency range cut into log-spaced bands, one wave per band carrying that
// band's energy, its direction drawn from the spreading at its frequency. The
// random draws go through distributions written here so that a seed gives the
// same waves with every standard library.
#include "swell/scene/spectrum.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>

#include "ocean/clamped_settings.h"

namespace swell {

namespace {


// Uniform in [0, 1) with 53 random bits from two 32-bit draws.
double uniform01(std::mt19937& rng)
{
    const std::uint32_t a = rng() >> 5; // 27 bits
    const std::uint32_t b = rng() >> 6; // 26 bits
    return (a * 67108864.0 + b) * (1.0 / 9007199254740992.0);
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

// An angle from the mean direction with density D(theta; omega): uMagnitude
// picks |theta| by inverting the cumulative D over [0, cut] (tabulated in 256
// trapezoids, linear inside each), uSide the side; D is even.
double drawAngle(const Spreading& spreading, double omega_radps, double uMagnitude, double uSide)
{
    const double cut = std::min(spreading.cut_rad, kPi);
    if (!(cut > 0.0))
        return 0.0;
    // The uncut density: the cut's normalisation cancels in the inversion.
    Spreading uncut = spreading;
    uncut.cut_rad = kPi;
    constexpr int kSteps = 256;
    const double h = cut / kSteps;
    std::array<double, kSteps + 1> cumulative{};
    double previous = spreadingDensity(uncut, omega_radps, 0.0);
    for (int i = 1; i <= kSteps; ++i) {
        const double d = spreadingDensity(uncut, omega_radps, i * h);
        cumulative[i] = cumulative[i - 1] + 0.5 * (previous + d) * h;
        previous = d;
    }
    const double target = uMagnitude * cumulative[kSteps];
    const int i = static_cast<int>(std::upper_bound(cumulative.begin(), cumulative.end(), target) - cumulative.begin()) - 1;
    double magnitude = cut;
    if (i < kSteps) {
        const double width = cumulative[i + 1] - cumulative[i];
        magnitude = (i + (width > 0.0 ? (target - cumulative[i]) / width : 0.0)) * h;
    }
    return uSide < 0.5 ? -magnitude : magnitude;
}

// Appends `count` waves of one component over [omegaLow, omegaHigh].
void addWaves(WaveSet& set, const SeaComponent& component, int count, double omegaLow, double omegaHigh,
              const WindSettings& w, std::mt19937& rng)
{
    const double logSpan = std::log(omegaHigh / omegaLow);
    for (int i = 0; i < count; ++i) {
        // A fixed order of draws per wave keeps every seed reproducible.
        const double uFrequency = uniform01(rng);
        const double uMagnitude = uniform01(rng);
        const double uSide = uniform01(rng);
        const double uPhase = uniform01(rng);

        const double a = omegaLow * std::exp(logSpan * i / count);
        const double b = omegaLow * std::exp(logSpan * (i + 1) / count);
        const double omega = a * std::pow(b / a, uFrequency);

        Wave wave;
        const double angle = component.direction_rad + drawAngle(component.spreading, omega, uMagnitude, uSide);
        wave.direction = {std::cos(angle), std::sin(angle)};
        wave.wavelength_m = std::max(2.0 * kPi / wavenumberOf(omega, w.depth_m), w.minWavelength_m);
        wave.amplitude_m = std::sqrt(2.0 * bandEnergy(component.spectrum, a, b));
        wave.steepness = w.steepness;
        wave.phase_rad = 2.0 * kPi * uPhase - kPi;
        set.waves.push_back(wave);
    }
}

} // namespace

double significantWaveHeight(const WaveSet& set)
{
    double variance = 0.0;
    for (const Wave& wave : set.waves)
        variance += 0.5 * wave.amplitude_m * wave.amplitude_m;
    return 4.0 * std::sqrt(variance);
}

WaveSet generateWaves(const WindSettings& wind)
{
    const WindSettings w = detail::clampedWind(wind, "swell::generateWaves()");
    const SeaSpectrum sea(w);
    const double omegaShortest = angularFrequency(2.0 * kPi / w.minWavelength_m, w.depth_m);

    WaveSet set;
    set.depth_m = w.depth_m;
    std::mt19937 rng(w.seed);

    const SeaComponent& windSea = sea.components()[0];
    const double windLow = std::min(0.7 * windSea.spectrum.peakFrequency_radps, 0.5 * omegaShortest);
    addWaves(set, windSea, w.waveCount, windLow, omegaShortest, w, rng);

    if (w.swell) {
        const SeaComponent& swell = sea.components()[1];
        const double swellHigh = std::min(3.0 * swell.spectrum.peakFrequency_radps, omegaShortest);
        const double swellLow = std::min(0.7 * swell.spectrum.peakFrequency_radps, 0.5 * swellHigh);
        addWaves(set, swell, w.swell->waveCount, swellLow, swellHigh, w, rng);
    }
    limitSteepness(set);
    return set;
}

} // namespace swell
