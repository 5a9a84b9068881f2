// Frequency spectra and the wave sets drawn from them: reproducible, valid
// and fold-free for any settings, and carrying the energy of the published
// laws (Pierson-Moskowitz for a fully developed sea, the JONSWAP growth laws
// for a fetch-limited one) within 5%.
#include "swell/gpu/limits.h"
#include "support/numbers.h"
#include "swell/scene/spectrum.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace {

using swell::WindSettings;

using swell::kPi;
using swell::test::kInf;

bool bitIdentical(const swell::WaveSet& a, const swell::WaveSet& b)
{
    if (a.waves.size() != b.waves.size() || std::memcmp(&a.depth_m, &b.depth_m, sizeof(double)) != 0)
        return false;
    for (std::size_t i = 0; i < a.waves.size(); ++i) {
        const swell::Wave& x = a.waves[i];
        const swell::Wave& y = b.waves[i];
        const double xs[] = {x.direction.x, x.direction.y, x.wavelength_m, x.amplitude_m, x.steepness, x.phase_rad};
        const double ys[] = {y.direction.x, y.direction.y, y.wavelength_m, y.amplitude_m, y.steepness, y.phase_rad};
        if (std::memcmp(xs, ys, sizeof xs) != 0)
            return false;
    }
    return true;
}

// Integral of S over [a, b], fine trapezoids in log(omega).
double spectrumIntegral(const swell::SpectrumParameters& s, double a, double b)
{
    const int n = 200000;
    const double step = std::log(b / a) / n;
    double sum = 0.0;
    for (int i = 0; i <= n; ++i) {
        const double omega = a * std::exp(step * i);
        const double weight = (i == 0 || i == n) ? 0.5 : 1.0;
        sum += weight * swell::spectralDensity(s, omega) * omega; // d(omega) = omega d(log omega)
    }
    return sum * step;
}

TEST(Spectrum, SameSettingsGiveBitIdenticalWaves)
{
    WindSettings wind;
    wind.seed = 1234;
    wind.depth_m = 20.0;
    EXPECT_TRUE(bitIdentical(swell::generateWaves(wind), swell::generateWaves(wind)));
    WindSettings other = wind;
    other.seed = 1235;
    EXPECT_FALSE(bitIdentical(swell::generateWaves(wind), swell::generateWaves(other)));
}

TEST(Spectrum, RandomDrawsArePortable)
{
    // The phases depend only on std::mt19937 (fixed by the standard) and the
    // distribution written in spectrum.cpp, not on the standard library or
    // libm: these values must come out on every platform. (Checked against
    // an independent implementation of mt19937 and of the draw order.)
    WindSettings wind;
    wind.seed = 42;
    wind.waveCount = 3;
    const swell::WaveSet set = swell::generateWaves(wind);
    ASSERT_EQ(set.waves.size(), 3u);
    EXPECT_EQ(set.waves[0].phase_rad, 0.6198895383354297);
    EXPECT_EQ(set.waves[1].phase_rad, 2.3007525789727232);
    EXPECT_EQ(set.waves[2].phase_rad, 2.952530678803174);
}

TEST(Spectrum, ResultsAreValidAndFoldFreeForAnySettings)
{
    for (double speed : {0.5, 3.0, 10.0, 25.0, 40.0}) {
        for (int count : {1, 7, 32, 64}) {
            for (double steepness : {0.0, 0.5, 1.0}) {
                for (double depth : {kInf, 50.0, 2.0}) {
                    WindSettings wind;
                    wind.windSpeed_mps = speed;
                    wind.waveCount = count;
                    wind.steepness = steepness;
                    wind.depth_m = depth;
                    wind.minWavelength_m = 0.1;
                    const swell::WaveSet set = swell::generateWaves(wind);
                    EXPECT_EQ(swell::validate(set), "");
                    EXPECT_LE(swell::foldMeasure(set), 1.0);
                    EXPECT_EQ(set.waves.size(), static_cast<std::size_t>(count));
                    EXPECT_EQ(set.depth_m, depth);
                    for (const swell::Wave& w : set.waves) {
                        EXPECT_GE(w.wavelength_m, wind.minWavelength_m);
                        EXPECT_LE(w.steepness, steepness);
                    }
                }
            }
        }
    }
}

