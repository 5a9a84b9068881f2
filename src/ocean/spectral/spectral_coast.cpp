// The spectral ocean's coast trains (spectral_coast.h).
#include "ocean/spectral/spectral_coast.h"

#include "swell/constants.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numeric>
#include <vector>

namespace swell::spectral {

WaveSet coastTrainsOf(const SpectralField& field, double depth_m)
{
    WaveSet trains;
    trains.depth_m = depth_m;
    const Cascade& band = field.cascades[0];
    const std::vector<std::complex<float>>& h0 = field.h0[0];
    std::vector<std::size_t> held;
    double bandVariance_m2 = 0.0;
    for (int row = 0; row < kSize; ++row)
        for (int col = 0; col < kSize; ++col) {
            const std::size_t i = std::size_t(row) * kSize + std::size_t(col);
            if (!band.holds(frequencyOf(row), frequencyOf(col)) || h0[i] == std::complex<float>(0.0f))
                continue;
            held.push_back(i);
            bandVariance_m2 += 2.0 * std::norm(std::complex<double>(h0[i]));
        }
    if (held.empty() || !(bandVariance_m2 > 0.0))
        return trains;
    const std::size_t count = std::min(held.size(), kMaxCoastWaves);
    // The most energetic first; of equal energy, the lower index.
    std::partial_sort(held.begin(), held.begin() + std::ptrdiff_t(count), held.end(), [&](std::size_t a, std::size_t b) {
        const float na = std::norm(h0[a]), nb = std::norm(h0[b]);
        return na != nb ? na > nb : a < b;
    });
    held.resize(count);
    double trainsVariance_m2 = 0.0;
    for (const std::size_t i : held)
        trainsVariance_m2 += 2.0 * std::norm(std::complex<double>(h0[i]));
    const double scale = std::sqrt(bandVariance_m2 / trainsVariance_m2);
    const double dk = kTwoPi / band.patch_m;
    for (const std::size_t i : held) {
        const glm::dvec2 k = dk * glm::dvec2(frequencyOf(int(i % kSize)), frequencyOf(int(i / kSize)));
        const double length = std::sqrt(k.x * k.x + k.y * k.y);
        const std::complex<double> h(h0[i]);
        Wave w;
        w.direction = k / length;
        w.wavelength_m = kTwoPi / length;
        w.amplitude_m = 2.0 * std::abs(h) * scale;
        w.steepness = field.choppiness;
        w.phase_rad = std::arg(h);
        trains.waves.push_back(w);
    }
    // Longest first, as the coast field and the shaders take them.
    std::stable_sort(trains.waves.begin(), trains.waves.end(),
                     [](const Wave& a, const Wave& b) { return a.wavelength_m > b.wavelength_m; });
    limitSteepness(trains);
    return trains;
}

CoastTrainDepths coastTrainDepthsOf(const WaveSet& trains)
{
    double variance = 0.0, weighted_m = 0.0;
    for (const Wave& w : trains.waves) {
        variance += w.amplitude_m * w.amplitude_m;
        weighted_m += w.amplitude_m * w.amplitude_m * w.wavelength_m;
    }
    const double mean_m = variance > 0.0 ? weighted_m / variance : 1.0;
    return {0.25 * mean_m, 0.5 * mean_m};
}

} // namespace swell::spectral
