// The sea state a scene asks for: the wind that raises a wind sea, and a
// distant swell on top of it. Plain data with units; swell/scene/spectrum.h turns
// them into spectra and Gerstner wave sets, swell/spectral_model.h into a
// spectral ocean, and Scene::sea holds the scene's (swell/scene/scene.h).
#pragma once

#include "swell/export.h"

#include <cstdint>
#include <limits>
#include <optional>

namespace swell {

// How the energy of the wind sea spreads over directions around the wind.
// Both narrow at the peak and widen above and below it.
enum class SpreadingModel {
    Mitsuyasu,     // cos^2s(theta/2) (Mitsuyasu et al. 1975), s(omega/omega_p, U10/c_p) of Hasselmann et al. 1980
    DonelanBanner, // sech^2(beta*theta) (Donelan et al. 1985), beta above 1.6*omega_p from Banner 1990
};

// A swell from a distant storm, added to the wind sea: a narrow JONSWAP
// spectrum of its own height and period, travelling its own way, spread
// narrowly in direction.
struct SWELL_API SwellSettings {
    double height_m = 1.0;       // significant wave height of the swell alone, m, 0..15
    double period_s = 12.0;      // peak period, s, 3..25
    double direction_deg = 0.0;  // direction the swell travels towards, degrees from +x towards +z
    double gamma = 7.0;          // JONSWAP peak enhancement, 1..10: high, a swell is narrower than any wind sea
    double sMax = 75.0;          // spreading exponent s at the peak, 1..200 (Goda 1985: 25 young swell, 75 from afar)
    int waveCount = 8;           // Gerstner waves for the swell, 1..SWELL_MAX_WAVES - 1
};

struct SWELL_API WindSettings {
    double windSpeed_mps = 8.0;       // wind speed 10 m above the sea (U10), m/s, 0.5..40
    double windDirection_deg = 0.0;   // direction the wind blows towards, degrees from +x towards +z
    double spread_deg = 35.0;         // widest angle from the wind a wave travels at, degrees, 0..180 (spreading cut there)
    double fetch_km = 300.0;          // distance over which the wind has blown, km, 1..10000
    int waveCount = 32;               // how many wind waves, 1..SWELL_MAX_WAVES
    double minWavelength_m = 0.5;     // shortest wave generated, m, > 0
    std::uint32_t seed = 1;           // random seed
    double steepness = 0.6;           // overall choppiness, 0..1 (scaled to stay fold-free)
    double depth_m = std::numeric_limits<double>::infinity(); // water depth, m (a scene's is Scene::sea.depth_m)
    SpreadingModel spreading = SpreadingModel::Mitsuyasu;
    std::optional<SwellSettings> swell; // a distant swell on top of the wind sea
};

} // namespace swell
