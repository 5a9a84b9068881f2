// Wave sets from the wind: reproducible, valid and fold-free for any settings,
// and carrying the energy of the JONSWAP spectrum (significant wave height
// against the Pierson-Moskowitz value for a fully developed sea).
#include "swell/spectrum.h"

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
constexpr double kInf = std::numeric_limits<double>::infinity();

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

TEST(Spectrum, FullyDevelopedSeaMatchesPiersonMoskowitz)
{
    // Pierson-Moskowitz: Hs = 0.21*U^2/g, 2.14 m for 10 m/s.
    WindSettings wind;
    wind.windSpeed_mps = 10.0;
    wind.fetch_km = 10000.0;
    wind.waveCount = 32;
    const double hs = swell::significantWaveHeight(swell::generateWaves(wind));
    const double pm = 0.21 * 10.0 * 10.0 / swell::kGravity;
    EXPECT_GT(hs, pm / 1.5);
    EXPECT_LT(hs, pm * 1.5);
    // The peak sits at the Pierson-Moskowitz frequency 0.877*g/U.
    EXPECT_NEAR(swell::jonswapParameters(wind).peakFrequency_radps, 0.877 * swell::kGravity / 10.0, 1e-12);
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

TEST(Spectrum, FetchLimitedParametersFollowJonswap)
{
    // Hasselmann et al. 1973 with chi = g*F/U^2.
    WindSettings wind;
    wind.windSpeed_mps = 10.0;
    wind.fetch_km = 20.0;
    const double chi = swell::kGravity * 20000.0 / 100.0;
    const swell::SpectrumParameters p = swell::jonswapParameters(wind);
    EXPECT_NEAR(p.alpha, 0.076 * std::pow(chi, -0.22), 1e-15);
    EXPECT_NEAR(p.peakFrequency_radps, 22.0 * swell::kGravity / 10.0 * std::pow(chi, -1.0 / 3.0), 1e-12);
    EXPECT_EQ(p.gamma, 3.3);
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
    double meanCos = 0.0;
    for (const swell::Wave& w : set.waves) {
        const double c = glm::dot(glm::normalize(w.direction), windDir);
        EXPECT_GE(c, std::cos(30.0 * kPi / 180.0) - 1e-12);
        meanCos += c / 64.0;
    }
    EXPECT_GT(meanCos, std::cos(15.0 * kPi / 180.0)); // clustered towards the wind

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
