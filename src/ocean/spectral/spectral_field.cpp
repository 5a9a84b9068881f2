// The spectral ocean's seeded initial field and its evolution in time.
#include "ocean/spectral/spectral_field.h"

#include "ocean/short_waves.h"

#include "swell/constants.h"
#include "swell/scene/waves.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace swell::spectral {

namespace {

// A standard normal pair from two uniform draws (Box & Muller 1958), written
// here so the numbers do not depend on a standard library's distributions.
struct NormalPair {
    double a, b;
};
NormalPair normalPair(std::mt19937& rng)
{
    const double u1 = (double(rng()) + 0.5) / 4294967296.0; // (0, 1)
    const double u2 = (double(rng()) + 0.5) / 4294967296.0;
    const double r = std::sqrt(-2.0 * std::log(u1));
    return {r * std::cos(kTwoPi * u2), r * std::sin(kTwoPi * u2)};
}

} // namespace

double Cascade::shortestWavelength_m() const { return kTwoPi / maxWavenumber_radpm; }

bool Cascade::holds(int fz, int fx) const
{
    if (fz == -kSize / 2 || fx == -kSize / 2 || (fz == 0 && fx == 0))
        return false;
    const double dk = kTwoPi / patch_m;
    const double k = std::hypot(dk * fx, dk * fz);
    return k >= minWavenumber_radpm && k < maxWavenumber_radpm;
}

namespace {

// Calls f(kx, kz, dk) for every sample that carries a wave, in every cascade.
template <class F>
void forEachWave(const std::array<Cascade, kCascades>& cascades, F f)
{
    for (const Cascade& cascade : cascades) {
        const double dk = kTwoPi / cascade.patch_m;
        for (int fz = -kSize / 2; fz < kSize / 2; ++fz)
            for (int fx = -kSize / 2; fx < kSize / 2; ++fx)
                if (cascade.holds(fz, fx))
                    f(dk * fx, dk * fz, dk);
    }
}

} // namespace

double sampledHeightVariance_m2(const SeaSpectrum& sea, const std::array<Cascade, kCascades>& cascades)
{
    double sum = 0.0;
    forEachWave(cascades, [&](double kx, double kz, double dk) { sum += sea.wavenumberDensity(kx, kz) * dk * dk; });
    return sum;
}

double sampledSlopeVariance(const SeaSpectrum& sea, const std::array<Cascade, kCascades>& cascades)
{
    double sum = 0.0;
    forEachWave(cascades, [&](double kx, double kz, double dk) {
        sum += (kx * kx + kz * kz) * sea.wavenumberDensity(kx, kz) * dk * dk;
    });
    return sum;
}

double unresolvedSlopeVariance(const SeaSpectrum& sea, double shortestResolvedWavelength_m)
{
    const SeaComponent& windSea = sea.components().front();
    const double peak_radps = windSea.spectrum.peakFrequency_radps;
    const double inverseWaveAge = windSea.spreading.windOverPeakSpeed;
    const double windSpeed10_mps = inverseWaveAge * kGravity / peak_radps;
    const detail::ShortWaveSpectrum shortWaves(windSpeed10_mps, inverseWaveAge);
    // Up to 10 k_m (1.7 mm), where the short-wave part has fallen by e^-20.
    const double end_radpm = 10.0 * detail::ShortWaveSpectrum::minimumPhaseSpeedWavenumber_radpm();
    return shortWaves.slopeVariance(kTwoPi / shortestResolvedWavelength_m, end_radpm);
}

std::array<Cascade, kCascades> cascadeLayout(double peakWavelength_m)
{
    std::array<Cascade, kCascades> c{};
    const double largestPatch_m = std::max(10.0 * peakWavelength_m, 100.0);
    constexpr double kRatio = 6.65;
    for (int i = 0; i < kCascades; ++i) {
        c[size_t(i)].patch_m = largestPatch_m / std::pow(kRatio, i);
        // 32 cycles per patch: 8 texels per wavelength; the last cascade 64 (4 texels).
        const double cycles = i + 1 < kCascades ? 32.0 : 64.0;
        c[size_t(i)].maxWavenumber_radpm = kTwoPi * cycles / c[size_t(i)].patch_m;
        c[size_t(i)].minWavenumber_radpm = i == 0 ? 0.0 : c[size_t(i - 1)].maxWavenumber_radpm;
    }
    return c;
}