// Hs of the spectrum: 4*sqrt(m0), m0 integrated far past both tails.
double spectrumHeight(const swell::SpectrumParameters& p)
{
    return 4.0 * std::sqrt(spectrumIntegral(p, 0.05 * p.peakFrequency_radps, 50.0 * p.peakFrequency_radps));
}

// U19.5 as the issue states it (a power law with exponent ~0.11 over the sea).
double u195(double u10) { return 1.075 * u10; }

TEST(Spectrum, FullyDevelopedSeaMatchesPiersonMoskowitz)
{
    // Pierson & Moskowitz 1964: Hs = 0.21*U19.5^2/g and omega_p = 0.877*g/U19.5
    // (Stewart 2008, eqs. 16.30 and 16.33), within 5% both from the spectrum
    // and from the generated waves (32 waves down to 0.5 m, seeded).
    for (double speed : {5.0, 10.0, 15.0, 20.0}) {
        SCOPED_TRACE(speed);
        WindSettings wind;
        wind.windSpeed_mps = speed;
        wind.fetch_km = 10000.0;
        wind.waveCount = 32;
        wind.minWavelength_m = 0.5;
        const double pm = 0.21 * u195(speed) * u195(speed) / swell::kGravity;
        const swell::SpectrumParameters p = swell::jonswapParameters(wind);
        EXPECT_NEAR(spectrumHeight(p) / pm, 1.0, 0.05);
        EXPECT_NEAR(swell::significantWaveHeight(swell::generateWaves(wind)) / pm, 1.0, 0.05);
        EXPECT_NEAR(p.peakFrequency_radps / (0.877 * swell::kGravity / u195(speed)), 1.0, 0.005);
        EXPECT_EQ(p.gamma, 1.0);   // no peak enhancement once fully developed
        EXPECT_EQ(p.alpha, 0.0081); // the Phillips constant of Pierson & Moskowitz
    }
}

TEST(Spectrum, FullyDevelopedDensityIsPiersonMoskowitz)
{
    // The form Pierson & Moskowitz 1964 published, with beta = 0.74 on
    // omega_0 = g/U19.5 rather than 1.25 on omega_p.
    const double u10 = 12.0;
    WindSettings wind;
    wind.windSpeed_mps = u10;
    wind.fetch_km = 5000.0;
    const swell::SpectrumParameters p = swell::jonswapParameters(wind);
    const double g = swell::kGravity;
    for (double omega : {0.6, 0.8, 1.2, 2.0, 4.0}) {
        const double w0 = g / u195(u10);
        const double published = 8.1e-3 * g * g / std::pow(omega, 5.0) * std::exp(-0.74 * std::pow(w0 / omega, 4.0));
        EXPECT_NEAR(swell::spectralDensity(p, omega) / published, 1.0, 0.02) << omega;
    }
}

TEST(Spectrum, FetchLimitedSeaFollowsTheJonswapGrowthLaws)
{
    // Hasselmann et al. 1973, chi = g*F/U10^2: g*Hs/U10^2 = 1.6e-3*sqrt(chi)
    // and f_p = 3.5*(g/U10)*chi^-0.33. Within 5%, at two fetches for each
    // wind, from the spectrum and from the generated waves.
    const double g = swell::kGravity;
    for (double speed : {5.0, 10.0, 15.0, 20.0}) {
        for (double chi : {1000.0, 10000.0}) {
            SCOPED_TRACE(::testing::Message() << speed << " m/s, chi " << chi);
            WindSettings wind;
            wind.windSpeed_mps = speed;
            wind.fetch_km = chi * speed * speed / g / 1000.0;
            wind.waveCount = 32;
            wind.minWavelength_m = 0.5;
            const double law = 1.6e-3 * std::sqrt(chi) * speed * speed / g;
            const swell::SpectrumParameters p = swell::jonswapParameters(wind);
            EXPECT_NEAR(spectrumHeight(p) / law, 1.0, 0.05);
            EXPECT_NEAR(swell::significantWaveHeight(swell::generateWaves(wind)) / law, 1.0, 0.05);
            const double peak = 2.0 * kPi * 3.5 * g / speed * std::pow(chi, -0.33);
            EXPECT_NEAR(p.peakFrequency_radps / peak, 1.0, 0.05);
            EXPECT_GT(p.gamma, 1.0); // a growing sea has an enhanced peak
        }
    }
}

