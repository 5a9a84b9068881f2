#include "render/simulation.h"

#include "render/frame_uniforms.h"
#include "render/gl_state.h"
#include "render/slope_statistics.h"
#include "render/waterline.h"
#include "objects/wake_surface.h"
#include "swell/composed_surface.h"
#include "swell/error.h"
#include "swell/gpu/bindings.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace swell::detail {

Scene Simulation::inSeaFrame(const Scene& scene)
{
    const SeaFrame sea = seaFrameOf(scene);
    Scene moved = scene;
    for (SceneObject& object : moved.objects)
        object.position_m = sea.toSea(object.position_m);
    return moved;
}

const Simulated& Simulation::require() const
{
    if (!simulated_)
        throw Error("nothing to draw yet: call advanceTo() with the frame's time before draw()");
    return *simulated_;
}

WaveReach Simulation::reach() const
{
    WaveReach reach = model().reach();
    if (simulated_)
        reach.vertical_m += simulated_->sourcesReach_m;
    return reach;
}

std::vector<std::string> Simulation::sourceCodes(const Scene& scene,
                                                 const std::vector<std::shared_ptr<const SurfaceSource>>& hosts)
{
    std::vector<std::string> codes;
    if (scene.wake.enabled)
        codes.push_back(WakeSurfaceSource::code());
    for (const std::shared_ptr<const SurfaceSource>& source : hosts)
        codes.push_back(source->glsl());
    return codes;
}

std::vector<std::shared_ptr<const SurfaceSource>> Simulation::sourcesWith(std::shared_ptr<const WakeFrame> wake) const
{
    std::vector<std::shared_ptr<const SurfaceSource>> drawn;
    if (seaScene_.wake.enabled)
        drawn.push_back(std::make_shared<const WakeSurfaceSource>(std::move(wake)));
    drawn.insert(drawn.end(), hostSources_.begin(), hostSources_.end());
    return drawn;
}

void Simulation::commit(const Scene& scene, SimulationUpdate update, bool interactive, PassObserver* stages)
{
    seaScene_ = inSeaFrame(scene);
    sea_ = seaFrameOf(scene);
    sceneModel_ = std::move(update.sceneModel);
    overrideModel_ = std::move(update.overrideModel);
    if (update.gpu) {
        gpu_ = std::move(update.gpu);
        gpu_->setInteractive(interactive);
        gpu_->setStageObserver(stages);
        seaMeanSquareSlope_ = meanSquareSlope(model());
    }
    hostSources_ = std::move(update.hostSources);
    if (update.bodies) {
        bodies_ = std::move(*update.bodies); // after the worker of the bodies before is done
        bodiesTally_ = {};
        bodyModel_ = std::move(update.bodyModel);
        bodySeabed_ = std::move(update.bodySeabed);
        queryBodies_.reset();
    }
    // What was simulated was for the scene before (the poses of objects
    // that float without being bodies follow their positions): the next
    // advanceTo() takes it again, at no cost where nothing moved.
    simulated_.reset();
}

void Simulation::advanceTo(double time_s, glm::dvec3 viewpointWorld, const Scene& scene, const SkyLight& sky,
                           Resources& resources, Telemetry& telemetry)
{
    const glm::dvec3 viewpoint = sea_.toSea(viewpointWorld);
    telemetry.counters = {};
    if (simulated_ && simulated_->time_s == time_s && simulated_->viewpoint == viewpoint)
        return;
    telemetry.counters.simulationSteps = 1;
    // The model's compute passes and the frame's queries use programs and
    // buffers of their own, and upload textures: the host's state is put
    // back, and what it left set that would change them is not used.
    const HostStateScope hostState;
    // The thread's CPU time, by part (FrameCounters::simulationCpu);
    // the observer's callbacks are outside every part.
    SimulationCpuTime& cpu = telemetry.counters.simulationCpu;
    const CpuPartScope modelPart(telemetry.cpu, cpu.model_ms);
    Simulated next;
    next.time_s = time_s;
    next.viewpoint = viewpoint;
    const GridPlacement grid = placeGrid(gridShape_, viewpoint);
    {
        const ObservedPass pass(telemetry, "ocean");
        gpu_->prepareFrame(grid.center_m, time_s);
        telemetry.addWork(gpu_->takeWork(), telemetry.counters.simulationGpu);
    }
    stepBodies(next, telemetry);
    // The wake's frame: blended, its slopes found and uploaded. It raises
    // and lowers the water beyond the waves' reach: the grid's tiles are
    // culled, and the near plane placed, with it.
    {
        const ObservedPass pass(telemetry, "wake");
        wakeTexture_.upload(next.wake.get());
        next.sources = sourcesWith(next.wake);
        for (const std::shared_ptr<const SurfaceSource>& source : next.sources)
            next.sourcesReach_m += std::abs(source->reach_m(time_s));
    }
    answerQueries(next, grid, scene, sky, resources, telemetry);
    simulated_ = std::move(next);
}

