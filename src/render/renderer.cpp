// The ocean renderer: owns the GPU state of a scene (render/renderer_impl.h).
// This file: the public calls, the simulation (advanceTo) and scene changes
// (apply); one view's passes are render/view_passes.cpp. Programs are
// render/programs.*, the world's assets and poses render/world.*, the shared
// uniforms render/frame_uniforms.*; the surface comes from a
// swell::WaveModel, never from a particular model.
#include "render/renderer_impl.h"

#include "ocean/waves_with_sources.h"
#include "render/gl_state.h"
#include "render/slope_statistics.h"
#include "swell/error.h"
#include "swell/gl/shader.h"
#include "swell/gpu/bindings.h"
#include "swell/gpu/limits.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace swell {

namespace {

// The scene with its objects moved into the sea's frame, in which the
// water's mean level is y = 0 (Scene::water.level_m).
Scene inSeaFrame(const Scene& scene)
{
    Scene sea = scene;
    for (SceneObject& object : sea.objects)
        object.position_m.y -= scene.water.level_m;
    return sea;
}

} // namespace

// The simulation (Renderer::advanceTo): the wave model's own work for the
// time (the spectral model's FFTs and foam), the bodies stepped on the
// CPU with fixed steps (so their poses depend on time_s alone, never on
// the frames before) and their wake.
void Renderer::Impl::advanceTo(double time_s, glm::dvec3 viewpointWorld)
{
    const glm::dvec3 viewpoint = toSea(viewpointWorld);
    if (simulated && simulated->time_s == time_s && simulated->viewpoint == viewpoint) {
        counters = {};
        return;
    }
    counters = {};
    counters.simulationSteps = 1;
    // The model's compute passes and the frame's queries use programs of
    // their own; the host's stays current.
    const SavedProgram savedProgram;
    // The thread's CPU time, by part (FrameCounters::simulationCpu);
    // the observer's callbacks are outside every part.
    SimulationCpuTime& cpu = counters.simulationCpu;
    const CpuPartScope modelPart(cpuParts, cpu.model_ms);
    Simulated next;
    next.time_s = time_s;
    next.viewpoint = viewpoint;
    const GridPlacement grid = placeGrid(gridShape, viewpoint);
    notify(true, "ocean");
    modelGpu->prepareFrame(grid.center_m, time_s);
    addWork(modelGpu->takeWork(), counters.simulationGpu);
    notify(false, "ocean");
    notify(true, "bodies");
    cpuParts.switchTo(&cpu.bodies_ms);
    // What the bodies' worker did ahead of this frame (anticipate()) is
    // waited for here, counted with the steps taken now.
    bodies.advanceTo(time_s);
    if (bodies.wake())
        next.wake = bodies.sharedWakeFrameAt(time_s);
    const BodiesTally tally{bodies.stepsTaken(), bodies.wakeStepsTaken(), bodies.wakeSteps_ms(), bodies.aheadCpu_ms()};
    counters.floatingBodies = int(bodies.count());
    counters.bodySteps = tally.steps - bodiesTally.steps;
    counters.wakeSteps = tally.wakeSteps - bodiesTally.wakeSteps;
    counters.wakeSteps_ms = tally.wake_ms - bodiesTally.wake_ms;
    counters.bodiesAheadCpu_ms = tally.ahead_ms - bodiesTally.ahead_ms;
    bodiesTally = tally;
    notify(false, "bodies");
    // The wake's frame: blended, its slopes found and uploaded. It raises
    // and lowers the water beyond the waves' reach: the grid's tiles are
    // culled, and the near plane placed, with it.
    notify(true, "wake");
    wakeTexture.upload(next.wake.get());
    next.sources = sourcesWith(next.wake);
    for (const std::shared_ptr<const SurfaceSource>& source : next.sources)
        next.sourcesReach_m += std::abs(source->reach_m(time_s));
    notify(false, "wake");
    // The frame's own queries of the water, answered on the GPU from what it
    // draws (render/surface_probe.h): the floating objects' water and the
    // viewpoint's side of it.
    notify(true, "queries");
    cpuParts.switchTo(&cpu.queries_ms);
    // The viewpoint's side of the water needs asking only within the waves'
    // reach (an eye above it is in the air, one below it in the water); a
    // frame with nothing to ask waits for nothing.
    std::vector<glm::dvec2> points = floatingObjectPoints(seaScene);
    const bool askViewpoint = eyeWithinReach(viewpoint, model().reach().vertical_m + next.sourcesReach_m);
    if (askViewpoint)
        points.emplace_back(viewpoint.x, viewpoint.z);
    const bool onGpu = modelGpu->answersFrameQueries();
    std::vector<ProbedPoint> water;
    if (!points.empty())
        water = onGpu ? probeWater(points, next, grid)
                      : answerOnCpu(points, model(), drawnSurfaceAt(viewpoint, time_s, next.sources, 0.0), time_s);
    if (points.empty() || !onGpu)
        surfaceProbe.release();
    for (const ProbedPoint& p : water)
        (p.drawnOnCpu ? counters.queriesOnCpu : counters.queriesOnGpu) += 1;
    if (askViewpoint) {
        next.viewpointWaterHeight_m = water.back().displacement_m.y;
        water.pop_back();
    }
    next.poses = objectPoses(seaScene, water, bodies, time_s);
    notify(false, "queries");
    simulated = std::move(next);
}

