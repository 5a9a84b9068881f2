// The renderer's simulation (Renderer::advanceTo): the wave model and its
// GPU half, the host's surface sources, the floating bodies and their wake,
// and the frame's queries of the water, all at one simulated time and in
// the sea's frame (swell/sea_frame.h). What it reached is what every view
// draws; the CPU queries (drawnSurface, objectTransforms) answer from the
// same state. Library-internal.
#pragma once

#include "objects/placement.h"
#include "render/gpu/blocks.h"
#include "render/resources.h"
#include "render/sky_light.h"
#include "render/surface_probe.h"
#include "render/surface_sources.h"
#include "render/telemetry.h"
#include "render/wake_texture.h"
#include "swell/camera.h"
#include "swell/dataset/platform.h"
#include "swell/drawn_surface.h"
#include "swell/scene/scene.h"
#include "swell/sea_frame.h"
#include "swell/surface_source.h"
#include "swell/wave_model.h"
#include "swell/wave_model_gpu.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace swell::detail {

// The simulation's state at the time advanceTo() reached (sea frame).
struct Simulated {
    double time_s = 0.0;
    glm::dvec3 viewpoint{0.0};
    // Each scene object's transform, object to sea frame (see world.h).
    std::vector<glm::dmat4> poses;
    // Each object's motion then (objectVelocities(): sea frame; nothing where it has no state).
    std::vector<std::optional<FloatingBody::Velocity>> velocities;
    std::shared_ptr<const WakeFrame> wake; // null when the scene has none
    // The surface sources drawn, in the programs' order: the wake's (when
    // the scene has one) and the host's.
    std::vector<std::shared_ptr<const SurfaceSource>> sources;
    double sourcesReach_m = 0.0; // the largest height they add together, m
    // The exact surface's height under the viewpoint (sea frame, m),
    // from the frame's queries: which side of the water an eye there is
    // (the mean level when the viewpoint is beyond the waves' reach,
    // which tells the side as well).
    double viewpointWaterHeight_m = 0.0;
};

// What a scene change hands the simulation, built before anything changes
// (render/scene_update.h): null or empty where that part stays.
struct SimulationUpdate {
    std::shared_ptr<const WaveModel> sceneModel, overrideModel;
    std::vector<std::shared_ptr<const SurfaceSource>> hostSources;
    std::unique_ptr<WaveModelGpu> gpu;
    std::optional<SceneBodies> bodies;
    std::shared_ptr<const SurfaceQuery> bodyModel;
    std::shared_ptr<const Seabed> bodySeabed; // the floor their wake feels
};

class Simulation {
public:
    // The surface drawn: the scene's model, or the one setWaveModel() put in its place.
    const WaveModel& model() const { return overrideModel_ ? *overrideModel_ : *sceneModel_; }
    const std::shared_ptr<const WaveModel>& sceneModel() const { return sceneModel_; }
    const std::shared_ptr<const WaveModel>& overrideModel() const { return overrideModel_; }
    const std::vector<std::shared_ptr<const SurfaceSource>>& hostSources() const { return hostSources_; }
    const std::shared_ptr<const SurfaceQuery>& bodyModel() const { return bodyModel_; }
    WaveModelGpu& gpu() const { return *gpu_; }
    bool hasModel() const { return sceneModel_ != nullptr; }

    const SeaFrame& sea() const { return sea_; }
    // The scene with its objects in the sea's frame: what the bodies, the
    // poses and the world's boxes use.
    const Scene& seaScene() const { return seaScene_; }
    const SceneBodies& bodies() const { return bodies_; }
    double seaMeanSquareSlope() const { return seaMeanSquareSlope_; }

    const std::optional<Simulated>& simulated() const { return simulated_; }
    // Throws swell::Error before the first advanceTo().
    const Simulated& require() const;

    // How far the simulated surface can move from rest: the model's reach,
    // and the sources' height above it.
    WaveReach reach() const;

    // The scene with its objects moved into its sea's frame.
    static Scene inSeaFrame(const Scene& scene);
    // The GLSL of the sources a scene's programs draw (render/surface_sources.h).
    static std::vector<std::string> sourceCodes(const Scene& scene,
                                                const std::vector<std::shared_ptr<const SurfaceSource>>& hosts);

    // Waits for the bodies' worker (before the model or sources it queries change).
    void settle() { bodies_.settle(); }
    // Takes a scene change (everything that could fail was built already);
    // forgets what was simulated.
    void commit(const Scene& scene, SimulationUpdate update, bool interactive, PassObserver* stages);
    void setInteractive(bool interactive) { gpu_->setInteractive(interactive); }

