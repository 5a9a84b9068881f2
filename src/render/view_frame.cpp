#include "render/view_frame.h"

#include "core/grid_tiles.h"
#include "ocean/coast/swash.h"
#include "render/frame_uniforms.h"
#include "render/waterline.h"
#include "render/world.h"
#include "swell/gpu/bindings.h"
#include "swell/gpu/underwater.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

namespace swell::detail {

ViewFrame prepareView(RenderContext& context, const View& view, glm::ivec2 size, bool hostGeometry)
{
    Simulation& simulation = context.simulation;
    Telemetry& telemetry = context.telemetry;
    const Simulated& simulated = simulation.require();
    const SeaFrame& sea = simulation.sea();
    SimulationCpuTime& cpu = telemetry.counters.simulationCpu;
    const CpuPartScope viewPart(telemetry.cpu, cpu.views_ms);
    ViewFrame v;
    v.size = size;
    v.depth = depthConventionOf(view.depth);
    v.eye = sea.toSea(view.eye_m());
    v.origin = glm::dvec3(v.eye.x, 0.0, v.eye.z);
    const glm::dvec3 lod = view.lodViewpoint_m ? sea.toSea(*view.lodViewpoint_m) : v.eye;
    const GridShape& gridShape = context.resources.gridShape;
    const GridPlacement grid = placeGrid(gridShape, lod);
    v.gridCenter_m = grid.center_m;
    simulation.prepareView(grid.center_m, v.origin, telemetry);
    // Positions relative to the render origin (sea frame) to clip space.
    v.viewProj = view.projection * view.view * glm::translate(glm::dmat4(1.0), sea.toWorld(v.origin));
    FrameUniforms& f = v.base;
    f = frameUniforms(context.scene, context.sky.light(context.scene), gridShape, grid, v.eye, v.viewProj, v.origin,
                      size);
    setDepthConvention(f, view.depth);
    f.projectionFocalY = float(view.projection[1][1]);
    f.waveHeightDeviation_m = float(simulation.model().heightDeviation_m());
    f.swashH0L0_m2 = float(coast::offshoreHeightTimesWavelength_m2(context.scene, simulation.model().heightDeviation_m()));
    f.waveMeanSquareSlope = float(simulation.seaMeanSquareSlope());
    const WaveReach reach = simulation.reach();
    // What the waterline mask's rays that meet no water are judged by
    // (shaders/underwater.glsl): the band the surface stays in, and the
    // eye's own side of it.
    f.waveReachVertical_m = float(reach.vertical_m);
    telemetry.cpu.switchTo(&cpu.queries_ms);
    f.eyeUnderwater = simulation.eyeUnderwater(v.eye) ? 1 : 0;
    telemetry.cpu.switchTo(&cpu.views_ms);
    for (const glm::dmat4& pose : simulated.poses)
        v.poses.emplace_back(glm::translate(glm::dmat4(1.0), -v.origin) * pose);
    v.island = glm::mat4(glm::translate(glm::dmat4(1.0), kIslandPosition_m - v.origin));
    const glm::dvec2 seabedAt = context.resources.world.seabedOrigin_m;
    v.seabed = glm::mat4(glm::translate(glm::dmat4(1.0), glm::dvec3(seabedAt.x, 0.0, seabedAt.y) - v.origin));
    // A host's geometry has no boxes Swell knows of: every reflected ray
    // is marched.
    const World& world = context.resources.world;
    f.worldBoxCount = hostGeometry
        ? -1
        : worldBoxes(world, simulation.seaScene(), reach, v.origin, simulated.poses, f.worldBoxes);
    WaterGrid& waterGrid = context.resources.waterGrid;
    waterGrid.cull(gridShape, grid, reach, v.viewProj, v.depth.zeroToOne(),
                   grid.center_m - glm::dvec2(v.origin.x, v.origin.z));
    telemetry.counters.cullBoxesTested += waterGrid.boxesTested();
    return v;
}

namespace {

// Whether any of the world's boxes (relative to the render origin) that
// stays put reaches below the mean level inside the caustics map's square
// (`floating[i]`: box i rides the water). Where none does, nothing the map
// lights is drawn (the default scene's island lies 1.7 km from its camera)
// or what it lights is a floating hull's underside, which from the air
// shows hardly any of it: the pass is left out. Unbounded worlds always do.
bool worldUnderMap(const FrameUniforms& f, const CausticsUniforms& map, const std::vector<bool>& floating)
{
    if (f.worldBoxCount < 0)
        return true;
    const glm::vec2 lo = map.mapCorner_m, hi = map.mapCorner_m + map.mapSize_m;
    for (int i = 0; i < f.worldBoxCount; ++i) {
        const WorldBoxUniform& box = f.worldBoxes[i];
        if (std::size_t(i) < floating.size() && floating[std::size_t(i)])
            continue;
        if (box.min_m.y < 0.0f && box.max_m.x >= lo.x && box.min_m.x <= hi.x && box.max_m.z >= lo.y &&
            box.min_m.z <= hi.y)
            return true;
    }
    return false;
}

// Whether the water over the caustics map's square shows in the view. From
// the air, what the map lights under the water is seen through the surface,
// and a ray refracted there keeps its way across (a wave's slope turns it by
// far less than the pad): a floor under the map shows only through the
// surface over it. A view from 60 m up, whose nearest water lies 50 m off
// (the harbour preset's), sees none of the map's 48 m square, and its
// frames need no map.
bool waterOverMapInView(const ViewFrame& v, const CausticsUniforms& map, const WaveReach& reach)
{
    constexpr double kPad_m = 2.0;
    const glm::dvec2 lo = glm::dvec2(map.mapCorner_m) - kPad_m;
    const glm::dvec2 hi = glm::dvec2(map.mapCorner_m) + double(map.mapSize_m) + kPad_m;
    const Bounds box{{lo.x, -reach.vertical_m - kPad_m, lo.y}, {hi.x, reach.vertical_m + kPad_m, hi.y}};
    return frustumContains(frustumPlanes(v.viewProj, v.depth.zeroToOne()), box) != Containment::Outside;
}

// Whether the caustics map is worth drawing for the view (prepareViewMaps).
bool causticsWanted(RenderContext& context, const ViewFrame& v, bool ownWorld)
{
    Resources& resources = context.resources;
    // A list of its own here once left out the sea floor's box, so the
    // floor of a scene without the island whose first object floats was
    // taken for a floating hull: no map was drawn, and the floor read it
    // empty, dark within 24 m of the eye (CausticsShallows).
    const std::vector<bool> floating = worldBoxesThatFloat(resources.world, context.simulation.seaScene());
    // Seen from under the water, the caustics on anything there (a hull's
    // underside included) are in full view.
    const bool wanted = v.base.eyeUnderwater != 0 || (worldUnderMap(v.base, resources.caustics.uniforms(), floating) &&
                                                      waterOverMapInView(v, resources.caustics.uniforms(),
                                                                         context.simulation.reach()));
    // The shafts of light read it along the rays of any pixel under the
    // water, the world drawn or not: wherever the main pass's near plane is
    // not wholly in the air (its programs then have no shafts).
    const bool shafts = resources.programs.flags.water.underwater.shafts &&
                        nearPlaneMedium(nearPlaneCorners(glm::inverse(v.viewProj), v.depth.nearNdcZ),
                                        context.simulation.reach()) != NearPlaneMedium::Air;
    return resources.programs.caustics && v.base.sunDirection.y > 0.0f && ((ownWorld && wanted) || shafts);
}

void drawCaustics(RenderContext& context, const ViewFrame& v, bool ownWorld)
{
    CausticsMap& caustics = context.resources.caustics;
    caustics.place(v.origin, v.base.gridCenter, v.base.sunDirection);
    if (causticsWanted(context, v, ownWorld)) {
        const ObservedPass pass(context.telemetry, "caustics");
        FrameCounters& counters = context.telemetry.counters;
        context.simulation.gpu().bind();
        counters.causticsTriangles += caustics.render(context.resources.programs.caustics);
        Telemetry::addWork(CausticsMap::renderWork(), counters.viewsGpu);
        counters.drawCalls += SWELL_CAUSTICS_SLICES; // a draw a slice
    }
    caustics.bind();
}

} // namespace

void prepareViewMaps(RenderContext& context, const ViewFrame& v, bool ownWorld)
{
    // The procedural sky is baked into the cubemap when first needed and
    // after the sun or sky changed (the bake reads the frame uniforms).
    context.sky.bakeIfStale(context.scene, v.base, context.resources, context.telemetry);
    // The cloud layer's shadows before every pass that reads them.
    context.sky.updateCloudShadows(context.scene, v.base, v.origin, context.resources, context.telemetry);
    // The sun's light under the water, before every pass that draws the world.
    drawCaustics(context, v, ownWorld);
}

} // namespace swell::detail