std::vector<ProbedPoint> Renderer::Impl::probeWater(const std::vector<glm::dvec2>& points, const Simulated& next,
                                                   const GridPlacement& grid)
{
    // A view of the simulated viewpoint, as drawView() sets one up: the
    // render origin at its x, z, the model phased at the grid's centre, the
    // wake and the sources placed for that origin.
    const glm::dvec3 origin(next.viewpoint.x, 0.0, next.viewpoint.z);
    const FrameUniforms f =
        frameUniforms(scene, currentSkyLight(), gridShape, grid, next.viewpoint, glm::dmat4(1.0), origin, {1, 1});
    glNamedBufferSubData(frameUbo[PassProbe].id(), 0, sizeof(f), &f);
    glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_FRAME, frameUbo[PassProbe].id());
    modelGpu->prepareView(grid.center_m);
    addWork(modelGpu->takeWork(), counters.simulationGpu);
    modelGpu->bind();
    wakeTexture.place(origin);
    wakeTexture.bind();
    sourceParameters.upload(next.sources, next.time_s, origin + glm::dvec3(0.0, level(), 0.0));
    programs.probe.use();
    const DrawnSurface cpu = drawnSurfaceAt(next.viewpoint, next.time_s, next.sources, 0.0);
    std::vector<ProbedPoint> answers = surfaceProbe.run(points, origin, gridShape, grid, cpu);
    counters.simulationGpu.dispatches += 1;
    counters.simulationGpu.barriers += 1;
    counters.simulationGpu.bytesWritten += (long long)(points.size() * SurfaceProbe::answerBytes());
    return answers;
}