TEST(Spectrum, PeakEnhancementFollowsDnv)
{
    // DNV-RP-C205 (2010) sec. 3.5.5.5: 5 up to Tp/sqrt(Hs) = 3.6,
    // exp(5.75 - 1.15*Tp/sqrt(Hs)) up to 5, then 1.
    EXPECT_EQ(swell::dnvPeakEnhancement(6.0, 4.0), 5.0);                          // 3.0
    EXPECT_NEAR(swell::dnvPeakEnhancement(8.0, 4.0), std::exp(5.75 - 4.6), 1e-12); // 4.0: 3.158
    EXPECT_NEAR(swell::dnvPeakEnhancement(8.0, 4.0), 3.158, 1e-3);
    EXPECT_EQ(swell::dnvPeakEnhancement(12.0, 4.0), 1.0);                         // 6.0
    // A young sea (short fetch) is peakier than an older one.
    WindSettings young, older;
    young.windSpeed_mps = older.windSpeed_mps = 15.0;
    young.fetch_km = 5.0;
    older.fetch_km = 150.0;
    EXPECT_GT(swell::jonswapParameters(young).gamma, swell::jonswapParameters(older).gamma + 1.0);
}

TEST(Spectrum, AlphaNormalisationMatchesTheDnvApproximation)
{
    // DNV-RP-C205 (2010) sec. 3.5.5.4: a JONSWAP spectrum of given Hs and Tp
    // has alpha = 5/16*Hs^2*omega_p^4/g^2*(1 - 0.287*ln(gamma)), good to a few
    // percent for gamma up to 7; exact for gamma = 1.
    const double hs = 3.0, wp = 0.7, g = swell::kGravity;
    for (double gamma : {1.0, 2.0, 3.3, 5.0, 7.0}) {
        const double dnv = 5.0 / 16.0 * hs * hs * std::pow(wp, 4.0) / (g * g) * (1.0 - 0.287 * std::log(gamma));
        EXPECT_NEAR(swell::jonswapAlphaFor(hs, wp, gamma) / dnv, 1.0, gamma == 1.0 ? 1e-6 : 0.03) << gamma;
    }
}

TEST(Spectrum, TmaFactorHasTheKitaigorodskiiLimits)
{
    const double g = swell::kGravity;
    const double h = 10.0;
    auto at = [&](double omegaH) { return swell::tmaFactor(omegaH / std::sqrt(h / g), h); };
    // Very shallow: Phi -> omega_h^2/2 (Kitaigorodskii et al. 1975; Bouws et al. 1985).
    EXPECT_NEAR(at(0.05) / (0.5 * 0.05 * 0.05), 1.0, 0.01);
    // Deep: 1.
    EXPECT_NEAR(at(4.0), 1.0, 1e-6);
    EXPECT_EQ(swell::tmaFactor(1.0, kInf), 1.0);
    // Thompson & Vincent 1983's piecewise fit of it, within 5% between.
    for (double wh : {0.5, 1.0, 1.5, 1.9}) {
        const double fit = wh <= 1.0 ? 0.5 * wh * wh : 1.0 - 0.5 * (2.0 - wh) * (2.0 - wh);
        EXPECT_NEAR(at(wh) / fit, 1.0, 0.05) << wh;
    }
}

TEST(Spectrum, SignificantHeightScalesWithWindSquared)
{
    // Fully developed: Hs ~ U^2, so doubling the wind quadruples it (up to the
    // short-wave cut-off, which removes a little more of the calmer sea).
    WindSettings wind;
    wind.fetch_km = 10000.0;
    wind.minWavelength_m = 0.05;
    wind.windSpeed_mps = 8.0;
    const double calm = swell::significantWaveHeight(swell::generateWaves(wind));
    wind.windSpeed_mps = 16.0;
    const double rough = swell::significantWaveHeight(swell::generateWaves(wind));
    EXPECT_NEAR(rough / calm, 4.0, 0.1);
}

TEST(Spectrum, WavesGrowWithFetchUntilFullyDeveloped)
{
    WindSettings wind;
    wind.windSpeed_mps = 12.0;
    auto hsAt = [&](double fetch_km) {
        wind.fetch_km = fetch_km;
        return swell::significantWaveHeight(swell::generateWaves(wind));
    };
    EXPECT_LT(hsAt(5.0), hsAt(50.0));
    EXPECT_LT(hsAt(50.0), hsAt(500.0));
    EXPECT_EQ(hsAt(5000.0), hsAt(10000.0)); // beyond full development nothing changes
}

