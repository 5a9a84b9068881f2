#include "render/sky_system.h"

#include "render/resources.h"
#include "render/telemetry.h"
#include "swell/gpu/bindings.h"

namespace swell::detail {

const SkyLight& SkySystem::light(const Scene& scene)
{
    const std::pair<SkyBakeKey, bool> key{skyBakeKeyOf(scene), usesPhysicalSky(scene)};
    if (lightKey_ != key) {
        std::shared_ptr<const Atmosphere> next = key.second ? atmosphereFor(scene.sky.atmosphere) : nullptr;
        // The tables depend on the atmosphere alone, not on the sun: uploaded
        // again only for another one (bakeIfStale), given back while the sky
        // is not physical.
        if (next != atmosphere_)
            atmosphereTextures_ = {};
        if (!next)
            physicalBake_ = {};
        atmosphere_ = std::move(next);
        light_ = skyLightOf(scene, atmosphere_.get());
        lightKey_ = key;
    }
    return light_;
}

void SkySystem::bakeIfStale(const Scene& scene, const FrameUniforms& base, Resources& resources, Telemetry& telemetry)
{
    if (!scene.sky.cubemapFaces.empty() || bakedSky_ == skyBakeKeyOf(scene))
        return;
    {
        const CpuPartScope part(telemetry.cpu, telemetry.counters.simulationCpu.views_ms);
        resources.bindFrame(PassMain, base);
    }
    glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    World& world = resources.world;
    if (usesPhysicalSky(scene)) {
        if (!physicalBake_)
            physicalBake_ = SkyBakeProgram(resources.sources, true);
        light(scene); // the atmosphere for this scene
        if (!atmosphereTextures_.transmittance)
            atmosphereTextures_.upload(*atmosphere_);
        atmosphereTextures_.bind();
        physicalBake_.setAtmosphere(scene.sky.exposure, scene.sky.atmosphere);
        physicalBake_.setClouds(scene.sky.clouds);
        bakeProceduralSky(physicalBake_, world.skyCube, resources.emptyVao.id());
        glBindTextureUnit(SWELL_UNIT_SKY_TRANSMITTANCE, 0);
        glBindTextureUnit(SWELL_UNIT_SKY_MULTISCATTER, 0);
    } else {
        bakeProceduralSky(resources.programs.skyBake, world.skyCube, resources.emptyVao.id());
    }
    telemetry.counters.drawCalls += kSkyFaces;
    bakedSky_ = skyBakeKeyOf(scene);
}

void SkySystem::updateCloudShadows(const Scene& scene, const FrameUniforms& base, glm::dvec3 origin,
                                   Resources& resources, Telemetry& telemetry)
{
    if (!resources.programs.flags.water.underwater.cloudShadows) {
        // No layer now: the map and its bake program are given back, as the
        // physical sky's are (a scene may drop its clouds for good).
        if (cloudShadow_.texture() != 0) {
            cloudShadow_ = {};
            cloudShadowBake_ = {};
        }
        return;
    }
    if (!cloudShadowBake_)
        cloudShadowBake_ = CloudShadowBakeProgram(resources.sources);
    {
        const ObservedPass pass(telemetry, "cloud shadows");
        if (cloudShadow_.update(cloudShadowBake_, resources.emptyVao.id(), scene.sky.clouds, base.sunDirection, origin,
                                float(light(scene).sunCloudTransmittance))) {
            ++telemetry.counters.drawCalls;
            ++telemetry.counters.viewsGpu.mipmaps;
        }
    }
    cloudShadow_.bind();
}

void SkySystem::forgetPrograms()
{
    bakedSky_.reset(); // the bake shader may have changed
    physicalBake_ = {};
    cloudShadowBake_ = {};
    cloudShadow_.forget();
}

} // namespace swell::detail