// Makes `next` the scene and `nextSceneModel` (when given) its model,
// rebuilding what `effects` and a changed model file ask for. Everything
// that can fail is built first; the renderer changes only when all did.
void Renderer::Impl::apply(const Scene& next, ParameterEffect effects, std::shared_ptr<const WaveModel> nextSceneModel,
           std::shared_ptr<const WaveModel> nextOverride, bool first,
           std::vector<std::shared_ptr<const SurfaceSource>> nextHostSources)
{
    // The bodies' worker may be querying the model and sources replaced here.
    bodies.settle();
    const std::shared_ptr<const WaveModel>& nextModelPtr = nextOverride ? nextOverride : nextSceneModel;
    const WaveModel& nextModel = *nextModelPtr;
    const bool modelChanged = first || &nextModel != &model();
    std::unique_ptr<WaveModelGpu> gpu = modelChanged ? nextModel.createGpu(sources) : nullptr;
    const ProgramFlags nextFlags =
        programFlagsOf(next, gpu ? *gpu : *modelGpu, omittedWaterTerms, sourceCodes(next, nextHostSources));
    const bool programsChanged = first || nextFlags != programs.flags;
    Programs nextPrograms;
    if (programsChanged) {
        try {
            // Only the programs whose own flags changed.
            nextPrograms = buildChangedPrograms(sources, programs, nextFlags);
        } catch (...) {
            // The files of the sources still drawn, for a later reload.
            setSurfaceSourceFiles(sources, programs.flags.water.surface.surfaceSources);
            throw;
        }
    }
    const bool worldChanged = first || hasEffect(effects, ParameterEffect::World);
    World nextWorld;
    if (worldChanged)
        nextWorld = buildWorld(next);
    // Bodies start again from their start when what moves them changed.
    const bool sourcesChanged = nextHostSources != hostSources;
    const bool bodiesChanged = worldChanged || modelChanged || sourcesChanged || !sameBodies(scene, next);
    SceneBodies nextBodies;
    std::shared_ptr<const WaveModel> nextBodyModel = bodyModel;
    if (bodiesChanged) {
        // The bodies float on the host's sources too.
        nextBodyModel = nextHostSources.empty()
            ? nextModelPtr
            : std::make_shared<const WavesWithSources>(nextModelPtr, nextHostSources);
        nextBodies = buildBodies(worldChanged ? nextWorld : world, inSeaFrame(next), *nextBodyModel);
    }

    scene = next;
    seaScene = inSeaFrame(next);
    sceneModel = std::move(nextSceneModel);
    overrideModel = std::move(nextOverride);
    if (gpu) {
        modelGpu = std::move(gpu);
        modelGpu->setInteractive(interactive);
        modelGpu->setStageObserver(&stageRelay);
        seaMeanSquareSlope = meanSquareSlope(model());
    }
    if (programsChanged) {
        keepUnchangedPrograms(nextPrograms, programs);
        programs = std::move(nextPrograms);
    }
    if (worldChanged) {
        world = std::move(nextWorld);
        bakedSky.reset();
    }
    hostSources = std::move(nextHostSources);
    if (bodiesChanged) {
        bodies = std::move(nextBodies); // after the worker of the bodies before is done
        bodiesTally = {};
        bodyModel = std::move(nextBodyModel);
        queryBodies.reset();
    }
    // What was simulated was for the scene before (the poses of objects
    // that float without being bodies follow their positions): the next
    // advanceTo() takes it again, at no cost where nothing moved.
    simulated.reset();
    if (first || hasEffect(effects, ParameterEffect::Grid))
        buildGrid();
    releaseUnusedSpray();
}