TEST(Spectrum, DensityPeaksAtThePeakFrequency)
{
    WindSettings wind;
    wind.windSpeed_mps = 14.0;
    wind.fetch_km = 100.0;
    const swell::SpectrumParameters p = swell::jonswapParameters(wind);
    double bestOmega = 0.0;
    double best = 0.0;
    for (double omega = 0.2 * p.peakFrequency_radps; omega < 5.0 * p.peakFrequency_radps; omega *= 1.0001) {
        const double s = swell::spectralDensity(p, omega);
        if (s > best) {
            best = s;
            bestOmega = omega;
        }
    }
    EXPECT_NEAR(bestOmega / p.peakFrequency_radps, 1.0, 0.01);
    EXPECT_EQ(swell::spectralDensity(p, 0.0), 0.0);
}

TEST(Spectrum, WavesCarryTheEnergyOfTheirBands)
{
    // sum(A^2/2) is the integral of S from 0.7*omega_p to the frequency of
    // the shortest wave: nothing lost or counted twice between bands.
    WindSettings wind;
    wind.windSpeed_mps = 9.0;
    wind.fetch_km = 80.0;
    wind.minWavelength_m = 0.3;
    wind.waveCount = 24;
    const swell::SpectrumParameters p = swell::jonswapParameters(wind);
    const double omegaHigh = swell::angularFrequency(2.0 * kPi / wind.minWavelength_m, kInf);
    const double m0 = spectrumIntegral(p, 0.7 * p.peakFrequency_radps, omegaHigh);
    const double hs = swell::significantWaveHeight(swell::generateWaves(wind));
    EXPECT_NEAR(hs / (4.0 * std::sqrt(m0)), 1.0, 1e-3);
}

TEST(Spectrum, ShallowWaterHasLessEnergy)
{
    WindSettings wind;
    wind.windSpeed_mps = 15.0;
    const double deep = swell::significantWaveHeight(swell::generateWaves(wind));
    wind.depth_m = 3.0;
    const swell::WaveSet shallow = swell::generateWaves(wind);
    EXPECT_LT(swell::significantWaveHeight(shallow), 0.5 * deep);
    // Their wavelengths follow the finite-depth dispersion relation: shorter
    // than in deep water at the same frequency, never below the minimum.
    for (const swell::Wave& w : shallow.waves)
        EXPECT_GE(w.wavelength_m, wind.minWavelength_m);
}

TEST(Spectrum, WavelengthsSpanFromThePeakToTheMinimum)
{
    WindSettings wind;
    wind.windSpeed_mps = 10.0;
    wind.minWavelength_m = 0.5;
    const swell::WaveSet set = swell::generateWaves(wind);
    const double omegaP = swell::jonswapParameters(wind).peakFrequency_radps;
    const double peakWavelength = 2.0 * kPi * swell::kGravity / (omegaP * omegaP);
    double longest = 0.0;
    double shortest = kInf;
    for (const swell::Wave& w : set.waves) {
        longest = std::max(longest, w.wavelength_m);
        shortest = std::min(shortest, w.wavelength_m);
    }
    EXPECT_GT(longest, peakWavelength);                // something at or beyond the peak
    EXPECT_LE(longest, peakWavelength / (0.7 * 0.7)); // nothing below 0.7*omega_p
    EXPECT_GE(shortest, 0.5);
    EXPECT_LT(shortest, 1.0); // the last band reaches down to the minimum
}

TEST(Spectrum, DirectionsStayWithinTheSpread)
{
    WindSettings wind;
    wind.windDirection_deg = 120.0;
    wind.spread_deg = 30.0;
    wind.waveCount = 64;
    const glm::dvec2 windDir(std::cos(120.0 * kPi / 180.0), std::sin(120.0 * kPi / 180.0));
    const swell::WaveSet set = swell::generateWaves(wind);
    for (const swell::Wave& w : set.waves)
        EXPECT_GE(glm::dot(glm::normalize(w.direction), windDir), std::cos(30.0 * kPi / 180.0) - 1e-12);

    wind.spread_deg = 0.0;
    for (const swell::Wave& w : swell::generateWaves(wind).waves)
        EXPECT_NEAR(glm::dot(glm::normalize(w.direction), windDir), 1.0, 1e-15);
}

