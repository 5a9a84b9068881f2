// What a scene change rebuilds (Renderer::Impl::apply): the wave model's
// GPU half when the model changed, the programs whose own flags changed,
// the world when a parameter of its says so (swell/scene/scene_changes.h), the
// floating bodies when what moves them changed, the grid when its settings
// did. Everything that can fail is built first (prepare); the renderer
// changes only when all of it did (commit).
#include "render/renderer_impl.h"

#include "objects/placement.h"
#include "render/surface_sources.h"
#include "swell/composed_surface.h"

namespace swell {

SceneUpdate Renderer::Impl::prepare(const Scene& next, ParameterEffect effects,
                                    std::shared_ptr<const WaveModel> nextSceneModel,
                                    std::shared_ptr<const WaveModel> nextOverride,
                                    std::vector<std::shared_ptr<const SurfaceSource>> nextHostSources, bool first,
                                    std::shared_ptr<const Seabed> nextSeabed)
{
    SceneUpdate update;
    SimulationUpdate& sim = update.simulation;
    const std::shared_ptr<const WaveModel>& nextModel = nextOverride ? nextOverride : nextSceneModel;
    const bool modelChanged = first || nextModel.get() != &simulation.model();
    if (modelChanged)
        sim.gpu = nextModel->createGpu(resources.sources);
    const ProgramFlags flags = programFlagsOf(next, sim.gpu ? *sim.gpu : simulation.gpu(), resources.omittedWaterTerms,
                                              Simulation::sourceCodes(next, nextHostSources));
    if (first || flags != resources.programs.flags) {
        try {
            // Only the programs whose own flags changed.
            update.programs = buildChangedPrograms(resources.sources, resources.programs, flags);
        } catch (...) {
            // The files of the sources still drawn, for a later reload.
            setSurfaceSourceFiles(resources.sources, resources.programs.flags.water.surface.surfaceSources);
            throw;
        }
        update.programsChanged = true;
    }
    if (first || hasEffect(effects, ParameterEffect::World)) {
        const SceneAssets assets = loadSceneAssets(next);
        update.world = buildWorld(next, assets);
        update.shapes = SceneShapes(assets);
    }
    if (first || hasEffect(effects, ParameterEffect::World) || hasEffect(effects, ParameterEffect::Seabed)) {
        update.seabed = nextSeabed ? std::move(nextSeabed) : seabedOf(next);
        update.seabedMesh = makeSeabedMesh(*update.seabed);
    }
    // Bodies start again from their start when what moves them changed.
    const bool sourcesChanged = nextHostSources != simulation.hostSources();
    if (update.world || modelChanged || sourcesChanged || !sameBodies(scene, next)) {
        // The bodies float on the host's sources too.
        sim.bodyModel = std::make_shared<const ComposedSurface>(nextModel, nextHostSources);
        sim.bodySeabed = update.seabed ? update.seabed : resources.seabed;
        sim.bodies = buildBodies(update.shapes ? *update.shapes : resources.shapes, Simulation::inSeaFrame(next),
                                 sim.bodyModel, sim.bodySeabed);
    }
    update.gridChanged = first || hasEffect(effects, ParameterEffect::Grid);
    sim.sceneModel = std::move(nextSceneModel);
    sim.overrideModel = std::move(nextOverride);
    sim.hostSources = std::move(nextHostSources);
    return update;
}

void Renderer::Impl::commit(const Scene& next, SceneUpdate update)
{
    scene = next;
    simulation.commit(scene, std::move(update.simulation), settings.interactive, telemetry.stageRelay());
    if (update.programsChanged) {
        keepUnchangedPrograms(update.programs, resources.programs);
        resources.programs = std::move(update.programs);
    }
    if (update.world) {
        resources.world = std::move(*update.world);
        resources.shapes = std::move(*update.shapes);
        sky.forgetBake();
    }
    if (update.seabed) {
        resources.seabed = std::move(update.seabed);
        setSeabedMesh(resources.world, update.seabedMesh);
    }
    if (update.gridChanged) {
        resources.buildGrid(scene);
        simulation.setGridShape(resources.gridShape);
    }
    spray.releaseUnused(scene, simulation.gpu(), resources.programs);
}

void Renderer::Impl::apply(const Scene& next, ParameterEffect effects, std::shared_ptr<const WaveModel> nextSceneModel,
                           std::shared_ptr<const WaveModel> nextOverride,
                           std::vector<std::shared_ptr<const SurfaceSource>> nextHostSources, bool first,
                           std::shared_ptr<const Seabed> nextSeabed)
{
    // The bodies' worker may be querying the model and sources replaced here.
    simulation.settle();
    commit(next, prepare(next, effects, std::move(nextSceneModel), std::move(nextOverride),
                         std::move(nextHostSources), first, std::move(nextSeabed)));
}

} // namespace swell
