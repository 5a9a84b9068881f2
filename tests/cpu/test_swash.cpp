// The swash's reach (src/ocean/coast/swash.h) against Stockdon et al.
// (2006, Coastal Eng. 53(7), 573-588): their run-up R2 is built from the
// setup (eq. 10), the incident band's swash (eq. 11) and the infragravity
// band's (eq. 12); and on dissipative beaches (Iribarren number under 0.3)
// their fit R2 = 0.043 sqrt(H0 L0) (eq. 18) stands for it.
#include "ocean/coast/swash.h"

#include "swell/constants.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

double deepWavelength_m(double period_s) { return swell::kGravity * period_s * period_s / swell::kTwoPi; }

TEST(Swash, RunUpIsTheSetupAndHalfTheSwashOfBothBands)
{
    for (double slope : {0.01, 0.025, 0.06, 0.1})
        for (double height : {0.5, 1.8, 4.0}) {
            const double length = deepWavelength_m(11.0), root = std::sqrt(height * length);
            const double setup = 0.35 * slope * root;                 // eq. 10
            const double incident = 0.75 * slope * root;              // eq. 11
            const double infragravity = 0.06 * root;                  // eq. 12
            const double published = 1.1 * (setup + 0.5 * std::hypot(incident, infragravity));
            // Eq. 19 writes 0.75^2 as 0.563 and 0.06^2 (0.0036) as 0.004:
            // up to 5.4% more where the infragravity band rules (low slopes).
            EXPECT_NEAR(swell::coast::runUp2_m(height, length, slope), published, 0.06 * published)
                << "slope " << slope << ", H0 " << height;
            EXPECT_NEAR(swell::coast::setup_m(height, length, slope), 1.1 * setup, 1e-12);
        }
}

TEST(Swash, OnADissipativeBeachRunUpFollowsTheFit)
{
    // H0 = 2 m, T = 12 s on a 1:200 slope: Iribarren's number
    // slope / sqrt(H0 / L0) = 0.05, dissipative.
    const double height = 2.0, length = deepWavelength_m(12.0), slope = 0.005;
    ASSERT_LT(slope / std::sqrt(height / length), 0.3);
    const double fit = 0.043 * std::sqrt(height * length);
    // Eq. 18 is its own fit to the dissipative data, not eq. 19's limit:
    // the two differ by up to a fifth there.
    EXPECT_NEAR(swell::coast::runUp2_m(height, length, slope), fit, 0.2 * fit);
}

TEST(Swash, TheCoastPresetsSwellRunsUpAboutEightyFiveCentimetres)
{
    // 1.8 m at 11 s on 1:40: sqrt(H0 L0) = 18.4 m, the setup 0.18 m, R2 0.85 m.
    EXPECT_NEAR(swell::coast::runUp2_m(1.8, deepWavelength_m(11.0), 0.025), 0.846, 0.005);
}

} // namespace
