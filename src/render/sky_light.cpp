#include "render/sky_light.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <mutex>
#include <numbers>

namespace swell::detail {

std::shared_ptr<const Atmosphere> atmosphereFor(const AtmosphereSettings& settings)
{
    // The last one built: scenes rarely change their atmosphere, and tests
    // and presets share the defaults.
    static std::mutex mutex;
    static std::shared_ptr<const Atmosphere> last;
    const std::lock_guard<std::mutex> lock(mutex);
    if (!last || last->settings() != settings)
        last = std::make_shared<const Atmosphere>(settings);
    return last;
}

SkyLight skyLightOf(const Scene& scene, const Atmosphere* atmosphere)
{
    SkyLight light;
    if (!usesPhysicalSky(scene) || atmosphere == nullptr) {
        light.sunColor = scene.sun.color;
        light.sunIntensity = scene.sun.intensity;
        light.clearSunColor = light.sunColor;
        light.clearSunIntensity = light.sunIntensity;
        light.zenith = scene.sky.zenithColor;
        light.horizon = scene.sky.horizonColor;
        // The gradient's ambient, 0.45 mix(horizon, zenith, n.y / 2 + 1/2),
        // is linear in n.y: Y_00 and Y_10 (0.282095 and 0.488603 n.y) hold it exactly.
        const glm::dvec3 mean = 0.45 * 0.5 * (scene.sky.horizonColor + scene.sky.zenithColor);
        const glm::dvec3 slope = 0.45 * 0.5 * (scene.sky.zenithColor - scene.sky.horizonColor);
        light.ambientSh[0] = mean / 0.282095;
        light.ambientSh[2] = slope / 0.488603;
        return light;
    }
    const double exposure = scene.sky.exposure;
    const glm::dvec3 sun = glm::normalize(scene.sun.direction);
    // A Lambertian surface of albedo a under irradiance E has radiance
    // a E / pi; the sky's pixels show exposure times radiance, so its
    // surfaces show exposure a E / pi: the sun's E is its transmittance
    // times the cosine (mesh.frag's phongDiffuse), the sky's the expansion.
    // The cloud layer shades the sun's direct light by its transmittance
    // along the sun from the observer (swell/scene/clouds.h): the sea and the
    // objects lie in the shadow the sky shows over them.
    const CloudSettings& clouds = scene.sky.clouds;
    const double cloudSun = cloudTransmittance(clouds, glm::vec3(sun));
    const glm::dvec3 sunLight = exposure / std::numbers::pi * cloudSun * atmosphere->sunTransmittance(sun);
    light.sunIntensity = std::max({sunLight.x, sunLight.y, sunLight.z});
    light.sunColor = light.sunIntensity > 0.0 ? sunLight / light.sunIntensity : glm::dvec3(0.0);
    // ...and without the layer, for the frame that shades the sun by the
    // layer's shadow at each point instead (cloud_shadow_map.h).
    const glm::dvec3 clearSun = exposure / std::numbers::pi * atmosphere->sunTransmittance(sun);
    light.sunCloudTransmittance = cloudSun;
    light.clearSunIntensity = std::max({clearSun.x, clearSun.y, clearSun.z});
    light.clearSunColor = light.clearSunIntensity > 0.0 ? clearSun / light.clearSunIntensity : glm::dvec3(0.0);
    // The sky the clouds leave (their light and what they hide), wherever
    // the frame looks at the sky's radiance.
    auto seen = [&](glm::dvec3 d, glm::dvec3 clear) { return cloudySkyRadiance(*atmosphere, clouds, d, sun, clear); };
    const glm::dvec3 up(0.0, 1.0, 0.0);
    light.zenith = exposure * seen(up, atmosphere->skyRadiance(up, sun));
    // The horizon a quarter turn from the sun: between its glow and the shadow's side.
    const glm::dvec3 side = glm::length(glm::dvec2(sun.x, sun.z)) > 1.0e-6 ? glm::dvec3(-sun.z, 0.0, sun.x) : glm::dvec3(1.0, 0.0, 0.0);
    light.horizon = exposure * seen(glm::normalize(side), atmosphere->skyRadiance(glm::normalize(side), sun));
    const std::array<glm::dvec3, 9> irradiance =
        clouds.cover > 0.0 ? atmosphere->irradianceSh(sun, seen, cloudSun) : atmosphere->irradianceSh(sun);
    for (size_t i = 0; i < 9; ++i)
        light.ambientSh[i] = exposure / std::numbers::pi * irradiance[i];
    return light;
}

} // namespace swell::detail
