// Shafts of light in the water column: the C++ twin of
// shaders/light_shafts.glsl's closed form, the sun's light a level surface
// lets in, scattered once towards an eye under the water. Tests check the
// shader's march against it (tests/gl/test_light_shafts.cpp) and it against
// a numerical integral (tests/cpu/test_light_shafts.cpp).
#pragma once

#include "swell/constants.h"

#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace swell::detail {

// Henyey and Greenstein 1941 ("Diffuse radiation in the Galaxy",
// Astrophysical Journal 93, 70): the share of scattered light per
// steradian at cosTheta from its first direction, 1/sr, normalised over the
// sphere, its mean cosine g.
inline double henyeyGreenstein(double cosTheta, double g = kWaterPhaseG)
{
    const double denom = 1.0 + g * g - 2.0 * g * cosTheta;
    return (1.0 - g * g) / (4.0 * std::numbers::pi * denom * std::sqrt(denom));
}

// The sun's ray under a level surface (Snell's law), pointing down; sun:
// towards the sun, unit, above the horizon.
inline glm::dvec3 levelRefractedRay(glm::dvec3 sun)
{
    const double sinI = std::sqrt(std::max(1.0 - sun.y * sun.y, 0.0));
    const double sinT = sinI / kWaterIor;
    const double cosT = std::sqrt(1.0 - sinT * sinT);
    const glm::dvec3 horizontal(-sun.x, 0.0, -sun.z);
    const double h = glm::length(horizontal);
    return h > 1e-12 ? glm::dvec3(horizontal.x / h * sinT, -cosT, horizontal.z / h * sinT) : glm::dvec3(0.0, -1.0, 0.0);
}

// The radiance the water scatters towards the eye along a view ray under a
// level surface (flat water): the sun's beam scattered once, the
// single-scattering approximation (Mobley 1994, "Light and Water"):
//
//   L = b P(theta) E sun.y T / cosT  int_0^s exp(-a z(t) / cosT) exp(-a t) dt
//
// with the ray starting z0 = -start.y below the surface and going along d
// (unit, from the eye), so z(t) = z0 - t d.y; the sun's beam refracted to
// the angle T from the vertical (cosT) and let in at Fresnel's share
// `levelTransmittance`, its irradiance normal to itself E sun.y T / cosT,
// absorbed along its slant path z / cosT; b kWaterScattering_per_m,
// P Henyey-Greenstein at the angle between the beam and the ray back to
// the eye; a the water's absorption per channel, both on the beam and on
// the way to the eye. The integral, exp(-a z0 / cosT) (1 - exp(-k s)) / k
// with k = a (1 - d.y / cosT), is s where k = 0. An upward ray ends at the
// surface. sunIrradiance: the sun's colour times its intensity (E).
inline glm::dvec3 levelShaftsRadiance(glm::dvec3 sun, glm::dvec3 sunIrradiance, glm::dvec3 absorption_per_m,
                                      double levelTransmittance, glm::dvec3 start, glm::dvec3 d, double path_m)
{
    if (sun.y <= 0.0)
        return glm::dvec3(0.0);
    const double z0 = std::max(-start.y, 0.0);
    if (d.y > 1e-6)
        path_m = std::min(path_m, z0 / d.y);
    const glm::dvec3 ray = levelRefractedRay(sun);
    const double cosT = -ray.y;
    const glm::dvec3 k = absorption_per_m * (1.0 - d.y / cosT);
    glm::dvec3 integral(0.0);
    for (int c = 0; c < 3; ++c)
        integral[c] = std::abs(k[c] * path_m) < 1e-6 ? path_m : -std::expm1(-k[c] * path_m) / k[c];
    const glm::dvec3 beam = sunIrradiance * (sun.y * levelTransmittance / cosT) * glm::exp(-absorption_per_m * z0 / cosT);
    return beam * kWaterScattering_per_m * henyeyGreenstein(glm::dot(ray, -d)) * integral;
}

} // namespace swell::detail
