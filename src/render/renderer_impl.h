// The renderer's state (swell/renderer.h), taken apart along Filament's
// lines: the resources it draws with (render/resources.h), the sky
// (render/sky_system.h), the simulation (render/simulation.h), the state
// each view keeps (render/view_state.h), and the spray and label passes'
// own (render/spray_renderer.h, render/label_renderer.h). This file joins
// them; render/renderer.cpp has the public calls, render/scene_update.cpp
// what a scene change rebuilds, render/view_draw.cpp one view's list of
// passes (render/view_passes.h). Library-internal.
#pragma once

#include "render/label_renderer.h"
#include "render/motion_vectors.h"
#include "render/render_target.h"
#include "render/resources.h"
#include "render/simulation.h"
#include "render/sky_system.h"
#include "render/spray_renderer.h"
#include "render/telemetry.h"
#include "render/view_frame.h"
#include "render/view_passes.h"
#include "render/view_state.h"
#include "swell/renderer.h"
#include "swell/scene/scene_changes.h"

#include <memory>
#include <vector>

namespace swell {

// The library's own code: its internal types are used unqualified.
using namespace detail;

namespace detail {

// How render() draws Swell's own frame (Renderer::setRenderScale,
// setTemporalResolve), and the settings tests and the benchmark change
// (swell/debug.h).
struct RenderSettings {
    double renderScale = 1.0;
    bool temporal = false;
    bool temporalJitter = true;
    bool interactive = false; // see Renderer::setInteractive
    double islandTolerance_px = kIslandLodTolerance_px;
};

// What a scene change builds before anything changes (scene_update.cpp):
// each part null or empty where it stays as it is.
struct SceneUpdate {
    SimulationUpdate simulation;
    bool programsChanged = false;
    Programs programs; // those whose flags changed (buildChangedPrograms)
    std::optional<World> world;
    std::optional<SceneShapes> shapes; // with the world: what its rigid bodies are built from
    // The sea floor built again (with the world, or when only it changed), and its mesh.
    std::shared_ptr<const Seabed> seabed;
    SeabedMesh seabedMesh;
    bool gridChanged = false;
};

} // namespace detail

struct Renderer::Impl {
    Scene scene;
    Telemetry telemetry;
    Resources resources;
    SkySystem sky;
    Simulation simulation;
    SprayRenderer spray;
    LabelRenderer labels;
    MotionVectors motionVectors;
    ViewStates views;
    RenderSettings settings;
    // The host's terrain (Renderer::setSeabedHeights), joined to the scene's seabed.
    std::optional<SeabedHeights> hostSeabed;
    // renderImage()'s offscreen frame.
    RenderTarget output;

    Impl(RendererOptions options, unsigned omittedWaterTerms)
        : resources(std::move(options.shaders), omittedWaterTerms)
    {
    }

    // The floor `next` describes, joined by the host's heights.
    std::shared_ptr<const Seabed> seabedOf(const Scene& next) const
    {
        return std::make_shared<const Seabed>(next, hostSeabed ? &*hostSeabed : nullptr);
    }
    // The model `next` describes, over `seabed`.
    static std::unique_ptr<WaveModel> waveModelOf(const Scene& next, const Seabed& seabed)
    {
        return makeWaveModel(next, seabed);
    }

    RenderContext context()
    {
        return RenderContext{scene, resources, sky, simulation, telemetry, spray, settings.islandTolerance_px};
    }

    // Makes `next` the scene and `nextSceneModel` its model (the override
    // and the host's sources as given), rebuilding what `effects` and a
    // changed model ask for; `nextSeabed`, when given, is `next`'s floor as
    // the caller built it for the model. Everything that can fail is built
    // first; the renderer changes only when all did.
    void apply(const Scene& next, ParameterEffect effects, std::shared_ptr<const WaveModel> nextSceneModel,
               std::shared_ptr<const WaveModel> nextOverride,
               std::vector<std::shared_ptr<const SurfaceSource>> nextHostSources, bool first = false,
               std::shared_ptr<const Seabed> nextSeabed = nullptr);
    SceneUpdate prepare(const Scene& next, ParameterEffect effects, std::shared_ptr<const WaveModel> nextSceneModel,
                        std::shared_ptr<const WaveModel> nextOverride,
                        std::vector<std::shared_ptr<const SurfaceSource>> nextHostSources, bool first,
                        std::shared_ptr<const Seabed> nextSeabed);
    void commit(const Scene& next, SceneUpdate update);

    void advanceTo(double time_s, glm::dvec3 viewpointWorld)
    {
        simulation.advanceTo(time_s, viewpointWorld, scene, sky.light(scene), resources, telemetry);
    }

    // The passes of one view, with the GL state put back afterwards,
    // whatever happens.
    void drawRestoring(const ViewRequest& request, ViewState& state);
    void drawView(const ViewRequest& request, ViewState& state);
    // render()'s frame, and draw()'s view, as the passes are asked for them.
    ViewRequest renderRequest(const Camera& camera, glm::ivec2 outputSize, GLuint framebuffer);
    ViewRequest drawRequest(const View& view, GLuint framebuffer, const DrawOptions& options, ViewState& state);
    void render(const Camera& camera, double time_s, glm::ivec2 outputSize, GLuint framebuffer,
                std::optional<glm::dvec3> simulatedAround_m = std::nullopt);
};

} // namespace swell