TEST(Spectrum, SteepnessIsLimitedToTheFoldMeasure)
{
    WindSettings wind;
    wind.windSpeed_mps = 20.0;
    wind.waveCount = 64;
    wind.steepness = 1.0;
    const swell::WaveSet steep = swell::generateWaves(wind);
    EXPECT_LE(swell::foldMeasure(steep), 1.0);
    EXPECT_GT(swell::foldMeasure(steep), 0.999999); // 64 waves at Q = 1 would fold: scaled to the limit
    wind.steepness = 0.0;
    for (const swell::Wave& w : swell::generateWaves(wind).waves)
        EXPECT_EQ(w.steepness, 0.0);
}

TEST(Spectrum, OutOfRangeSettingsAreClamped)
{
    WindSettings wind;
    wind.waveCount = 0;
    EXPECT_EQ(swell::generateWaves(wind).waves.size(), 1u);
    wind.waveCount = 1000;
    EXPECT_EQ(swell::generateWaves(wind).waves.size(), static_cast<std::size_t>(SWELL_MAX_WAVES));

    WindSettings silly;
    silly.windSpeed_mps = -3.0;
    silly.fetch_km = 1e9;
    silly.spread_deg = 720.0;
    silly.minWavelength_m = -1.0;
    silly.steepness = 7.0;
    silly.depth_m = 1e-9;
    const swell::WaveSet set = swell::generateWaves(silly);
    EXPECT_EQ(swell::validate(set), "");
    EXPECT_LE(swell::foldMeasure(set), 1.0);
    EXPECT_EQ(set.depth_m, 0.1);
    for (const swell::Wave& w : set.waves)
        EXPECT_GE(w.wavelength_m, 0.05);

    // Clamped the same way as the fields they stand for.
    WindSettings clamped = silly;
    clamped.windSpeed_mps = 0.5;
    clamped.fetch_km = 10000.0;
    clamped.spread_deg = 180.0;
    clamped.minWavelength_m = 0.05;
    clamped.steepness = 1.0;
    clamped.depth_m = 0.1;
    EXPECT_TRUE(bitIdentical(set, swell::generateWaves(clamped)));
}

TEST(Spectrum, NonFiniteSettingsThrow)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    WindSettings wind;
    wind.windSpeed_mps = nan;
    try {
        swell::generateWaves(wind);
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "swell::generateWaves(): windSpeed_mps must be finite (got nan)");
    }
    wind = WindSettings{};
    wind.fetch_km = kInf;
    EXPECT_THROW(swell::generateWaves(wind), std::invalid_argument);
    wind = WindSettings{};
    wind.depth_m = 0.0;
    EXPECT_THROW(swell::generateWaves(wind), std::invalid_argument);
    wind.depth_m = nan;
    EXPECT_THROW(swell::generateWaves(wind), std::invalid_argument);
}

TEST(Spectrum, LongMinimumWavelengthGivesSmallWaves)
{
    // Asking only for waves far longer than the sea makes: the octave below
    // the minimum, where the spectrum has almost nothing.
    WindSettings wind;
    wind.windSpeed_mps = 3.0; // peak wavelength ~ 7.5 m
    wind.minWavelength_m = 200.0;
    const swell::WaveSet set = swell::generateWaves(wind);
    EXPECT_EQ(swell::validate(set), "");
    for (const swell::Wave& w : set.waves) {
        EXPECT_GE(w.wavelength_m, 200.0);
        EXPECT_LE(w.wavelength_m, 800.0 * 1.0001);
    }
    EXPECT_LT(swell::significantWaveHeight(set), 1e-3);
}

TEST(Spectrum, SignificantWaveHeightOfAKnownSet)
{
    swell::WaveSet set;
    set.waves = {{{1.0, 0.0}, 10.0, 1.0, 0.5, 0.0}, {{0.0, 1.0}, 10.0, 2.0, 0.5, 0.0}};
    EXPECT_DOUBLE_EQ(swell::significantWaveHeight(set), 4.0 * std::sqrt(2.5));
}

} // namespace
