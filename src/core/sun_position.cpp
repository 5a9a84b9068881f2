// The sun's position from the date, the time and the place
// (swell/scene/sun_position.h): Michalsky (1988), the Astronomical Almanac's
// low-precision formulas for the sun, step by step as the paper lists them.
#include "swell/scene/sun_position.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace swell {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// x reduced to 0 <= x < period.
double wrap(double x, double period)
{
    const double r = std::fmod(x, period);
    return r < 0.0 ? r + period : r;
}

} // namespace

SolarPosition solarPosition(double time_s, double latitude_deg, double longitude_deg, const RefractionAir& air)
{
    // Days since J2000.0 (2000-01-01 12:00 UT, Julian date 2451545.0); the
    // Unix epoch is Julian date 2440587.5. Michalsky's `time`.
    const double n = time_s / 86400.0 + 2440587.5 - 2451545.0;
    const double hour_h = wrap(time_s, 86400.0) / 3600.0; // UT hour of the day

    // Ecliptic coordinates (Michalsky 1988, sec. 2): the mean longitude L,
    // the mean anomaly g, the ecliptic longitude with the equation of the
    // centre, and the obliquity of the ecliptic, all in degrees.
    const double meanLongitude_deg = wrap(280.460 + 0.9856474 * n, 360.0);
    const double meanAnomaly = wrap(357.528 + 0.9856003 * n, 360.0) * kDegree;
    const double eclipticLongitude =
        wrap(meanLongitude_deg + 1.915 * std::sin(meanAnomaly) + 0.020 * std::sin(2.0 * meanAnomaly), 360.0) * kDegree;
    const double obliquity = (23.439 - 0.0000004 * n) * kDegree;

    // Celestial coordinates: right ascension (atan2 puts it in the
    // ecliptic longitude's quadrant, which the paper does by hand) and declination.
    const double rightAscension =
        wrap(std::atan2(std::cos(obliquity) * std::sin(eclipticLongitude), std::cos(eclipticLongitude)), 2.0 * std::numbers::pi);
    const double declination = std::asin(std::sin(obliquity) * std::sin(eclipticLongitude));

    // Local coordinates: Greenwich mean sidereal time (hours), the local
    // one, and the hour angle, -pi..pi.
    const double gmst_h = wrap(6.697375 + 0.0657098242 * n + hour_h, 24.0);
    const double lmst_h = wrap(gmst_h + longitude_deg / 15.0, 24.0);
    double hourAngle = lmst_h * 15.0 * kDegree - rightAscension;
    hourAngle = wrap(hourAngle + std::numbers::pi, 2.0 * std::numbers::pi) - std::numbers::pi;

    const double latitude = latitude_deg * kDegree;
    const double sinElevation = std::sin(declination) * std::sin(latitude)
        + std::cos(declination) * std::cos(latitude) * std::cos(hourAngle);
    const double elevation = std::asin(std::clamp(sinElevation, -1.0, 1.0));
    // Azimuth from north towards east. The paper's arcsine needs a
    // quadrant rule that fails in the southern hemisphere (Spencer 1989,
    // Solar Energy 42(4), 353); atan2 of the east and north components needs none.
    const double east = -std::cos(declination) * std::sin(hourAngle);
    const double north = std::sin(declination) * std::cos(latitude)
        - std::cos(declination) * std::sin(latitude) * std::cos(hourAngle);
    const double azimuth = wrap(std::atan2(east, north), 2.0 * std::numbers::pi);

    // Refraction (Michalsky 1988, from the Almanac), degrees of elevation:
    // P / (273 + T) (0.1594 + 0.0196 e + 0.00002 e^2) / (1 + 0.505 e + 0.0845 e^2),
    // and 0.56 degree below -0.56 (the horizon's value held).
    const double e_deg = elevation / kDegree;
    const double airFactor = air.pressure_hPa / (273.15 + air.temperature_C);
    const double refraction_deg = e_deg > -0.56
        ? airFactor * (0.1594 + 0.0196 * e_deg + 0.00002 * e_deg * e_deg) / (1.0 + 0.505 * e_deg + 0.0845 * e_deg * e_deg)
        : 0.56;

    SolarPosition p;
    p.declination_deg = declination / kDegree;
    p.rightAscension_deg = rightAscension / kDegree;
    p.hourAngle_deg = hourAngle / kDegree;
    p.trueElevation_deg = e_deg;
    p.elevation_deg = std::min(e_deg + refraction_deg, 90.0);
    p.azimuth_deg = azimuth / kDegree;
    return p;
}

glm::dvec3 sunDirectionOf(const SolarPosition& position)
{
    const double e = position.elevation_deg * kDegree, a = position.azimuth_deg * kDegree;
    // North -z, east +x: the heading formula of docs/SCENE.md.
    return {std::sin(a) * std::cos(e), std::sin(e), -std::cos(a) * std::cos(e)};
}

} // namespace swell