    // The simulation (Renderer::advanceTo): the wave model's own work for
    // the time (the spectral model's FFTs and foam), the bodies stepped on
    // the CPU with fixed steps (so their poses depend on time_s alone, never
    // on the frames before), their wake, and the frame's queries.
    void advanceTo(double time_s, glm::dvec3 viewpointWorld, const Scene& scene, const SkyLight& sky,
                   Resources& resources, Telemetry& telemetry);
    // Steps the bodies towards nextTime_s on their worker (Renderer::anticipate).
    void anticipate(double nextTime_s);

    // A view's part: the model's uniforms for the view's grid centre, the
    // wake and the sources placed for its render origin (sea frame), all bound.
    void prepareView(glm::dvec2 gridCenter_m, glm::dvec3 origin, Telemetry& telemetry);
    // Binds what the water's programs read of the simulation.
    void bindForWater() const;
    // Whether an eye (sea frame) is under the water at the simulated time.
    bool eyeUnderwater(glm::dvec3 eye) const;

    // The CPU queries (swell/renderer.h): in absolute world coordinates.
    DrawnSurface drawnSurface(glm::dvec3 eyeWorld, double time_s, const SceneShapes& shapes) const;
    DrawnSurface drawnSurface(glm::dvec3 lodViewpointWorld) const;
    std::vector<glm::dmat4> objectTransforms() const;
    // Each object's motion at that time, world axes (objectVelocities()).
    std::vector<std::optional<FloatingBody::Velocity>> objectVelocities() const;
    // The scene's camera at time_s, on its mount (Renderer::sceneCameraAt).
    Camera sceneCameraAt(const Scene& scene, double time_s);
    // The platform that camera stands for, and how it moves (Renderer::platformAt).
    PlatformMotion platformAt(const Scene& scene, double time_s);

    // The grid shape the drawn surface is built on (the water grid's).
    void setGridShape(const GridShape& shape) { gridShape_ = shape; }

private:
    // The sources drawn with the wake's frame `wake`.
    std::vector<std::shared_ptr<const SurfaceSource>> sourcesWith(std::shared_ptr<const WakeFrame> wake) const;
    // The water as the grid draws it around a viewpoint (sea frame), with
    // `drawn` sources, in the world's frame or (seaFrame) the sea's.
    DrawnSurface drawnSurfaceAt(glm::dvec3 viewpointSea, double time_s,
                                std::vector<std::shared_ptr<const SurfaceSource>> drawn, bool seaFrame) const;
    void stepBodies(Simulated& next, Telemetry& telemetry);
    void answerQueries(Simulated& next, const GridPlacement& grid, const Scene& scene, const SkyLight& sky,
                       Resources& resources, Telemetry& telemetry);
    // The frame's water queries (sea-frame x, z) answered on the GPU for
    // `next`'s time, sources and viewpoint, whose grid is `grid`.
    std::vector<ProbedPoint> probeWater(const std::vector<glm::dvec2>& points, const Simulated& next,
                                        const GridPlacement& grid, const Scene& scene, const SkyLight& sky,
                                        Resources& resources, Telemetry& telemetry);

    Scene seaScene_;
    SeaFrame sea_;
    GridShape gridShape_;
    std::shared_ptr<const WaveModel> sceneModel_, overrideModel_;
    // The host's surface sources (Renderer::addSurfaceSource), drawn after the wake.
    std::vector<std::shared_ptr<const SurfaceSource>> hostSources_;
    // What the floating bodies float on: model() plus the host's sources.
    std::shared_ptr<const SurfaceQuery> bodyModel_;
    std::shared_ptr<const Seabed> bodySeabed_; // the floor the bodies' wake feels
    std::unique_ptr<WaveModelGpu> gpu_;
    double seaMeanSquareSlope_ = 0.0; // of model(), for the reflection's masking (slope_statistics.h)
    std::optional<Simulated> simulated_;
    // The floating rigid bodies, stepped to the simulated time (objects/scene_bodies.h).
    SceneBodies bodies_;
    // What the bodies had done by the last advanceTo(), for its counters.
    struct BodiesTally {
        std::int64_t steps = 0, wakeSteps = 0;
        double wake_ms = 0.0, ahead_ms = 0.0;
    };
    BodiesTally bodiesTally_;
    // Bodies of drawnSurface()'s queries at times other than the simulated
    // one: stepped apart from those drawn, so a query changes no frame.
    mutable std::optional<SceneBodies> queryBodies_;
    WakeTexture wakeTexture_;
    SurfaceSourceParametersBuffer sourceParameters_;
    SurfaceProbe surfaceProbe_;
};

} // namespace swell::detail
