// One view's setup, shared by all its passes: the render origin at the
// eye's x, z (so precision does not depend on where the eye is), the
// surface phased at the snapped grid centre around the LOD viewpoint, the
// frame uniforms every pass starts from, the objects' poses relative to the
// origin and the water tiles in view; and the maps the passes read, made
// or updated for the view (the baked sky, the cloud shadows, the caustics).
// Library-internal.
#pragma once

#include "render/gpu/blocks.h"
#include "render/resources.h"
#include "render/simulation.h"
#include "render/sky_system.h"
#include "render/telemetry.h"
#include "render/view_setup.h"
#include "swell/scene/scene.h"
#include "swell/view.h"

#include <glm/mat4x4.hpp>

#include <vector>

namespace swell::detail {

class SprayRenderer;

// What a view's passes draw with: the renderer's parts (Renderer::Impl's),
// by reference.
struct RenderContext {
    const Scene& scene;
    Resources& resources;
    SkySystem& sky;
    Simulation& simulation;
    Telemetry& telemetry;
    SprayRenderer& spray;
    // The island's largest error a pass may show, in its pixels (swell/debug.h).
    double islandTolerance_px;
};

// What every pass of one view shares.
struct ViewFrame {
    FrameUniforms base{};
    glm::dvec3 origin{0.0};   // the render origin, sea frame: the eye's x, z at the mean level
    glm::dvec3 eye{0.0};      // sea frame
    glm::dvec2 gridCenter_m{0.0}; // the water grid's centre (sea frame x, z), which the wave model is phased at
    glm::dmat4 viewProj{1.0}; // positions relative to the render origin to clip space
    DepthConvention depth;
    std::vector<glm::mat4> poses; // each object's transform relative to the origin
    glm::mat4 island{1.0f};
    glm::mat4 seabed{1.0f};   // the seabed's mesh relative to the render origin
    glm::ivec2 size{0};       // every pass's size, pixels
};

// The setup of `view` drawn at `size` pixels. hostGeometry: a host's
// geometry joins the passes (its extent unknown: every reflected ray is
// marched).
ViewFrame prepareView(RenderContext& context, const View& view, glm::ivec2 size, bool hostGeometry);

// The maps the view's passes read, before the first of them: the
// procedural sky baked when stale, the cloud layer's shadows, and the
// caustics map (drawn when the scene has caustics, the sun is up and
// either Swell's own world is drawn and reaches under the water within the
// map, or the shafts of light may be seen). ownWorld: Swell's world is drawn.
void prepareViewMaps(RenderContext& context, const ViewFrame& v, bool ownWorld);

} // namespace swell::detail
