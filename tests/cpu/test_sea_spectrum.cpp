// Directional spreading, the swell and the directional wave-number spectrum:
// spreading integrates to 1 and has the published widths, the wave-number
// spectrum carries the same variance as the frequency spectrum (its
// Jacobian), the swell has its height, period and direction, and generated
// directions follow the spreading.
#include "swell/gpu/limits.h"
#include "support/numbers.h"
#include "swell/scene/spectrum.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace {

using swell::Spreading;
using swell::SpreadingModel;
using swell::WindSettings;

using swell::kPi;
using swell::test::kInf;

// The integral of f(theta) over [a, b], Simpson with n (even) intervals.
template <class F>
double integrate(F f, double a, double b, int n = 20000)
{
    const double h = (b - a) / n;
    double sum = f(a) + f(b);
    for (int i = 1; i < n; ++i)
        sum += (i % 2 == 1 ? 4.0 : 2.0) * f(a + i * h);
    return sum * h / 3.0;
}

Spreading windSpreading(SpreadingModel model, double windOverPeakSpeed, double cut_rad = kPi)
{
    Spreading s;
    s.model = model;
    s.peakFrequency_radps = 1.0;
    s.windOverPeakSpeed = windOverPeakSpeed;
    s.cut_rad = cut_rad;
    return s;
}

TEST(SeaSpectrum, SpreadingIntegratesToOne)
{
    std::vector<Spreading> all;
    for (double age : {0.83, 1.5, 3.0}) {
        all.push_back(windSpreading(SpreadingModel::Mitsuyasu, age));
        all.push_back(windSpreading(SpreadingModel::DonelanBanner, age));
        all.push_back(windSpreading(SpreadingModel::Mitsuyasu, age, 30.0 * kPi / 180.0));
        all.push_back(windSpreading(SpreadingModel::DonelanBanner, age, 90.0 * kPi / 180.0));
    }
    Spreading swellSpread;
    swellSpread.swellPeakExponent = 75.0;
    all.push_back(swellSpread);
    swellSpread.swellPeakExponent = 200.0;
    all.push_back(swellSpread);
    for (const Spreading& s : all) {
        for (double ratio : {0.3, 0.6, 0.9, 1.0, 1.2, 1.7, 3.0, 6.0}) {
            auto d = [&](double theta) { return swell::spreadingDensity(s, ratio, theta); };
            // Over the cut only: Simpson's rule would blur the step at its edge.
            const double cut = std::min(s.cut_rad, kPi);
            EXPECT_NEAR(integrate(d, -cut, cut, 4000), 1.0, 1e-4) // the quadrature's own error, at the cusp of a small s
                << static_cast<int>(s.model) << " " << s.windOverPeakSpeed << " " << s.cut_rad << " " << ratio;
            if (s.cut_rad < kPi) {
                EXPECT_EQ(d(s.cut_rad + 1e-3), 0.0);
                EXPECT_EQ(d(-s.cut_rad - 1e-3), 0.0);
            }
            EXPECT_NEAR(d(0.7), d(-0.7), 1e-15); // symmetric about the mean direction
            EXPECT_NEAR(d(0.3), d(0.3 + 2.0 * kPi), 1e-12); // periodic
        }
    }
}

TEST(SeaSpectrum, Cos2sSpreadingHasThePublishedWidth)
{
    // For D ~ cos^2s(theta/2) the first circular moment is s/(s+1), so the
    // circular spread sqrt(2*(1 - m1)) is sqrt(2/(s+1)) (Kuik, van Vledder &
    // Holthuijsen 1988, J. Phys. Oceanogr. 18).
    const Spreading s = windSpreading(SpreadingModel::Mitsuyasu, 1.0);
    for (double ratio : {0.7, 1.0, 2.0}) {
        const double exponent = swell::spreadingExponent(s, ratio);
        const double m1 = integrate([&](double t) { return std::cos(t) * swell::spreadingDensity(s, ratio, t); }, -kPi, kPi);
        EXPECT_NEAR(m1, exponent / (exponent + 1.0), 1e-6) << ratio;
    }
}

