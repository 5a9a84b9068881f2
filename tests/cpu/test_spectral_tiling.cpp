// No visible tiling (issue 12, "Done when"): the normalised autocorrelation
// of the spectral ocean's heightfield at a shift of any cascade's patch size
// is at most 0.3, measured directly on the drawn surface (the CPU twin, which
// equals the GPU's vertices) at random points spread over a wide area. A
// single repeated patch gives 1.0; the anti-tiling warp
// (src/ocean/spectral/spectral_warp.h) is what brings it down.
#include "ocean/spectral/spectral_cpu.h"
#include "ocean/spectral/spectral_field.h"
#include "ocean/spectral/spectral_warp.h"
#include "swell/scene/spectrum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

namespace {

using namespace swell;
using namespace swell::spectral;

constexpr double kTilingFullyDeveloped_km = 10000.0; // past any fetch limit at 5..20 m/s

struct TilingSea {
    double windSpeed_mps, fetch_km;
};
// The seas the statistics tests use: fully developed at 5, 10, 15, 20 m/s,
// and fetches of 10 and 40 km at 5, 10, 20 m/s.
const TilingSea kTilingSeas[] = {{5, kTilingFullyDeveloped_km}, {10, kTilingFullyDeveloped_km}, {15, kTilingFullyDeveloped_km},
                          {20, kTilingFullyDeveloped_km}, {5, 10},  {5, 40},  {10, 10}, {10, 40}, {20, 10}, {20, 40}};

SeaSpectrum seaOf(const TilingSea& sc)
{
    WindSettings w;
    w.windSpeed_mps = sc.windSpeed_mps;
    w.fetch_km = sc.fetch_km;
    return SeaSpectrum(w);
}

// The field of a sea with the cascades before `firstCascade` emptied: what
// is left holds only waves shorter than that cascade's patch.
std::shared_ptr<const SpectralField> fieldFrom(const SpectralField& full, int firstCascade)
{
    auto f = std::make_shared<SpectralField>(full);
    for (int c = 0; c < firstCascade; ++c) {
        std::fill(f->h0[size_t(c)].begin(), f->h0[size_t(c)].end(), std::complex<float>(0.0f));
        std::fill(f->h0MinusConj[size_t(c)].begin(), f->h0MinusConj[size_t(c)].end(), std::complex<float>(0.0f));
    }
    return f;
}

// The points: uniform over a square 100 patches wide (about 26 wavelengths
// of the warp's longest sinusoid, so its phases are evenly sampled), so
// sparse (about one per 0.5 patches squared, several peak wavelengths apart
// for cascade 0) that their heights are nearly independent. For independent
// Gaussian heights the estimate's standard error is sqrt((1 + r^2)/N): with
// N = 20000, under 0.01, a fifth of the margin a 0.05 error would need. The
// test measures it too (the spread of the products over sqrt(N)).
constexpr int kPoints = 20000;
constexpr double kAreaInPatches = 100.0;

struct Correlation {
    double value = 0.0;         // sum h(x) h(x + shift) / sum h(x)^2
    double standardError = 0.0; // of that value, from the spread of the products
};

// `quantity` at a rest point: the height, or the local energy of the waves.
template <class Q>
Correlation correlationAt(Q quantity, glm::dvec2 shift_m, double patch_m, std::uint32_t seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> coordinate(-0.5 * kAreaInPatches * patch_m, 0.5 * kAreaInPatches * patch_m);
    std::vector<double> products(kPoints);
    double sumSquares = 0.0, mean = 0.0;
    std::vector<double> a(kPoints), b(kPoints);
    for (int i = 0; i < kPoints; ++i) {
        const glm::dvec2 x(coordinate(rng), coordinate(rng));
        a[size_t(i)] = quantity(x);
        b[size_t(i)] = quantity(x + shift_m);
        mean += a[size_t(i)];
    }
    mean /= kPoints;
    for (int i = 0; i < kPoints; ++i) {
        products[size_t(i)] = (a[size_t(i)] - mean) * (b[size_t(i)] - mean);
        sumSquares += (a[size_t(i)] - mean) * (a[size_t(i)] - mean);
    }
    double sum = 0.0, sumSq = 0.0;
    for (double p : products) {
        sum += p;
        sumSq += p * p;
    }
    const double meanProduct = sum / kPoints;
    const double spread = std::sqrt(std::max(sumSq / kPoints - meanProduct * meanProduct, 0.0));
    return {sum / sumSquares, spread / std::sqrt(double(kPoints)) / (sumSquares / kPoints)};
}

constexpr double kTime_s = 100.0;
constexpr double kThreshold = 0.3; // the criterion

// The four shifts by one patch: x, z, and both diagonals (all periods of the patch).
std::array<glm::dvec2, 4> shiftsOf(double patch_m)
{
    return {glm::dvec2(patch_m, 0.0), glm::dvec2(0.0, patch_m), glm::dvec2(patch_m, patch_m),
            glm::dvec2(patch_m, -patch_m)};
}

// The worst height autocorrelation at a shift of cascade c's patch, over
// the four shifts, measured on the cascades from c on (for c = 0, the
// whole heightfield). The cascades before c are left out: their waves are
// longer than the patch, and two points one patch apart are correlated by
// a wave much longer than the shift whether or not anything repeats (along
// a crest of a 100 m wave, 30 m apart, say). Leaving them out only removes
// waves that do not repeat at that shift, so it is the stricter measure.
struct TilingResult {
    double worst = -1.0, worstError = 0.0;
};
TilingResult worstHeightCorrelation(const SpectralField& full, int c, std::uint32_t seed)
{
    const CpuSurface surface(fieldFrom(full, c));
    const SurfaceFilter exact{};
    auto height = [&](glm::dvec2 x) { return surface.displacementAt(x, kTime_s, exact).y; };
    const double patch_m = full.cascades[size_t(c)].patch_m;
    TilingResult r;
    for (glm::dvec2 shift : shiftsOf(patch_m)) {
        const Correlation m = correlationAt(height, shift, patch_m, seed);
        if (m.value > r.worst)
            r = {m.value, m.standardError};
    }
    return r;
}

// The measure itself: without the warp, a cascade alone repeats exactly at
// its patch (1.0 up to float rounding) and correlates little at an
// irrational fraction of it.
TEST(SpectralTiling, MeasureGivesOneForARepeatedPatch)
{
    const SpectralField unwarped = makeSpectralField(seaOf({10, kTilingFullyDeveloped_km}), 0.0, 1, 0.0);
    auto onlyLargest = std::make_shared<SpectralField>(unwarped);
    for (int c = 1; c < kCascades; ++c) {
        std::fill(onlyLargest->h0[size_t(c)].begin(), onlyLargest->h0[size_t(c)].end(), std::complex<float>(0.0f));
        std::fill(onlyLargest->h0MinusConj[size_t(c)].begin(), onlyLargest->h0MinusConj[size_t(c)].end(),
                  std::complex<float>(0.0f));
    }
    const CpuSurface surface(onlyLargest);
    auto height = [&](glm::dvec2 x) { return surface.displacementAt(x, kTime_s, SurfaceFilter{}).y; };
    const double patch_m = unwarped.cascades[0].patch_m;
    for (glm::dvec2 shift : shiftsOf(patch_m))
        EXPECT_NEAR(correlationAt(height, shift, patch_m, 7).value, 1.0, 1e-4);
    EXPECT_LT(std::abs(correlationAt(height, {patch_m / std::sqrt(2.0), 0.0}, patch_m, 7).value), kThreshold);
}

// Without the warp the sum of the cascades repeats with the largest patch,
// which holds most of the variance: far above the criterion (about 0.9).
TEST(SpectralTiling, WithoutTheWarpTheLargestPatchRepeats)
{
    for (const TilingSea& sc : {kTilingSeas[1], kTilingSeas[3], kTilingSeas[4]}) {
        const SpectralField unwarped = makeSpectralField(seaOf(sc), 0.0, 1, 0.0);
        const TilingResult r = worstHeightCorrelation(unwarped, 0, 11);
        std::printf("U10 %4.1f m/s fetch %6.0f km, no warp: worst autocorrelation at L0 = %.1f m: %.3f (+-%.3f)\n",
                    sc.windSpeed_mps, sc.fetch_km, unwarped.cascades[0].patch_m, r.worst, r.worstError);
        EXPECT_GT(r.worst, 0.8) << sc.windSpeed_mps << " m/s, " << sc.fetch_km << " km";
    }
}

// The criterion, for every sea and every patch: at most 0.3 along x, z and
// both diagonals. The estimate's standard error is checked to be well under
// the margin, so a pass is not luck.
TEST(SpectralTiling, NoPatchRepeatsVisibly)
{
    for (const TilingSea& sc : kTilingSeas) {
        const SpectralField field = makeSpectralField(seaOf(sc), 0.0, 1);
        std::printf("U10 %4.1f m/s fetch %6.0f km: worst autocorrelation at each patch:", sc.windSpeed_mps, sc.fetch_km);
        for (int c = 0; c < kCascades; ++c) {
            const TilingResult r = worstHeightCorrelation(field, c, 100 + std::uint32_t(c));
            std::printf(" L%d %.4g m %.3f (+-%.3f);", c, field.cascades[size_t(c)].patch_m, r.worst, r.worstError);
            EXPECT_LE(r.worst, kThreshold) << sc.windSpeed_mps << " m/s, " << sc.fetch_km << " km, cascade " << c;
            EXPECT_LT(r.worstError, 0.02) << sc.windSpeed_mps << " m/s, " << sc.fetch_km << " km, cascade " << c;
        }
        std::printf("\n");
    }
}

// What the warp costs: the largest local strain (how much longer or
// shorter it makes a wave) over many points, per cascade, for every sea.
// Kept to a few percent, physically unremarkable next to the spread of
// wavelengths in the spectrum itself.
constexpr double kLargestStrain = 0.12;
TEST(SpectralTiling, WarpStrainStaysSmall)
{
    double worst = 0.0;
    for (const TilingSea& sc : kTilingSeas) {
        const SpectralField field = makeSpectralField(seaOf(sc), 0.0, 1);
        std::printf("U10 %4.1f m/s fetch %6.0f km: warp strain rms / largest:", sc.windSpeed_mps, sc.fetch_km);
        for (int c = 0; c < kCascades; ++c) {
            const double patch_m = field.cascades[size_t(c)].patch_m;
            std::mt19937 rng(3);
            std::uniform_real_distribution<double> coordinate(-50.0 * patch_m, 50.0 * patch_m);
            double largest = 0.0, sumSq = 0.0;
            for (int i = 0; i < kPoints; ++i) {
                const double s = strainAt(field.warps[size_t(c)], {coordinate(rng), coordinate(rng)});
                largest = std::max(largest, s);
                sumSq += s * s;
            }
            std::printf(" L%d %.3f / %.3f;", c, std::sqrt(sumSq / kPoints), largest);
            worst = std::max(worst, largest);
        }
        std::printf("\n");
    }
    EXPECT_LE(worst, kLargestStrain);
}

} // namespace
