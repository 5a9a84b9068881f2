// Elfouhaily et al. 1997's unified spectrum (ocean/short_waves.h) against the
// paper's own numbers and Cox & Munk's measured slopes.
#include "ocean/short_waves.h"
#include "published_sea_laws.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace {

using swell::detail::ShortWaveSpectrum;

// Sec. 3.2: the slowest wave on clean water travels at c_m = 0.23 m/s, at
// k_m = 370 rad/m (1.7 cm).
TEST(ShortWaves, TheSlowestWaveIsTheGravityCapillaryMinimum)
{
    double slowest = 1e9, at = 0.0;
    for (double k = 50.0; k < 3000.0; k *= 1.001) {
        const double c = ShortWaveSpectrum::phaseSpeed_mps(k);
        if (c < slowest) {
            slowest = c;
            at = k;
        }
    }
    EXPECT_NEAR(slowest, 0.23, 0.0005);
    EXPECT_NEAR(at / 370.0, 1.0, 0.01);
    // Long waves are gravity waves: c = sqrt(g/k).
    EXPECT_NEAR(ShortWaveSpectrum::phaseSpeed_mps(0.1) / std::sqrt(9.80665 / 0.1), 1.0, 1e-6);
}

// Eq. 44: alpha_m = 0.01 at u* = c_m, growing as 1 + ln(u*/c_m) below it and
// 1 + 3 ln(u*/c_m) above; and Wu's (1982) drag law C10 = (0.8 + 0.065 U10)e-3
// gives u* = 0.381 m/s at 10 m/s.
TEST(ShortWaves, TheShortWavesGrowWithTheFrictionVelocity)
{
    EXPECT_NEAR(swell::detail::frictionVelocity_mps(10.0), std::sqrt(1.45e-3) * 10.0, 1e-12);
    for (const double u10 : {3.0, 5.0, 10.0, 20.0}) {
        const ShortWaveSpectrum s(u10, 0.84);
        const double ratio = s.frictionVelocity_mps() / 0.23;
        const double expected = 0.01 * (ratio <= 1.0 ? 1.0 + std::log(ratio) : 1.0 + 3.0 * std::log(ratio));
        EXPECT_NEAR(s.shortWaveAlpha(), expected, 1e-12) << u10;
        // Eq. 40 at k_m: B_h = alpha_m/2 (c_m/c = 1, F_m = 1 there).
        EXPECT_NEAR(s.shortWaveCurvature(ShortWaveSpectrum::minimumPhaseSpeedWavenumber_radpm()) / (0.5 * expected),
                    1.0, 1e-3)
            << u10;
    }
    EXPECT_LT(ShortWaveSpectrum(5.0, 0.84).shortWaveAlpha(), ShortWaveSpectrum(15.0, 0.84).shortWaveAlpha());
}

// The spectrum's purpose (sec. 6): its mean square slope, integrated over all
// wavenumbers, is Cox & Munk's clean-surface slope at every wind. Within 15%
// (the paper's Figure 8 shows it within Cox & Munk's scatter; measured here:
// +8% at 5 m/s, +9% at 10, +3% at 15, -6% at 20). JONSWAP's gravity range
// alone gives less than half of it at 15 m/s.
TEST(ShortWaves, TheWholeSpectrumHasCoxAndMunksSlopes)
{
    for (const double u10 : {5.0, 10.0, 15.0, 20.0}) {
        const ShortWaveSpectrum s(u10, 0.84);
        const double mss = s.slopeVariance(1.0e-3, 1.0e5);
        const double published = swell::test::coxMunkSlopeVariance(u10);
        std::printf("U10 %4.1f m/s: mean square slope %.4f, Cox & Munk %.4f (%+.0f%%)\n", u10, mss, published,
                    100.0 * (mss / published - 1.0));
        EXPECT_NEAR(mss / published, 1.0, 0.15) << u10 << " m/s";
    }
}

// Nothing between equal bounds, and more the further it reaches.
TEST(ShortWaves, SlopeVarianceIsAnIntegralOverTheBand)
{
    const ShortWaveSpectrum s(10.0, 0.84);
    EXPECT_EQ(s.slopeVariance(100.0, 100.0), 0.0);
    EXPECT_EQ(s.slopeVariance(200.0, 100.0), 0.0);
    EXPECT_NEAR(s.slopeVariance(10.0, 100.0) + s.slopeVariance(100.0, 1000.0), s.slopeVariance(10.0, 1000.0), 1e-6);
}

} // namespace
