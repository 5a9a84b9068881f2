// What the sky gives the rest of the frame: the sun's colour and intensity,
// the zenith and horizon colours a few water terms use, and world objects'
// ambient light (order-2 spherical harmonics of the irradiance around a
// normal). The gradient sky takes them from the scene as it always did; the
// physical sky from its atmosphere (swell/scene/atmosphere.h), once per change of
// sun or sky, not per frame.
#pragma once

#include "swell/scene/atmosphere.h"
#include "swell/scene/scene.h"

#include <array>
#include <memory>

namespace swell::detail {

struct SkyLight {
    glm::dvec3 sunColor{0.0}; // linear RGB, the frame's sunColor
    double sunIntensity = 0.0;
    glm::dvec3 zenith{0.0}, horizon{0.0}; // displayed linear RGB
    // mesh.frag's ambient light on a surface facing n: sum_i ambientSh[i] * Y_i(n)
    // (swell::shHarmonics), the light an albedo of 1 reflects, displayed.
    std::array<glm::dvec3, 9> ambientSh{};
    // The cloud layer's transmittance towards the sun from the sky's
    // observer (cloudTransmittance; 1 without clouds), which sunIntensity
    // holds, and the sun's light without it: where the layer's shadow map
    // shades the sun point by point (cloudShadowsOn), the frame takes the
    // latter and the map the layer.
    double sunCloudTransmittance = 1.0;
    glm::dvec3 clearSunColor{0.0};
    double clearSunIntensity = 0.0;
};

// The atmosphere for these settings: built once per process per settings
// (0.35 s measured on one core), shared by every renderer that asks for the same.
std::shared_ptr<const Atmosphere> atmosphereFor(const AtmosphereSettings& settings);

// The light of the scene's sky. `atmosphere` is used for the physical sky
// only (and must then be atmosphereFor(scene.sky.atmosphere)).
SkyLight skyLightOf(const Scene& scene, const Atmosphere* atmosphere);

// Whether the scene's sky is the physical one (a built-in sky, not faces).
inline bool usesPhysicalSky(const Scene& scene)
{
    return scene.sky.cubemapFaces.empty() && scene.sky.model == SkyModel::Physical;
}

// Whether the sun's light is shaded point by point by the cloud layer's
// shadow map (render/cloud_shadow_map.h): the physical sky with clouds.
inline bool cloudShadowsOn(const Scene& scene)
{
    return usesPhysicalSky(scene) && scene.sky.clouds.cover > 0.0;
}

} // namespace swell::detail
