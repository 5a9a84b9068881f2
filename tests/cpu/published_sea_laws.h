// Published measurements of the sea that tests check the physics against.
#pragma once

#include <cmath>

namespace swell::test {

// The wind z metres up from the 10 m wind: the power law U ~ z^0.11 over the
// sea (Hsu, Meindl & Gilhousen 1994, J. Appl. Meteor. 33, eq. 4).
inline double windAt(double z_m, double windSpeed10_mps) { return windSpeed10_mps * std::pow(z_m / 10.0, 0.11); }

// Cox & Munk (1954, J. Opt. Soc. Am. 44, eq. 4, clean surface): the mean
// square slope of the sea is 0.003 + 5.12e-3*U12.5 (+-0.004), U12.5 in m/s.
inline double coxMunkSlopeVariance(double windSpeed10_mps) { return 0.003 + 5.12e-3 * windAt(12.5, windSpeed10_mps); }

} // namespace swell::test
