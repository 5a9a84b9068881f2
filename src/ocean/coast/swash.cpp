// The swash's reach on a beach (swash.h).
#include "ocean/coast/swash.h"

#include "swell/constants.h"

#include <algorithm>
#include <cmath>

namespace swell::coast {

double setup_m(double offshoreHeight_m, double offshoreWavelength_m, double slope)
{
    return 1.1 * 0.35 * slope * std::sqrt(offshoreHeight_m * offshoreWavelength_m);
}

double runUp2_m(double offshoreHeight_m, double offshoreWavelength_m, double slope)
{
    const double heightTimesLength_m2 = offshoreHeight_m * offshoreWavelength_m;
    const double swash_m = std::sqrt(heightTimesLength_m2 * (0.563 * slope * slope + 0.004));
    return setup_m(offshoreHeight_m, offshoreWavelength_m, slope) + 1.1 * 0.5 * swash_m;
}

namespace {

// The sea's peak period, s: the swell's, or the wind sea's fully developed
// peak, omega_p = 0.877 g / U (Pierson & Moskowitz 1964, whose U is at
// 19.5 m: taken here at 10 m), or the longest listed wave's; 0 for none.
double peakPeriod_s(const Scene& scene)
{
    if (const auto& wind = scene.sea.wind) {
        if (wind->swell)
            return wind->swell->period_s;
        return kTwoPi * wind->windSpeed_mps / (0.877 * kGravity);
    }
    double longest_m = 0.0;
    for (const Wave& w : scene.waves.listed)
        longest_m = std::max(longest_m, w.wavelength_m);
    return longest_m > 0.0 ? std::sqrt(kTwoPi * longest_m / kGravity) : 0.0;
}

} // namespace

double offshoreHeightTimesWavelength_m2(const Scene& scene, double heightDeviation_m)
{
    const double period_s = peakPeriod_s(scene);
    const double wavelength_m = kGravity * period_s * period_s / kTwoPi;
    return 4.0 * std::max(heightDeviation_m, 0.0) * wavelength_m;
}

} // namespace swell::coast
