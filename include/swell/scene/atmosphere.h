// The physical sky: the Earth's atmosphere as Bruneton & Neyret (2008) and
// Bruneton (2017) describe it (Rayleigh scattering by air, Mie scattering
// and absorption by aerosols, absorption by ozone), lit by the sun. Single
// scattering is ray-marched; light scattered more than once comes from
// Hillaire's (2020, sec. 5.5) multiple-scattering table, with the part of
// the air's Rayleigh phase function that his isotropic estimate drops.
//
// Everything here is in double precision and depends only on its arguments:
// the renderer bakes the same model from shaders/atmosphere.glsl (float, on
// the GPU) with the two tables built here, and tests/golden/test_sky_physical.cpp
// checks that the baked sky agrees with skyRadiance(). Radiances are per unit
// of the sun's irradiance at the top of the atmosphere (1/sr), for the three
// wavelengths drawn as red, green and blue (680, 550, 440 nm); the renderer
// multiplies them by the scene's sky.exposure.
#pragma once

#include "swell/export.h"
#include "swell/gpu/sky.h"

#include <glm/vec3.hpp>

#include <array>
#include <functional>
#include <vector>

namespace swell {

// What a scene can change in the atmosphere (the rest are the constants of
// swell/constants.h and swell/gpu/sky.h).
struct SWELL_API AtmosphereSettings {
    double mieScale = 1.0;      // aerosol density over Bruneton 2017's clear air, 0..20 (haze)
    double rayleighScale = 1.0; // air over Bruneton 2017's Earth's at every altitude, 0..10 (thinner or thicker air)
    double groundAlbedo = 0.06; // the surface below, Lambertian, 0..1 (the sea: about 0.06)
    bool operator==(const AtmosphereSettings&) const = default;
};

// What the atmosphere does to light at one point, 1/m per channel.
struct SWELL_API AtmosphereCoefficients {
    glm::dvec3 rayleighScattering{0.0};
    double mieScattering = 0.0;
    glm::dvec3 extinction{0.0}; // Rayleigh + Mie + ozone
};

// The coefficients at altitude_m above the ground.
SWELL_API AtmosphereCoefficients atmosphereAt(double altitude_m, const AtmosphereSettings& settings);

// The fraction of light that crosses the atmosphere from a point at radius
// r_m (from the Earth's centre) along a direction whose zenith angle's
// cosine is mu, to the top: exp(-optical depth) (Bruneton & Neyret 2008,
// sec. 2), integrated with `steps` trapezoids. 0 where the ray meets the ground.
SWELL_API glm::dvec3 transmittanceToTop(double r_m, double mu, const AtmosphereSettings& settings, int steps = 512);

// Phase functions, 1/sr, of the cosine between the light's and the view's
// directions: Rayleigh's (Bruneton & Neyret 2008, eq. 2) and the
// Cornette-Shanks form of Henyey-Greenstein for aerosols (Cornette & Shanks
// 1992, as in Bruneton & Neyret 2008, eq. 4).
SWELL_API double rayleighPhase(double cosAngle);
SWELL_API double miePhase(double cosAngle, double g);

// The two tables the sky is drawn with, built once per settings. Texel
// centres as OpenGL places them; both are sampled bilinearly, clamped at
// their edges, the same way here and in shaders/atmosphere.glsl.
class SWELL_API Atmosphere {
public:
    explicit Atmosphere(const AtmosphereSettings& settings);

    const AtmosphereSettings& settings() const { return settings_; }

    // Transmittance from radius r_m along mu to the top, from the table
    // (0 where the ray meets the ground).
    glm::dvec3 transmittance(double r_m, double mu) const;
    // Hillaire 2020's Psi_ms at radius r_m for the sun at zenith cosine muSun:
    // the radiance scattered twice or more, per unit of scattering coefficient.
    glm::dvec3 multipleScattering(double r_m, double muSun) const;
    // What the air's Rayleigh phase function adds to that, per unit of its
    // scattering coefficient, for light scattered towards a view whose zenith
    // cosine is muView and whose angle to the sun has cosine cosAngle: the
    // table's order-2 harmonics at the view (atmosphere.cpp,
    // buildMultipleScattering).
    glm::dvec3 rayleighMultipleScatteringOrder2(double r_m, double muSun, double muView, double cosAngle) const;

    // The sky's radiance seen from SWELL_ATMOSPHERE_OBSERVER_ALTITUDE_M along
    // a unit direction (y up) with the sun towards a unit sunDirection, 1/sr
    // per unit solar irradiance, without the sun's disc. Below the horizon
    // (the sea there) it is the horizon's radiance in the same azimuth,
    // which is what a water surface's reflections look up. `steps`: the ray
    // march's (the GPU's are SWELL_SKY_MARCH_STEPS; more for tests).
    glm::dvec3 skyRadiance(glm::dvec3 direction, glm::dvec3 sunDirection, int steps = SWELL_SKY_MARCH_STEPS) const;

    // The sun's light at the observer: the transmittance towards it (0 below
    // the horizon), per unit solar irradiance; exact, not from the table.
    glm::dvec3 sunTransmittance(glm::dvec3 sunDirection) const;

    // Irradiance on a surface of every orientation, from the sky above the
    // horizon and from the ground below it (Lambertian, groundAlbedo, lit by
    // the sun and the sky), as the nine coefficients of its order-2
    // spherical harmonics expansion (Ramamoorthi & Hanrahan 2001): the
    // irradiance on a surface facing n is sum_i coefficients[i] * Y_i(n),
    // with Y_i in shHarmonics()'s order. Per unit solar irradiance.
    std::array<glm::dvec3, 9> irradianceSh(glm::dvec3 sunDirection) const;
    // The same with something in the sky (a cloud layer, swell/scene/clouds.h):
    // radianceOf(direction, clear) is the radiance seen along a direction
    // above the horizon where the clear sky's is `clear`, and sunScale the
    // share of the sun's direct light that reaches the ground.
    std::array<glm::dvec3, 9> irradianceSh(glm::dvec3 sunDirection,
                                           const std::function<glm::dvec3(glm::dvec3, glm::dvec3)>& radianceOf,
                                           double sunScale) const;

    // Row-major RGB floats as uploaded: the transmittance table
    // (SWELL_TRANSMITTANCE_MU_SIZE x SWELL_TRANSMITTANCE_R_SIZE) and the
    // multiple-scattering one (SWELL_MULTISCATTER_LAYERS layers of
    // SWELL_MULTISCATTER_SIZE square, one after the other).
    const std::vector<float>& transmittanceTable() const { return transmittanceTable_; }
    const std::vector<float>& multipleScatteringTable() const { return multiScatteringTable_; }

private:
    AtmosphereSettings settings_;
    std::vector<float> transmittanceTable_;
    std::vector<float> multiScatteringTable_;
    void buildMultipleScattering();
};

// The nine real spherical harmonics Y_00, Y_1-1, Y_10, Y_11, Y_2-2, Y_2-1,
// Y_20, Y_21, Y_22 at a unit direction, in Ramamoorthi & Hanrahan's (2001,
// sec. 2) Cartesian form with y (up here) as the axis they call z.
SWELL_API std::array<double, 9> shHarmonics(glm::dvec3 n);

// The irradiance the expansion gives on a surface facing unit n.
SWELL_API glm::dvec3 evaluateSh(const std::array<glm::dvec3, 9>& coefficients, glm::dvec3 n);

} // namespace swell
