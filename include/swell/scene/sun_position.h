// Where the sun stands in the sky at a place and an instant: the
// Astronomical Almanac's approximate solar position as Michalsky (1988)
// gives it ("The Astronomical Almanac's algorithm for approximate solar
// position (1950-2050)", Solar Energy 40(3), 227-235), accurate to about
// 0.01 degree from 1950 to 2050, with its refraction correction, and the
// direction that puts it in Swell's world.
//
// Swell's world axes as a map: north is -z, east is +x, up is +y, so an
// azimuth measured like a compass bearing (from north towards east) is
// measured like a heading (docs/SCENE.md: from -z towards +x).
#pragma once

#include "swell/export.h"

#include <glm/vec3.hpp>

namespace swell {

// The span Michalsky's algorithm is published for, as seconds since
// 1970-01-01T00:00:00Z: 1950-01-01T00:00:00Z and 2050-01-01T00:00:00Z.
inline constexpr double kSolarPositionFirst_s = -631152000.0;
inline constexpr double kSolarPositionLast_s = 2524608000.0;

// The air's state for the refraction correction: the Almanac's standard
// (1013.25 hPa and 15 degrees C, for which Michalsky 1988 writes the factor
// P / (273 + T) as 3.51561), or a site's.
struct SWELL_API RefractionAir {
    double pressure_hPa = 1013.25;
    double temperature_C = 15.0;
};

struct SWELL_API SolarPosition {
    double declination_deg = 0.0;     // geocentric, apparent
    double rightAscension_deg = 0.0;  // geocentric, apparent, 0..360
    double hourAngle_deg = 0.0;       // local, -180..180, + in the afternoon
    double trueElevation_deg = 0.0;   // above the horizon, without refraction
    double elevation_deg = 0.0;       // above the horizon, refraction included (what is seen)
    double azimuth_deg = 0.0;         // from north towards east, 0..360
};

// The sun's position at time_s (seconds since 1970-01-01T00:00:00Z, UTC
// taken as UT; the second or so between them moves the sun by 0.004
// degree), seen from latitude_deg (north +, -90..90) and longitude_deg
// (east +, -180..180).
SWELL_API SolarPosition solarPosition(double time_s, double latitude_deg, double longitude_deg,
                                      const RefractionAir& air = {});

// The unit vector towards the sun in Swell's world (north -z, east +x, y up)
// for the seen elevation and azimuth.
SWELL_API glm::dvec3 sunDirectionOf(const SolarPosition& position);

} // namespace swell