SpectralField makeSpectralField(const SeaSpectrum& sea, double choppiness, std::uint32_t seed, double warpStrength)
{
    SpectralField f;
    // The longest peak of the sea's components (the wind sea, a swell).
    double peakWavelength_m = 0.0;
    for (const SeaComponent& component : sea.components())
        peakWavelength_m = std::max(peakWavelength_m,
                                    kTwoPi / wavenumberOf(component.spectrum.peakFrequency_radps, sea.depth_m()));
    f.cascades = cascadeLayout(peakWavelength_m);
    f.choppiness = choppiness;
    std::mt19937 rng(seed);
    double sumAbs = 0.0;
    // Per cascade: the variance-weighted mean wavelength, what its warp must turn.
    std::array<double, kCascades> patches_m{}, meanWavelength_m{};
    for (int c = 0; c < kCascades; ++c) {
        const Cascade& cascade = f.cascades[size_t(c)];
        const double dk = kTwoPi / cascade.patch_m;
        std::vector<std::complex<double>> h0(size_t(kSize) * kSize);
        f.omega_radps[size_t(c)].assign(h0.size(), 0.0);
        for (int row = 0; row < kSize; ++row)
            for (int col = 0; col < kSize; ++col) {
                const int fz = frequencyOf(row), fx = frequencyOf(col);
                // Every sample draws its pair, in or out of the band, so a
                // change of band never reshuffles the others' numbers.
                const NormalPair xi = normalPair(rng);
                const double kx = dk * fx, kz = dk * fz;
                const double k = std::hypot(kx, kz);
                if (!cascade.holds(fz, fx))
                    continue;
                const size_t i = size_t(row) * kSize + size_t(col);
                h0[i] = 0.5 * std::complex<double>(xi.a, xi.b) * std::sqrt(sea.wavenumberDensity(kx, kz)) * dk;
                f.omega_radps[size_t(c)][i] = angularFrequency(k, sea.depth_m());
            }
        f.h0[size_t(c)].resize(h0.size());
        f.h0MinusConj[size_t(c)].resize(h0.size());
        for (int row = 0; row < kSize; ++row)
            for (int col = 0; col < kSize; ++col) {
                const size_t i = size_t(row) * kSize + size_t(col);
                const size_t mirrored = size_t(sampleIndex(-frequencyOf(row), -frequencyOf(col)));
                f.h0[size_t(c)][i] = std::complex<float>(h0[i]);
                f.h0MinusConj[size_t(c)][i] = std::complex<float>(std::conj(h0[mirrored]));
                sumAbs += std::abs(h0[i]) + std::abs(h0[mirrored]);
            }
        double variance = 0.0, weighted_m = 0.0;
        for (int row = 0; row < kSize; ++row)
            for (int col = 0; col < kSize; ++col) {
                const double p = std::norm(h0[size_t(row) * kSize + size_t(col)]);
                if (p == 0.0)
                    continue;
                variance += p;
                weighted_m += p * cascade.patch_m / std::hypot(double(frequencyOf(row)), double(frequencyOf(col)));
            }
        patches_m[size_t(c)] = cascade.patch_m;
        meanWavelength_m[size_t(c)] = variance > 0.0 ? weighted_m / variance : cascade.shortestWavelength_m();
    }
    f.warps = makeWarps(patches_m, meanWavelength_m, seed, warpStrength);
    f.verticalReach_m = sumAbs;
    f.horizontalReach_m = choppiness * sumAbs;
    f.unresolvedSlopeVariance = unresolvedSlopeVariance(sea, f.cascades.back().shortestWavelength_m());
    return f;
}

void evolve(const SpectralField& field, int cascade, double time_s, Spectra& out)
{
    const size_t n = size_t(kSize) * kSize;
    // Sized once: every sample is written below (the modes outside the band
    // as zero), so a buffer kept from the time before is not cleared first.
    for (auto& p : out.packed)
        p.resize(n);
    const double dk = kTwoPi / field.cascades[size_t(cascade)].patch_m;
    const auto& h0 = field.h0[size_t(cascade)];
    const auto& h0mc = field.h0MinusConj[size_t(cascade)];
    const auto& omega = field.omega_radps[size_t(cascade)];
    const float lambda = float(field.choppiness);
    using C = std::complex<float>;
    const C i1(0.0f, 1.0f);
    for (int row = 0; row < kSize; ++row)
        for (int col = 0; col < kSize; ++col) {
            const size_t s = size_t(row) * kSize + size_t(col);
            if (omega[s] == 0.0) {
                for (auto& p : out.packed)
                    p[s] = {};
                continue;
            }
            const float phase = float(std::fmod(omega[s] * time_s, kTwoPi));
            const C e(std::cos(phase), std::sin(phase));
            const C h = h0[s] * std::conj(e) + h0mc[s] * e;
            const float kx = float(dk * frequencyOf(col)), kz = float(dk * frequencyOf(row));
            const float k = std::sqrt(kx * kx + kz * kz);
            const C dx = i1 * (lambda * kx / k) * h, dz = i1 * (lambda * kz / k) * h;
            const C dyx = i1 * kx * h, dyz = i1 * kz * h;
            const C dxx = -(lambda * kx * kx / k) * h, dzz = -(lambda * kz * kz / k) * h;
            const C dxz = -(lambda * kx * kz / k) * h;
            out.packed[0][s] = dx + i1 * h;
            out.packed[1][s] = dz + i1 * dxz;
            out.packed[2][s] = dyx + i1 * dyz;
            out.packed[3][s] = dxx + i1 * dzz;
        }
}

} // namespace swell::spectral
