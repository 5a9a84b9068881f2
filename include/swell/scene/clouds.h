// The cloud layer: a thin deck of cloud at an altitude over the sea, baked
// into the physical sky's cubemap with the atmosphere (so the sky, the
// water's reflections and the ambient light all show it, at no cost per
// frame), and shading the sun's direct light by its transmittance.
//
// Its shape is a fractal sum of gradient noise (Perlin 2002) on lattices
// turned from each other, domain-warped (Quilez 2002), anchored in the
// world, thresholded at the quantile that makes the clouded share of the
// layer the scene's cover. Its light is a slab's: the single-scattering
// forward lobe of a Henyey-Greenstein phase function (Liou 2002, sec. 6.2)
// and the two-stream diffuse transmittance of a non-absorbing layer (Bohren
// 1987), seen through the air's transmittance (docs/RENDERING.md, "Clouds").
//
// The shape functions are in float, step for step as shaders/clouds.glsl
// computes them, so the CPU and the GPU agree (tests/gl/test_clouds.cpp);
// the light is in double.
#pragma once

#include "swell/export.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>

namespace swell {

class Atmosphere;

// What a scene says of its clouds ([sky.clouds]; physical sky only).
struct SWELL_API CloudSettings {
    double cover = 0.0;          // share of the layer that is cloud, 0..1 (0: no layer, the sky as without)
    double altitude_m = 1500.0;  // the layer's height over the sea, m, 100..12000
    double opticalDepth = 20.0;  // a cloud's mean vertical optical depth, 0..200 (a deck: 10..50)
    double scale_m = 3000.0;     // the coarsest cell of the layer's shapes, m, 200..50000
    bool operator==(const CloudSettings&) const = default;
};

// One octave of 2D gradient noise at p (lattice cells of 1) for octave
// `seed`: about -0.7..0.7, 0 at every lattice point.
SWELL_API float cloudGradientNoise(glm::vec2 p, std::uint32_t seed);

// The layer's fractal sum at p (in coarsest cells), its octaves finer than
// footprintCells averaged away; `unresolvedSigma` receives the standard
// deviation of what the footprint averages away (those octaves, and the
// kept ones' change across it; 0 for a footprint of 0).
SWELL_API float cloudFractalSum(glm::vec2 p, float footprintCells, float& unresolvedSigma);

// The layer at a point of it (x, z world metres), seen with a footprint of
// footprint_m: how much of the point is cloud (0..1; over 0.5 on a share
// `cover` of the layer) and its vertical optical depth (0 in the clear,
// about settings.opticalDepth in a cloud).
struct CloudSample {
    float mask = 0.0f;
    float opticalDepth = 0.0f;
};
SWELL_API CloudSample cloudSample(const CloudSettings& settings, glm::vec2 xz_m, float footprint_m);
SWELL_API float cloudOpticalDepth(const CloudSettings& settings, glm::vec2 xz_m, float footprint_m);

// Where a ray from the baked sky's observer (the world's origin, at
// SWELL_ATMOSPHERE_OBSERVER_ALTITUDE_M) along a unit direction meets the
// layer, on the spherical Earth: the distance, the point's x and z, the
// cosine of the ray with the vertical there and the footprint of one bake
// texel there. Directions below the horizon are taken at the horizon in
// the same azimuth (as Atmosphere::skyRadiance does).
struct CloudHit {
    float distance_m = 0.0f;
    glm::vec2 xz_m{0.0f};
    float cosZenith = 1.0f;
    float footprint_m = 0.0f;
};
SWELL_API CloudHit cloudHit(const CloudSettings& settings, glm::vec3 direction);

// The layer's direct transmittance along a unit direction from the
// observer, exp(-tau / cosZenith): what is left of the sun's beam (or of
// the sky behind) after the layer. 1 for cover 0.
SWELL_API float cloudTransmittance(const CloudSettings& settings, glm::vec3 direction);

// The layer's direct transmittance along the sun's ray from a world point
// (x, z world metres as cloudSample takes them; y metres over the sea's
// mean level), towards the sun (unit): the shadow the layer casts there.
// The ray crosses the layer's altitude at xz + sun.xz (altitude - y) /
// sun.y, on a flat layer (a shadow falls a few kilometres from its cloud,
// where the Earth's curve lowers the layer by a metre or so), and the
// beam's path through it is tau / sun.y, with tau filtered over
// footprint_m. The sun is taken no lower than
// SWELL_CLOUD_SHADOW_MIN_SUN_Y (below it the atmosphere has put the sun
// out anyway). 1 for cover 0 and for a point at or over the layer.
SWELL_API float cloudShadowTransmittance(const CloudSettings& settings, glm::vec3 point_m, glm::vec3 sun,
                                         float footprint_m);

// The sky's radiance along a unit direction with the layer in it, per unit
// solar irradiance (1/sr), from the clear sky's radiance in that direction
// (Atmosphere::skyRadiance): the cloud's light seen through the air in
// front of it, and the clear sky dimmed by what the cloud hides.
// `clear` is returned unchanged for cover 0.
SWELL_API glm::dvec3 cloudySkyRadiance(const Atmosphere& atmosphere, const CloudSettings& settings,
                                       glm::dvec3 direction, glm::dvec3 sunDirection, glm::dvec3 clear);

} // namespace swell
