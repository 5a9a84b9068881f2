// Fresnel's reflectance for the tests, written apart from the shaders'
// water_optics.glsl so the two can be held to each other.
#pragma once

#include "swell/constants.h"

#include <cmath>

namespace swell::test {

// Fresnel's reflectance of unpolarised light from air into water at the
// cosine of incidence cosI (Hecht, "Optics", 4th ed., eqs. 4.34 and 4.40).
inline double fresnelAirToWater(double cosI)
{
    const double n = swell::kWaterIor;
    const double sinT = std::sqrt(1.0 - cosI * cosI) / n;
    const double cosT = std::sqrt(1.0 - sinT * sinT);
    const double rs = (cosI - n * cosT) / (cosI + n * cosT);
    const double rp = (n * cosI - cosT) / (n * cosI + cosT);
    return 0.5 * (rs * rs + rp * rp);
}

} // namespace swell::test