void Simulation::stepBodies(Simulated& next, Telemetry& telemetry)
{
    const ObservedPass pass(telemetry, "bodies");
    FrameCounters& counters = telemetry.counters;
    telemetry.cpu.switchTo(&counters.simulationCpu.bodies_ms);
    // What the bodies' worker did ahead of this frame (anticipate()) is
    // waited for here, counted with the steps taken now.
    bodies_.advanceTo(next.time_s);
    if (bodies_.wake())
        next.wake = bodies_.sharedWakeFrameAt(next.time_s);
    const BodiesTally tally{bodies_.stepsTaken(), bodies_.wakeStepsTaken(), bodies_.wakeSteps_ms(),
                            bodies_.aheadCpu_ms()};
    counters.floatingBodies = int(bodies_.count());
    counters.bodySteps = tally.steps - bodiesTally_.steps;
    counters.wakeSteps = tally.wakeSteps - bodiesTally_.wakeSteps;
    counters.wakeSteps_ms = tally.wake_ms - bodiesTally_.wake_ms;
    counters.bodiesAheadCpu_ms = tally.ahead_ms - bodiesTally_.ahead_ms;
    bodiesTally_ = tally;
}

// The frame's own queries of the water, answered on the GPU from what it
// draws (render/surface_probe.h): the floating objects' water and the
// viewpoint's side of it.
void Simulation::answerQueries(Simulated& next, const GridPlacement& grid, const Scene& scene, const SkyLight& sky,
                               Resources& resources, Telemetry& telemetry)
{
    const ObservedPass pass(telemetry, "queries");
    FrameCounters& counters = telemetry.counters;
    telemetry.cpu.switchTo(&counters.simulationCpu.queries_ms);
    // The viewpoint's side of the water needs asking only within the waves'
    // reach (an eye above it is in the air, one below it in the water); a
    // frame with nothing to ask waits for nothing.
    std::vector<glm::dvec2> points = floatingObjectPoints(seaScene_);
    const glm::dvec3 viewpoint = next.viewpoint;
    const bool askViewpoint = eyeWithinReach(viewpoint, model().reach().vertical_m + next.sourcesReach_m);
    if (askViewpoint)
        points.emplace_back(viewpoint.x, viewpoint.z);
    const bool onGpu = gpu_->answersFrameQueries();
    std::vector<ProbedPoint> water;
    if (!points.empty())
        water = onGpu ? probeWater(points, next, grid, scene, sky, resources, telemetry)
                      : answerOnCpu(points, model(), drawnSurfaceAt(viewpoint, next.time_s, next.sources, true),
                                    next.time_s);
    if (points.empty() || !onGpu)
        surfaceProbe_.release();
    for (const ProbedPoint& p : water)
        (p.drawnOnCpu ? counters.queriesOnCpu : counters.queriesOnGpu) += 1;
    if (askViewpoint) {
        next.viewpointWaterHeight_m = water.back().displacement_m.y;
        water.pop_back();
    }
    next.poses = objectPoses(seaScene_, water, bodies_, next.time_s);
    next.velocities = detail::objectVelocities(seaScene_, bodies_, next.time_s);
}