Renderer::Renderer(const Scene& scene, RendererOptions options) : impl_(std::make_unique<Impl>(std::move(options)))
{
    for (gl::Buffer& b : impl_->frameUbo) {
        b = gl::Buffer::create();
        glNamedBufferStorage(b.id(), sizeof(FrameUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    impl_->emptyVao = gl::VertexArray::create();
    impl_->apply(scene, ParameterEffect::Frame, makeWaveModel(scene), nullptr, true, {});
}

Renderer::~Renderer() = default;

void Renderer::setScene(const Scene& scene)
{
    Impl& s = *impl_;
    const ParameterEffect effects = sceneChanges(s.scene, scene);
    // The waves are generated again only when a wave parameter changed.
    std::shared_ptr<const WaveModel> sceneModel =
        hasEffect(effects, ParameterEffect::Waves) ? makeWaveModel(scene) : s.sceneModel;
    s.apply(scene, effects, std::move(sceneModel), s.overrideModel, false, s.hostSources);
}

const Scene& Renderer::scene() const { return impl_->scene; }
const WaveModel& Renderer::waveModel() const { return impl_->model(); }

void Renderer::setWaveModel(std::shared_ptr<const WaveModel> model)
{
    Impl& s = *impl_;
    s.apply(s.scene, ParameterEffect::Frame, s.sceneModel, std::move(model), false, s.hostSources);
}

void Renderer::addSurfaceSource(std::shared_ptr<const SurfaceSource> source)
{
    Impl& s = *impl_;
    if (!source)
        throw Error("addSurfaceSource: no source (null)");
    if (std::find(s.hostSources.begin(), s.hostSources.end(), source) != s.hostSources.end())
        throw Error("addSurfaceSource: the source was added already");
    std::vector<std::shared_ptr<const SurfaceSource>> next = s.hostSources;
    next.push_back(std::move(source));
    const std::size_t drawn = next.size() + (s.scene.wake.enabled ? 1 : 0);
    if (drawn > SWELL_MAX_SURFACE_SOURCES)
        throw Error(fmt::format("addSurfaceSource: at most {} surface sources are drawn{}", SWELL_MAX_SURFACE_SOURCES,
                                s.scene.wake.enabled ? ", the wake's included" : ""));
    s.apply(s.scene, ParameterEffect::Frame, s.sceneModel, s.overrideModel, false, std::move(next));
}

void Renderer::removeSurfaceSource(const std::shared_ptr<const SurfaceSource>& source)
{
    Impl& s = *impl_;
    std::vector<std::shared_ptr<const SurfaceSource>> next = s.hostSources;
    next.erase(std::remove(next.begin(), next.end(), source), next.end());
    s.apply(s.scene, ParameterEffect::Frame, s.sceneModel, s.overrideModel, false, std::move(next));
}

void Renderer::setRenderScale(double scale)
{
    if (!(scale >= kMinRenderScale && scale <= kMaxRenderScale))
        throw InputError({"render scale"}, fmt::format("{} is outside {}..{}", scale, kMinRenderScale, kMaxRenderScale));
    impl_->renderScale = scale;
}

double Renderer::renderScale() const { return impl_->renderScale; }

void Renderer::setTemporalResolve(bool on)
{
    if (on != impl_->temporalOn)
        impl_->temporal.reset();
    impl_->temporalOn = on;
}

bool Renderer::temporalResolve() const { return impl_->temporalOn; }
void Renderer::resetTemporalHistory() { impl_->temporal.reset(); }
void Renderer::setTemporalJitter(bool on) { impl_->temporal.setJitterEnabled(on); }

void Renderer::setIslandTolerance(double tolerance_px)
{
    if (!(tolerance_px >= 0.0))
        throw InputError({"island tolerance"}, fmt::format("{} pixels is below 0", tolerance_px));
    impl_->islandTolerance_px = tolerance_px;
}

const FrameCounters& Renderer::counters() const { return impl_->counters; }
void Renderer::setPassObserver(PassObserver* observer) { impl_->observer = observer; }

void Renderer::setInteractive(bool interactive)
{
    impl_->interactive = interactive;
    impl_->modelGpu->setInteractive(interactive);
}

void Renderer::reloadShaders()
{
    Impl& s = *impl_;
    s.sources.forgetCachedFiles();
    s.programs = buildChangedPrograms(s.sources, Programs{}, s.programs.flags);
    s.labelPrograms.reset(); // built again from the new sources when next asked for
    s.bakedSky.reset(); // the bake shader may have changed
    s.physicalSkyBake = {};
    s.cloudShadowBake = {};
    s.cloudShadow.forget();
}

void Renderer::advanceTo(double time_s, glm::dvec3 viewpoint_m)
{
    if (!std::isfinite(time_s) || !std::isfinite(viewpoint_m.x + viewpoint_m.y + viewpoint_m.z))
        throw Error(fmt::format("advanceTo: the time ({}) and the viewpoint must be finite", time_s));
    impl_->advanceTo(time_s, viewpoint_m);
}

void Renderer::anticipate(double nextTime_s)
{
    Impl& s = *impl_;
    if (s.simulated && std::isfinite(nextTime_s) && nextTime_s > s.simulated->time_s)
        s.bodies.stepAheadTo(nextTime_s);
}

std::optional<double> Renderer::simulatedTime_s() const
{
    return impl_->simulated ? std::optional<double>(impl_->simulated->time_s) : std::nullopt;
}

void Renderer::draw(const View& view, unsigned framebuffer, const DrawOptions& options)
{
    Impl& s = *impl_;
    s.requireSimulation();
    // A callback's error is told by the flag it leaves: one pending already
    // would be blamed on it, and clearing it would hide the host's own.
    if (const GLenum pending = glGetError(); pending != GL_NO_ERROR)
        throw Error(fmt::format("GL error 0x{:04x} was pending when draw() was called (draw() tells its "
                                "callbacks' errors by the flag they leave, so it needs none pending)",
                                pending));
    checkView(view);
    checkFramebuffer(framebuffer, true);
    s.drawRestoring(view, framebuffer, options, false, {view.viewport.z, view.viewport.w});
}

void Renderer::render(const Camera& camera, double time_s, glm::ivec2 size, unsigned framebuffer)
{
    impl_->render(camera, time_s, size, framebuffer);
}

Image Renderer::renderImage(const Camera& camera, double time_s, glm::ivec2 size)
{
    Image image;
    if (size.x <= 0 || size.y <= 0)
        return image;
    impl_->output.resize(size, GL_RGBA8);
    impl_->render(camera, time_s, size, impl_->output.framebuffer());
    image.width = size.x;
    image.height = size.y;
    image.rgba.resize(size_t(size.x) * size_t(size.y) * 4);
    std::vector<std::uint8_t> bottomUp(image.rgba.size());
    GLint packAlignment = 4;
    glGetIntegerv(GL_PACK_ALIGNMENT, &packAlignment);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(impl_->output.color(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(bottomUp.size()), bottomUp.data());
    glPixelStorei(GL_PACK_ALIGNMENT, packAlignment);
    const size_t row = size_t(size.x) * 4;
    for (int y = 0; y < size.y; ++y)
        std::copy_n(&bottomUp[size_t(size.y - 1 - y) * row], row, &image.rgba[size_t(y) * row]);
    return image;
}

Camera Renderer::sceneCameraAt(double time_s)
{
    Impl& s = *impl_;
    Camera camera = cameraAt(s.scene.camera, time_s);
    const int mount = s.scene.camera.mountObject;
    if (mount < 0 || std::size_t(mount) >= s.seaScene.objects.size())
        return camera;
    camera.position_m = s.scene.camera.mountOffset_m; // in the object's axes
    // A rigid body where advanceTo() will find it (its steps are taken here,
    // not again there); a fixed object where it stands.
    s.bodies.advanceTo(time_s);
    const std::optional<glm::dmat4> body = s.bodies.poseAt(std::size_t(mount), time_s);
    const glm::dmat4 pose = body ? *body : placedObjectPose(s.seaScene.objects[std::size_t(mount)],
                                                            s.seaScene.objects[std::size_t(mount)].position_m);
    return mountedCamera(camera, glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, s.level(), 0.0)) * pose);
}

std::vector<glm::dmat4> Renderer::objectTransforms() const
{
    std::vector<glm::dmat4> out;
    if (!impl_->simulated)
        return out;
    const glm::dmat4 toWorld = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, impl_->level(), 0.0));
    for (const glm::dmat4& pose : impl_->simulated->poses)
        out.push_back(toWorld * pose);
    return out;
}

