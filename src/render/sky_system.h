// The sky as the rest of the frame sees it: the light it gives (the sun's
// colour, the ambient light; render/sky_light.h), the procedural sky baked
// into the world's cubemap when the sun or the sky changed, the physical
// sky's atmosphere tables, and the cloud layer's shadow map. Built when a
// scene first asks for each, given back when it no longer does.
// Library-internal.
#pragma once

#include "render/cloud_shadow_map.h"
#include "render/frame_uniforms.h"
#include "render/programs.h"
#include "render/sky_cubemap.h"
#include "render/sky_light.h"
#include "swell/scene/atmosphere.h"
#include "swell/scene/scene.h"

#include <memory>
#include <optional>
#include <utility>

namespace swell::detail {

class Resources;
class Telemetry;

class SkySystem {
public:
    // The sky's light for the scene, found again when the sun or sky changed.
    const SkyLight& light(const Scene& scene);

    // Bakes the procedural sky into the world's cubemap when it is not
    // baked for the scene's sun and sky yet (a scene of six images has
    // nothing to bake). `base`: the view's frame uniforms, which the bake reads.
    void bakeIfStale(const Scene& scene, const FrameUniforms& base, Resources& resources, Telemetry& telemetry);

    // The cloud layer's shadow map, baked again only when the clouds, the
    // sun or the render origin's neighbourhood changed, and bound; given
    // back with its program when the scene has no layer now.
    void updateCloudShadows(const Scene& scene, const FrameUniforms& base, glm::dvec3 origin, Resources& resources,
                            Telemetry& telemetry);

    // The world's cubemap was replaced: bake again when next drawn.
    void forgetBake() { bakedSky_.reset(); }
    // The shaders were reloaded: the bake and shadow programs are built
    // again from the new sources when next needed.
    void forgetPrograms();

private:
    // The sun and sky the cubemap was baked for; empty when it must be (re)baked.
    std::optional<SkyBakeKey> bakedSky_;
    // The physical sky's atmosphere (null for the gradient), the light the
    // frame uniforms take from the sky and what it was found for, and the
    // atmosphere's tables on the GPU while the sky is physical.
    std::shared_ptr<const Atmosphere> atmosphere_;
    SkyLight light_;
    std::optional<std::pair<SkyBakeKey, bool>> lightKey_;
    AtmosphereTextures atmosphereTextures_;
    // The physical sky's bake program: built when a scene first asks for it
    // (its ray march is the costliest shader here to compile) and kept
    // across scene changes, whose flags it does not read; empty until then,
    // after a shader reload and while the sky is not physical.
    SkyBakeProgram physicalBake_;
    // The cloud layer's shadows on what the sun lights (cloud_shadow_map.h)
    // and their bake's program: built when a scene first has clouds, kept
    // across scene changes (it reads no flags).
    CloudShadowMap cloudShadow_;
    CloudShadowBakeProgram cloudShadowBake_;
};

} // namespace swell::detail