std::vector<ProbedPoint> Simulation::probeWater(const std::vector<glm::dvec2>& points, const Simulated& next,
                                                const GridPlacement& grid, const Scene& scene, const SkyLight& sky,
                                                Resources& resources, Telemetry& telemetry)
{
    // A view of the simulated viewpoint, as a view sets one up: the render
    // origin at its x, z, the model phased at the grid's centre, the wake
    // and the sources placed for that origin.
    const glm::dvec3 origin(next.viewpoint.x, 0.0, next.viewpoint.z);
    const FrameUniforms f =
        frameUniforms(scene, sky, gridShape_, grid, next.viewpoint, glm::dmat4(1.0), origin, {1, 1});
    resources.bindFrame(PassProbe, f);
    gpu_->prepareView(grid.center_m);
    telemetry.addWork(gpu_->takeWork(), telemetry.counters.simulationGpu);
    gpu_->bind();
    wakeTexture_.place(origin);
    wakeTexture_.bind();
    sourceParameters_.upload(next.sources, next.time_s, sea_.toWorld(origin));
    resources.programs.probe.use();
    const DrawnSurface cpu = drawnSurfaceAt(next.viewpoint, next.time_s, next.sources, true);
    std::vector<ProbedPoint> answers = surfaceProbe_.run(points, origin, gridShape_, grid, cpu);
    GpuWork& work = telemetry.counters.simulationGpu;
    work.dispatches += 1;
    work.barriers += 1;
    work.bytesWritten += (long long)(points.size() * SurfaceProbe::answerBytes());
    return answers;
}

void Simulation::anticipate(double nextTime_s)
{
    if (simulated_ && std::isfinite(nextTime_s) && nextTime_s > simulated_->time_s)
        bodies_.stepAheadTo(nextTime_s);
}

void Simulation::prepareView(glm::dvec2 gridCenter_m, glm::dvec3 origin, Telemetry& telemetry)
{
    SimulationCpuTime& cpu = telemetry.counters.simulationCpu;
    telemetry.cpu.switchTo(&cpu.model_ms);
    gpu_->prepareView(gridCenter_m);
    // No transforms, unless a view simulated: the counters would show it.
    telemetry.addWork(gpu_->takeWork(), telemetry.counters.viewsGpu);
    gpu_->bind();
    telemetry.cpu.switchTo(&cpu.views_ms);
    wakeTexture_.place(origin);
    wakeTexture_.bind();
    sourceParameters_.upload(simulated_->sources, simulated_->time_s, sea_.toWorld(origin));
}

void Simulation::bindForWater() const
{
    gpu_->bind();
    wakeTexture_.bind();
    sourceParameters_.bind();
}

bool Simulation::eyeUnderwater(glm::dvec3 eye) const
{
    // The frame's query answered it for the simulated viewpoint (the eye a
    // view matrix gives back differs from it by rounding); another eye
    // asks the model.
    constexpr double kSameEye_m = 1e-6;
    const Simulated& s = *simulated_;
    const bool atViewpoint =
        std::abs(eye.x - s.viewpoint.x) < kSameEye_m && std::abs(eye.z - s.viewpoint.z) < kSameEye_m;
    return atViewpoint ? eye.y < s.viewpointWaterHeight_m
                       : detail::eyeUnderwater(eye, model(), s.time_s, reach().vertical_m);
}

DrawnSurface Simulation::drawnSurfaceAt(glm::dvec3 viewpointSea, double time_s,
                                        std::vector<std::shared_ptr<const SurfaceSource>> drawn, bool seaFrame) const
{
    return DrawnSurface(std::make_shared<const ComposedSurface>(overrideModel_ ? overrideModel_ : sceneModel_,
                                                                std::move(drawn)),
                        gridShape_, horizonFadeFor(seaScene_.grid, gridShape_), viewpointSea, time_s,
                        seaFrame ? SeaFrame() : sea_);
}

DrawnSurface Simulation::drawnSurface(glm::dvec3 eyeWorld, double time_s, const SceneShapes& shapes) const
{
    const glm::dvec3 eye = sea_.toSea(eyeWorld);
    if (simulated_ && simulated_->time_s == time_s)
        return drawnSurfaceAt(eye, time_s, simulated_->sources, false);
    // Another time: the wake there, from bodies of the queries' own, so
    // that nothing a frame draws changes.
    std::shared_ptr<const WakeFrame> wake;
    if (bodies_.wake()) {
        if (!queryBodies_)
            queryBodies_ = buildBodies(shapes, seaScene_, bodyModel_, bodySeabed_);
        queryBodies_->advanceTo(time_s);
        wake = std::make_shared<const WakeFrame>(queryBodies_->wakeFrameAt(time_s));
    }
    return drawnSurfaceAt(eye, time_s, sourcesWith(std::move(wake)), false);
}

