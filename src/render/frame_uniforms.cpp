#include "render/frame_uniforms.h"
#include "swell/gpu/sky.h"
#include "swell/gpu/limits.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace swell::detail {

FrameUniforms frameUniforms(const Scene& scene, const SkyLight& sky, const GridShape& gridShape,
                            const GridPlacement& grid, glm::dvec3 eye_m, const glm::dmat4& viewProj, glm::dvec3 origin,
                            glm::ivec2 size)
{
    FrameUniforms f{};
    f.cameraViewProj = glm::mat4(viewProj);
    f.cameraInvViewProj = glm::mat4(glm::inverse(viewProj));
    f.passViewProj = f.cameraViewProj;
    f.passInvViewProj = f.cameraInvViewProj;
    f.clipPlane = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    f.eyePosition = glm::vec3(eye_m - origin);
    f.sunDirection = glm::vec3(glm::normalize(scene.sun.direction));
    // With the cloud layer's shadow map the layer is left out of the sun's
    // light here: the map shades it at each point (cloud_shadow_map.h).
    const bool shadowMap = cloudShadowsOn(scene);
    f.sunIntensity = float(shadowMap ? sky.clearSunIntensity : sky.sunIntensity);
    f.sunColor = glm::vec3(shadowMap ? sky.clearSunColor : sky.sunColor);
    // The sky's fog layer: the height at which a ray at the fog's end distance has
    // risen by 2% of it, so the sky stays clear a few degrees above the horizon.
    f.fogSkyLayer_m = float(0.02 * scene.fog.end_m);
    f.fogColor = glm::vec3(scene.fog.color);
    f.fogStart_m = float(scene.fog.start_m);
    f.fogEnd_m = float(scene.fog.end_m);
    if (scene.fog.model == FogModel::Atmosphere) {
        f.fogFromSky = 1;
        // The air's extinction where the eye is (Rayleigh, aerosols and
        // ozone; swell/scene/atmosphere.h), constant along a near-level ray.
        if (usesPhysicalSky(scene))
            f.fogExtinction_per_m =
                glm::vec3(atmosphereAt(SWELL_ATMOSPHERE_OBSERVER_ALTITUDE_M, scene.sky.atmosphere).extinction);
    }
    f.skyZenith = glm::vec3(sky.zenith);
    f.skyHorizon = glm::vec3(sky.horizon);
    for (size_t i = 0; i < sky.ambientSh.size(); ++i)
        f.ambientSh[i] = glm::vec4(glm::vec3(sky.ambientSh[i]), 0.0f);
    f.waterDeep = glm::vec3(scene.water.deepColor);
    f.waterAbsorption = glm::vec3(scene.water.absorption_per_m);
    f.fresnelF0 = float(scene.water.fresnelF0);
    f.shininess = float(scene.water.shininess);
    f.specularStrength = float(scene.water.specularStrength);
    f.refractionDistortion = float(scene.water.refractionDistortion);
    f.gridCenter = glm::vec2(grid.center_m - glm::dvec2(origin.x, origin.z));
    f.gridRadius_m = float(gridShape.radius_m);
    f.gridCells = float(gridShape.cells);
    f.gridSkirt_m = float(gridShape.skirt_m);
    f.gridFinestStep_m = float(grid.finestStep_m);
    const HorizonFade fade = horizonFadeFor(scene.grid, gridShape);
    f.gridFadeStart_m = float(fade.start_m);
    f.gridFadeEnd_m = float(fade.end_m);
    f.gridInnerScale_m = float(grid.rings.innerScale_m);
    f.gridGrowth = float(grid.rings.growth);
    f.gridCoarseGrowth = float(grid.coarseRings.growth);
    for (int l = 0; l < SWELL_GRID_LEVELS; ++l)
        f.gridLevels[l] = {glm::vec2(grid.snapOffsets[size_t(l)]), glm::vec2(grid.coarseSnapOffsets[size_t(l)]),
                           float(grid.rings.levelFirstRing[size_t(l)]), float(grid.coarseRings.levelFirstRing[size_t(l)])};
    f.gridMorph = float(grid.morph);
    f.gridCoarseCenterShift = glm::vec2(grid.coarseCenterShift_m);
    f.reflectionFixedDistance_m = float(scene.reflection.fixedDistance_m);
    setViewport(f, size);
    f.footprintScale = 1.0f; // the temporal resolve's frames set their own (view_passes.cpp)
    return f;
}

void setViewport(FrameUniforms& f, glm::ivec2 size)
{
    f.viewportSize = glm::vec2(size);
    f.viewportInvSize = 1.0f / glm::vec2(size);
}

} // namespace swell::detail