DrawnSurface Renderer::drawnSurface(const Camera& camera, double time_s) const
{
    const Impl& s = *impl_;
    const glm::dvec3 eye = s.toSea(camera.position_m);
    if (s.simulated && s.simulated->time_s == time_s)
        return s.drawnSurfaceAt(eye, time_s, s.simulated->sources, s.level());
    // Another time: the wake there, from bodies of the queries' own, so
    // that nothing a frame draws changes.
    std::shared_ptr<const WakeFrame> wake;
    if (s.bodies.wake()) {
        if (!s.queryBodies)
            s.queryBodies = buildBodies(s.world, s.seaScene, *s.bodyModel);
        s.queryBodies->advanceTo(time_s);
        wake = std::make_shared<const WakeFrame>(s.queryBodies->wakeFrameAt(time_s));
    }
    return s.drawnSurfaceAt(eye, time_s, s.sourcesWith(std::move(wake)), s.level());
}

DrawnSurface Renderer::drawnSurface(glm::dvec3 lodViewpoint_m) const
{
    const Impl& s = *impl_;
    s.requireSimulation();
    return s.drawnSurfaceAt(s.toSea(lodViewpoint_m), s.simulated->time_s, s.simulated->sources, s.level());
}

int Renderer::waterVertexCount() const { return (impl_->gridShape.cells + 1) * (impl_->gridShape.cells + 1); }

int Renderer::captureWaterVertices(const Camera& camera, double time_s, unsigned buffer, glm::ivec2 size,
                                   std::vector<std::uint32_t>* drawnIndices)
{
    Impl& s = *impl_;
    size = glm::max(size, glm::ivec2(1));
    s.advanceTo(time_s, camera.position_m);
    const SavedGlState saved;
    s.bindFrame(PassMain, s.prepareView(viewOf(camera, size), size, false).base);
    if (drawnIndices)
        *drawnIndices = s.waterGrid.chosenIndices();
    // Drawing needs a complete framebuffer even with rasterisation discarded
    // (a headless context has no default one).
    if (s.output.size().x == 0)
        s.output.resize({1, 1}, GL_RGBA8);
    glBindFramebuffer(GL_FRAMEBUFFER, s.output.framebuffer());
    s.programs.capture.use();
    glBindVertexArray(s.emptyVao.id());
    glEnable(GL_RASTERIZER_DISCARD);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffer);
    glBeginTransformFeedback(GL_POINTS);
    const int count = waterVertexCount();
    glDrawArrays(GL_POINTS, 0, count);
    glEndTransformFeedback();
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    saved.restore();
    return count;
}

} // namespace swell