DrawnSurface Simulation::drawnSurface(glm::dvec3 lodViewpointWorld) const
{
    const Simulated& s = require();
    return drawnSurfaceAt(sea_.toSea(lodViewpointWorld), s.time_s, s.sources, false);
}

std::vector<glm::dmat4> Simulation::objectTransforms() const
{
    std::vector<glm::dmat4> out;
    if (!simulated_)
        return out;
    for (const glm::dmat4& pose : simulated_->poses)
        out.push_back(sea_.worldFromSea() * pose);
    return out;
}

std::vector<std::optional<FloatingBody::Velocity>> Simulation::objectVelocities() const
{
    std::vector<std::optional<FloatingBody::Velocity>> out;
    if (!simulated_)
        return out;
    // The sea frame's axes are the world's turned by worldFromSea's rotation (none but a shift today).
    const glm::dmat3 turn(sea_.worldFromSea());
    for (const std::optional<FloatingBody::Velocity>& v : simulated_->velocities)
        out.push_back(v ? std::optional(FloatingBody::Velocity{turn * v->origin_m_per_s, turn * v->angular_rad_per_s})
                        : std::nullopt);
    return out;
}

Camera Simulation::sceneCameraAt(const Scene& scene, double time_s)
{
    Camera camera = cameraAt(scene.camera, time_s);
    const int mount = scene.camera.mountObject;
    if (mount < 0 || std::size_t(mount) >= seaScene_.objects.size())
        return camera;
    camera.position_m = scene.camera.mountOffset_m; // in the object's axes
    // A rigid body where advanceTo() will find it (its steps are taken here,
    // not again there); a fixed object where it stands.
    bodies_.advanceTo(time_s);
    const SceneObject& object = seaScene_.objects[std::size_t(mount)];
    const std::optional<glm::dmat4> body = bodies_.poseAt(std::size_t(mount), time_s);
    const glm::dmat4 pose = body ? *body : placedObjectPose(object, object.position_m);
    return mountedCamera(camera, sea_.worldFromSea() * pose);
}

PlatformMotion Simulation::platformAt(const Scene& scene, double time_s)
{
    const int mount = scene.camera.mountObject;
    if (mount < 0 || std::size_t(mount) >= seaScene_.objects.size())
        return unmountedCameraMotion(scene.camera, time_s);
    // Mounted: the camera's pose on its object (its steps taken here), and
    // the body's motion carried to the camera's eye as a rigid body's point
    // moves: v = v_c + w x r, a = a_c + alpha x r + w x (w x r), r from the
    // centre of mass. A fixed object stands still.
    const Camera camera = sceneCameraAt(scene, time_s);
    PlatformMotion m;
    m.time_s = time_s;
    m.position_m = camera.position_m;
    m.orientation = platformOrientationOf(camera);
    const std::optional<FloatingBody::Velocity> velocity = bodies_.velocityAt(std::size_t(mount), time_s);
    const std::optional<FloatingBody::Acceleration> acceleration =
        bodies_.accelerationAt(std::size_t(mount), time_s);
    if (!velocity || !acceleration)
        return m;
    // The sea frame's axes are the world's (worldFromSea is a shift).
    const glm::dvec3 r = sea_.toSea(camera.position_m) - acceleration->centerOfMass_m;
    const glm::dvec3 w = velocity->angular_rad_per_s;
    // The centre of mass's velocity, from its model origin's (where the pose puts the origin).
    const glm::dvec3 origin = glm::dvec3(bodies_.poseAt(std::size_t(mount), time_s).value()[3]);
    const glm::dvec3 centre = velocity->origin_m_per_s - glm::cross(w, origin - acceleration->centerOfMass_m);
    m.velocity_m_per_s = centre + glm::cross(w, r);
    m.angularVelocity_rad_per_s = w;
    m.acceleration_m_per_s2 = acceleration->centerOfMass_m_per_s2 + glm::cross(acceleration->angular_rad_per_s2, r) +
                              glm::cross(w, glm::cross(w, r));
    return m;
}

} // namespace swell::detail