TEST(SeaSpectrum, SpreadingExponentsFollowThePublishedFits)
{
    // Hasselmann et al. 1980: s = 6.97*(f/f_m)^4.06 below 1.05*f_m,
    // 9.77*(f/f_m)^(-2.33 - 1.45*(U/c_m - 1.17)) above.
    const Spreading s = windSpreading(SpreadingModel::Mitsuyasu, 1.17);
    EXPECT_NEAR(swell::spreadingExponent(s, 1.0), 6.97, 1e-12);
    EXPECT_NEAR(swell::spreadingExponent(s, 0.5), 6.97 * std::pow(0.5, 4.06), 1e-12);
    EXPECT_NEAR(swell::spreadingExponent(s, 2.0), 9.77 * std::pow(2.0, -2.33), 1e-12);
    const Spreading young = windSpreading(SpreadingModel::Mitsuyasu, 3.0);
    EXPECT_NEAR(swell::spreadingExponent(young, 2.0), 9.77 * std::pow(2.0, -2.33 - 1.45 * (3.0 - 1.17)), 1e-12);
    // Donelan et al. 1985: beta = 2.61*r^1.3 (0.56 < r < 0.95), 2.28*r^-1.3
    // (0.95 <= r < 1.6), 1.24 below; Banner 1990 above 1.6, meeting there.
    EXPECT_NEAR(swell::donelanBannerBeta(0.8), 2.61 * std::pow(0.8, 1.3), 1e-12);
    EXPECT_NEAR(swell::donelanBannerBeta(1.0), 2.28, 1e-12);
    EXPECT_EQ(swell::donelanBannerBeta(0.4), 1.24);
    EXPECT_NEAR(swell::donelanBannerBeta(1.6) / (2.28 * std::pow(1.6, -1.3)), 1.0, 0.01);
    EXPECT_NEAR(swell::donelanBannerBeta(3.0), std::pow(10.0, -0.4 + 0.8393 * std::exp(-0.567 * std::log(9.0))), 1e-12);
    // Mitsuyasu et al. 1975 for a swell: s_max at the peak, ^5 below, ^-2.5 above.
    Spreading sw;
    sw.swellPeakExponent = 75.0;
    EXPECT_NEAR(swell::spreadingExponent(sw, 1.0), 75.0, 1e-12);
    EXPECT_NEAR(swell::spreadingExponent(sw, 0.8), 75.0 * std::pow(0.8, 5.0), 1e-12);
    EXPECT_NEAR(swell::spreadingExponent(sw, 2.0), 75.0 * std::pow(2.0, -2.5), 1e-12);
}

// The variance of the sea from the wave-number spectrum: Psi over a polar
// grid in (k, theta), k*dk*dtheta = dkx*dkz, log-spaced in k.
double wavenumberVariance(const swell::SeaSpectrum& sea, double kLow, double kHigh)
{
    const int nk = 800, nt = 360;
    const double logStep = std::log(kHigh / kLow) / nk;
    const double dTheta = 2.0 * kPi / nt;
    double sum = 0.0;
    for (int i = 0; i < nk; ++i) {
        const double k = kLow * std::exp(logStep * (i + 0.5));
        const double dk = k * logStep;
        for (int j = 0; j < nt; ++j) {
            const double theta = -kPi + dTheta * (j + 0.5);
            sum += sea.wavenumberDensity(k * std::cos(theta), k * std::sin(theta)) * k * dk * dTheta;
        }
    }
    return sum;
}

TEST(SeaSpectrum, WavenumberSpectrumCarriesTheVariance)
{
    // The Jacobian d(omega)/dk / k makes the k-plane integral equal the
    // frequency integral, in deep water and in 15 m (where d(omega)/dk is not
    // half the phase speed) and with a swell, whose direction is not the wind's.
    for (double depth : {kInf, 15.0}) {
        WindSettings wind;
        wind.windSpeed_mps = 10.0;
        wind.fetch_km = 200.0;
        wind.windDirection_deg = 30.0;
        wind.spread_deg = 180.0;
        wind.depth_m = depth;
        wind.swell = swell::SwellSettings{};
        wind.swell->direction_deg = 200.0;
        const swell::SeaSpectrum sea(wind);
        double frequencyVariance = 0.0;
        for (const swell::SeaComponent& c : sea.components()) {
            const double wp = c.spectrum.peakFrequency_radps;
            frequencyVariance += integrate([&](double w) { return swell::spectralDensity(c.spectrum, w); }, 0.2 * wp, 20.0 * wp, 200000);
        }
        const double kLow = swell::wavenumberOf(0.2 * sea.components()[1].spectrum.peakFrequency_radps, depth);
        const double kHigh = swell::wavenumberOf(20.0 * sea.components()[0].spectrum.peakFrequency_radps, depth);
        EXPECT_NEAR(wavenumberVariance(sea, kLow, kHigh) / frequencyVariance, 1.0, 0.01) << depth;
    }
}

TEST(SeaSpectrum, WavenumberSpectrumPointsDownwind)
{
    WindSettings wind;
    wind.windSpeed_mps = 12.0;
    wind.windDirection_deg = 90.0; // towards +z
    wind.spread_deg = 180.0;
    const swell::SeaSpectrum sea(wind);
    const double kp = swell::wavenumberOf(sea.components()[0].spectrum.peakFrequency_radps, kInf);
    EXPECT_GT(sea.wavenumberDensity(0.0, kp), 10.0 * sea.wavenumberDensity(kp, 0.0));
    EXPECT_GT(sea.wavenumberDensity(kp, 0.0), sea.wavenumberDensity(0.0, -kp));
    EXPECT_EQ(sea.wavenumberDensity(0.0, 0.0), 0.0);
}

TEST(SeaSpectrum, SwellHasItsHeightPeriodAndDirection)
{
    swell::SwellSettings s;
    s.height_m = 2.0;
    s.period_s = 14.0;
    const swell::SpectrumParameters p = swell::swellParameters(s, kInf);
    const double wp = 2.0 * kPi / 14.0;
    EXPECT_NEAR(p.peakFrequency_radps, wp, 1e-12);
    const double m0 = integrate([&](double w) { return swell::spectralDensity(p, w); }, 0.2 * wp, 40.0 * wp, 200000);
    EXPECT_NEAR(4.0 * std::sqrt(m0) / 2.0, 1.0, 0.01);

    // In the generated set: the wind sea's waves come first and are unchanged
    // (but for the steepness, scaled over the whole set); the swell's follow,
    // travelling around its direction, and the energies add.
    WindSettings wind;
    wind.windSpeed_mps = 7.0;
    wind.windDirection_deg = 0.0;
    wind.waveCount = 24;
    const swell::WaveSet windOnly = swell::generateWaves(wind);
    wind.swell = s;
    wind.swell->direction_deg = 90.0;
    wind.swell->waveCount = 12;
    const swell::WaveSet both = swell::generateWaves(wind);
    ASSERT_EQ(both.waves.size(), 36u);
    for (std::size_t i = 0; i < 24; ++i) {
        EXPECT_EQ(both.waves[i].amplitude_m, windOnly.waves[i].amplitude_m);
        EXPECT_EQ(both.waves[i].phase_rad, windOnly.waves[i].phase_rad);
    }
    double swellVariance = 0.0;
    for (std::size_t i = 24; i < 36; ++i) {
        const swell::Wave& w = both.waves[i];
        EXPECT_GT(glm::dot(glm::normalize(w.direction), glm::dvec2(0.0, 1.0)), std::cos(40.0 * kPi / 180.0));
        swellVariance += 0.5 * w.amplitude_m * w.amplitude_m;
    }
    EXPECT_NEAR(4.0 * std::sqrt(swellVariance) / 2.0, 1.0, 0.05);
    const double hsWind = swell::significantWaveHeight(windOnly);
    EXPECT_NEAR(swell::significantWaveHeight(both), std::sqrt(hsWind * hsWind + 4.0), 0.05 * 2.0);
}

TEST(SeaSpectrum, SwellSharesTheWaveBudget)
{
    WindSettings wind;
    wind.waveCount = SWELL_MAX_WAVES;
    wind.swell = swell::SwellSettings{};
    wind.swell->waveCount = 10;
    const swell::WaveSet set = swell::generateWaves(wind);
    EXPECT_EQ(set.waves.size(), static_cast<std::size_t>(SWELL_MAX_WAVES));
    EXPECT_EQ(swell::validate(set), "");
}

TEST(SeaSpectrum, GeneratedDirectionsFollowTheSpreading)
{
    // Over many seeds, the mean cosine of each wave's angle to the wind
    // matches the first moment of D at that wave's frequency (triangular or
    // uniform draws would not), and the angles stay inside the cut.
    for (SpreadingModel model : {SpreadingModel::Mitsuyasu, SpreadingModel::DonelanBanner}) {
        for (double spread : {180.0, 40.0}) {
            WindSettings wind;
            wind.windSpeed_mps = 10.0;
            wind.fetch_km = 50.0;
            wind.spreading = model;
            wind.spread_deg = spread;
            wind.waveCount = 64;
            const swell::SeaSpectrum sea(wind);
            // The expected moment from the uncut density over the cut, renormalised.
            Spreading s = sea.components()[0].spreading;
            const double cut = s.cut_rad;
            s.cut_rad = kPi;
            double sampled = 0.0, expected = 0.0;
            int n = 0;
            for (std::uint32_t seed = 1; seed <= 20; ++seed) {
                wind.seed = seed;
                for (const swell::Wave& w : swell::generateWaves(wind).waves) {
                    const double angle = std::atan2(w.direction.y, w.direction.x);
                    EXPECT_LE(std::abs(angle), spread * kPi / 180.0 + 1e-9);
                    const double omega = swell::angularFrequency(2.0 * kPi / w.wavelength_m, kInf);
                    sampled += std::cos(angle);
                    expected += integrate([&](double t) { return std::cos(t) * swell::spreadingDensity(s, omega, t); },
                                          -cut, cut, 400)
                              / integrate([&](double t) { return swell::spreadingDensity(s, omega, t); }, -cut, cut, 400);
                    ++n;
                }
            }
            // 1280 draws: the standard error of the mean cosine is below 0.02.
            EXPECT_NEAR(sampled / n, expected / n, 0.04) << static_cast<int>(model) << " " << spread;
        }
    }
}

} // namespace
