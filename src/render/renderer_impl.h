// The renderer's state and its steps (swell/renderer.h), shared by the
// files that define them: render/renderer.cpp (the public calls, the
// simulation, scene changes) and render/view_passes.cpp (one view's passes).
// Library-internal.
#pragma once

#include "swell/renderer.h"

#include "render/caustics_map.h"
#include "render/cloud_shadow_map.h"
#include "render/cpu_parts.h"
#include "render/frame_uniforms.h"
#include "render/host_depth.h"
#include "render/label_target.h"
#include "render/programs.h"
#include "render/render_target.h"
#include "render/scene_world.h"
#include "render/spray_buffers.h"
#include "render/sky_cubemap.h"
#include "render/surface_probe.h"
#include "render/surface_sources.h"
#include "render/temporal_resolve.h"
#include "render/view_setup.h"
#include "render/wake_texture.h"
#include "render/water_grid.h"
#include "render/waterline.h"
#include "render/world.h"
#include "objects/wake_surface.h"
#include "swell/error.h"
#include "swell/gpu/bindings.h"
#include "swell/grid.h"
#include "swell/scene_changes.h"
#include "swell/wave_model_gpu.h"

#include <glm/gtc/matrix_transform.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace swell {

namespace detail {

// The uniform buffer of each kind of pass (Renderer::Impl::frameUbo).
// PassProbe: the frame's water queries (render/surface_probe.h).
enum Pass { PassReflection = 0, PassRefraction = 1, PassMain = 2, PassWaterline = 3, PassProbe = 4, PassCount = 5 };

} // namespace detail

// The library's own code: its internal types are used unqualified.
using namespace detail;

struct Renderer::Impl {
    Scene scene;
    // The scene with its objects in the sea's frame (y = 0 at the water's
    // mean level): what the bodies, the poses and the world's boxes use.
    Scene seaScene;
    // The scene's wave model, and the one setWaveModel() put in its place.
    std::shared_ptr<const WaveModel> sceneModel, overrideModel;
    // The host's surface sources (Renderer::addSurfaceSource), drawn after the wake.
    std::vector<std::shared_ptr<const SurfaceSource>> hostSources;
    // What the floating bodies float on: model() plus the host's sources.
    std::shared_ptr<const WaveModel> bodyModel;
    std::unique_ptr<WaveModelGpu> modelGpu;
    double seaMeanSquareSlope = 0.0; // of model(), for the reflection's masking (slope_statistics.h)
    GridShape gridShape;
    gl::ShaderSources sources;
    // Water shading terms left out, for the benchmark (RendererOptions).
    unsigned omittedWaterTerms = 0;
    Programs programs; // and the flags they were built for
    gl::Buffer frameUbo[PassCount];
    gl::VertexArray emptyVao;
    WaterGrid waterGrid;
    World world;
    RenderTarget reflection, refraction, output;
    WaterlineMask waterline;
    // Where the main pass draws when anti-aliased or scaled (render_target.h).
    MainTarget mainTarget;
    double renderScale = 1.0;
    // The temporal resolve (Renderer::setTemporalResolve): on or off, its
    // history and jitter, and for the frame render() is drawing its
    // unjittered view and projection (absolute world to clip), which
    // drawView() hands to the resolve.
    bool temporalOn = false;
    TemporalResolve temporal;
    std::optional<glm::dmat4> temporalViewProj;
    bool interactive = false; // see Renderer::setInteractive
    double islandTolerance_px = kIslandLodTolerance_px; // see Renderer::setIslandTolerance
    FrameCounters counters;
    // Charges the calling thread's CPU time to counters.simulationCpu's
    // parts; paused while the observer runs.
    mutable CpuParts cpuParts;
    PassObserver* observer = nullptr;
    // The wave model's stages, passed on to the observer as passes inside
    // "ocean", with the CPU parts paused as for the renderer's own.
    struct StageRelay final : PassObserver {
        const Impl* impl;
        explicit StageRelay(const Impl* owner) : impl(owner) {}
        void beginPass(const char* name) override { impl->notify(true, name); }
        void endPass(const char* name) override { impl->notify(false, name); }
    } stageRelay{this};
    // The sun and sky world.skyCube was baked for; empty when it must be (re)baked.
    std::optional<SkyBakeKey> bakedSky;
    // The physical sky's atmosphere (null for the gradient), the light the
    // frame uniforms take from the sky (sky_light.h) and what it was found
    // for, and the atmosphere's tables on the GPU while the sky is physical.
    std::shared_ptr<const Atmosphere> atmosphere;
    SkyLight skyLight;
    std::optional<std::pair<SkyBakeKey, bool>> skyLightKey;
    AtmosphereTextures atmosphereTextures;
    // The physical sky's bake program: built when a scene first asks for it
    // (its ray march is the costliest shader here to compile) and kept
    // across scene changes, whose flags it does not read; empty until then,
    // after a shader reload and while the sky is not physical.
    SkyBakeProgram physicalSkyBake;
    // The cloud layer's shadows on what the sun lights (cloud_shadow_map.h)
    // and their bake's program: built when a scene first has clouds, kept
    // across scene changes (it reads no flags); used while the scene's
    // clouds cast shadows (cloudShadowsOn).
    CloudShadowMap cloudShadow;
    CloudShadowBakeProgram cloudShadowBake;
    // The sky's light for the scene, found again when the sun or sky changed.
    const SkyLight& currentSkyLight();

    // The simulation's state at the time advanceTo() reached (sea frame).
    struct Simulated {
        double time_s = 0.0;
        glm::dvec3 viewpoint{0.0};
        // Each scene object's transform, object to sea frame (see world.h).
        std::vector<glm::dmat4> poses;
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
    std::optional<Simulated> simulated;
    // The floating rigid bodies, stepped to the simulated time (objects/scene_bodies.h).
    SceneBodies bodies;
    // What the bodies had done by the last advanceTo(), for its counters.
    struct BodiesTally {
        std::int64_t steps = 0, wakeSteps = 0;
        double wake_ms = 0.0, ahead_ms = 0.0;
    };
    BodiesTally bodiesTally;
    // Bodies of drawnSurface()'s queries at times other than the simulated
    // one: stepped apart from those drawn, so a query changes no frame.
    mutable std::optional<SceneBodies> queryBodies;
    WakeTexture wakeTexture;
    // The sun's light under the water, drawn once per view (caustics_map.h).
    CausticsMap caustics;
    // The spray's clumps, their list and their draw's command, the crests'
    // and the bows' (spray_buffers.h).
    SprayBuffers crestSprayBuffers, bowSprayBuffers;
    SurfaceSourceParametersBuffer sourceParameters;
    SurfaceProbe surfaceProbe;
    HostDepthCopy hostDepth; // draw()'s copy of the host's depth, for its geometry under the water
    // The label pass (swell/labels.h): its programs, built when first asked
    // for and again where the colour programs' flags change, and its target.
    std::optional<LabelPrograms> labelPrograms;
    LabelTarget labelTarget;

    explicit Impl(RendererOptions options)
        : sources(std::move(options.shaders)), omittedWaterTerms(options.omittedWaterTerms)
    {
    }

    const WaveModel& model() const { return overrideModel ? *overrideModel : *sceneModel; }
    double level() const { return scene.water.level_m; }
    glm::dvec3 toSea(glm::dvec3 world_m) const { return world_m - glm::dvec3(0.0, level(), 0.0); }

    // How far the simulated surface can move from rest: the model's reach,
    // and the wake's height above it.
    WaveReach simulatedReach() const
    {
        WaveReach reach = model().reach();
        if (simulated)
            reach.vertical_m += simulated->sourcesReach_m;
        return reach;
    }

    // The GLSL of the sources a scene's programs draw (render/surface_sources.h).
    static std::vector<std::string> sourceCodes(const Scene& scene,
                                                const std::vector<std::shared_ptr<const SurfaceSource>>& hosts)
    {
        std::vector<std::string> codes;
        if (scene.wake.enabled)
            codes.push_back(WakeSurfaceSource::code());
        for (const std::shared_ptr<const SurfaceSource>& source : hosts)
            codes.push_back(source->glsl());
        return codes;
    }

    // The sources drawn at time_s with the wake's frame `wake`.
    std::vector<std::shared_ptr<const SurfaceSource>> sourcesWith(std::shared_ptr<const WakeFrame> wake) const
    {
        std::vector<std::shared_ptr<const SurfaceSource>> drawn;
        if (scene.wake.enabled)
            drawn.push_back(std::make_shared<const WakeSurfaceSource>(std::move(wake)));
        drawn.insert(drawn.end(), hostSources.begin(), hostSources.end());
        return drawn;
    }

    // The water as the grid draws it around a viewpoint (sea frame), with
    // the surface sources `sources`; in the sea frame, or in the world's with
    // `level_m` added.
    DrawnSurface drawnSurfaceAt(glm::dvec3 viewpointSea, double time_s,
                                std::vector<std::shared_ptr<const SurfaceSource>> drawn, double level_m) const
    {
        return DrawnSurface(model(), gridShape, horizonFadeFor(scene.grid, gridShape), viewpointSea, time_s,
                            std::move(drawn), level_m);
    }

    // The wave model's work, for advanceTo()'s frame (simulationGpu) or
    // for a view (viewsGpu).
    void addWork(const WaveModelGpu::Work& work, GpuWork& gpu)
    {
        counters.oceanTransforms += work.transforms;
        counters.foamSteps += work.foamSteps;
        gpu.dispatches += work.dispatches;
        gpu.barriers += work.barriers;
        gpu.mipmaps += work.mipmaps;
        gpu.bytesWritten += work.bytesWritten;
    }

    void notify(bool begin, const char* pass) const
    {
        if (!observer)
            return;
        cpuParts.pause();
        begin ? observer->beginPass(pass) : observer->endPass(pass);
        cpuParts.resume();
    }

    void buildGrid()
    {
        gridShape = gridShapeFor(scene.grid, scene.camera);
        waterGrid.build(gridShape);
    }

    // The simulation (Renderer::advanceTo): the wave model's own work for the
    // time (the spectral model's FFTs and foam), the bodies stepped on the
    // CPU with fixed steps (so their poses depend on time_s alone, never on
    // the frames before) and their wake.
    void advanceTo(double time_s, glm::dvec3 viewpointWorld);

    // The frame's water queries (sea-frame x, z) answered on the GPU for
    // `next`'s time, sources and viewpoint, whose grid is `grid`
    // (render/surface_probe.h): after the model's prepareFrame() and the
    // wake's upload.
    std::vector<ProbedPoint> probeWater(const std::vector<glm::dvec2>& points, const Simulated& next,
                                        const GridPlacement& grid);

    // What every pass of one view shares.
    struct ViewFrame {
        FrameUniforms base{};
        glm::dvec3 origin{0.0};   // the render origin, sea frame: the eye's x, z at the mean level
        glm::dvec3 eye{0.0};      // sea frame
        glm::dmat4 viewProj{1.0};     // positions relative to the render origin to clip space
        DepthConvention depth;
        std::vector<glm::mat4> poses; // each object's transform relative to the origin
        glm::mat4 island{1.0f};
        glm::ivec2 size{0};       // every pass's size, pixels
    };

    // Per-view setup shared by drawing and capture: the render origin is the
    // eye's x,z; the surface is phased at the snapped grid centre around the
    // LOD viewpoint; the water tiles in view are chosen.
    ViewFrame prepareView(const View& view, glm::ivec2 size, bool hostGeometry);

    void bindFrame(Pass pass, const FrameUniforms& f)
    {
        const CpuPartScope part(cpuParts, counters.simulationCpu.views_ms);
        glNamedBufferSubData(frameUbo[pass].id(), 0, sizeof(f), &f);
        glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_FRAME, frameUbo[pass].id());
    }

    void drawSky(bool inAir, const DepthConvention& depth);

    // The caustics map for a view (caustics_map.h): placed always, drawn
    // when the scene has caustics, the sun is up and either Swell's own
    // world is drawn and reaches under the water within the map, or the
    // shafts of light (water.shafts) may be seen, the eye below the waves'
    // crests; bound for the passes after it.
    void drawCaustics(const ViewFrame& v, bool ownWorld);

    void drawWater(bool inAir);
    // The spray (shaders/spray_clumps.comp, spray.vert): over the finished frame, blended,
    // depth-tested against the world and the water, writing no depth; none
    // below Beaufort 7. The crests' (its amount growing with the wind) and
    // the bows' of the bodies under way.
    void drawSpray(const ViewFrame& v, const View& view);
    void drawCrestSpray(const ViewFrame& v, const View& view);
    void drawBowSpray(const ViewFrame& v);
    // Gives back the spray's buffers a scene that draws no such spray
    // does not need (the crests' 39 MB of streaks among them).
    void releaseUnusedSpray();
    void drawSprayClumps(const SprayPasses& passes, SprayBuffers& buffers, long long slots, long long capacity,
                         long long recordBytes, int strips);

    // The waterline mask for the main pass (render/waterline.h): drawn from
    // the water grid when the near plane can lie on either side of the
    // waves, else cleared to the side it lies on. Draws into its own target
    // with its own frame uniforms (the viewport at its origin).
    void drawWaterline(NearPlaneMedium medium, const ViewFrame& v);

    // Every pass sets all the state it depends on, so passes can be
    // reordered; a clear colour clears colour and depth, none keeps both.
    void beginPass(GLuint framebuffer, glm::ivec4 viewport, const DepthConvention& depth,
                   std::optional<glm::vec4> clear);

    void setPassState(glm::ivec4 viewport, const DepthConvention& depth);

    // Calls a host's geometry for a pass and puts back the state the pass
    // draws with: the host may change any of it.
    void drawHost(PassGeometry& geometry, const PassView& pass, Pass uniforms, const FrameUniforms& f,
                  GLuint framebuffer, bool mirrored);

    static const char* passName(PassKind pass)
    {
        switch (pass) {
        case PassKind::Reflection: return "reflection";
        case PassKind::Refraction: return "refraction";
        case PassKind::Main: return "main";
        case PassKind::WaterMask: return "water mask";
        }
        return "?";
    }

    // The geometry of a pass: Swell's own world and the host's, each through
    // the same callback; the pass's view in absolute world coordinates.
    void drawGeometry(PassKind kind, SceneWorld* own, PassGeometry* host, const View& view, Pass uniforms,
                      const FrameUniforms& f, GLuint framebuffer, glm::ivec4 viewport);

    // The passes of one view. ownsFrame: render()'s frame (cleared, the main
    // pass through mainTarget at the render scale); else draw()'s
    // compositing into the host's framebuffer at the view's viewport.
    void drawView(const View& view, GLuint framebuffer, const DrawOptions& options, bool ownsFrame,
                  glm::ivec2 outputSize);

    // The underwater pass over the host's geometry (underwater_host.frag):
    // on its copied depth, blending in-scattering and transmittance.
    void fogHostUnderwater(GLuint framebuffer, glm::ivec4 viewport, const DepthConvention& depth);

    void requireSimulation() const
    {
        if (!simulated)
            throw Error("nothing to draw yet: call advanceTo() with the frame's time before draw()");
    }

    // Draws a view with the GL state put back afterwards, whatever happens.
    void drawRestoring(const View& view, GLuint framebuffer, const DrawOptions& options, bool ownsFrame,
                       glm::ivec2 outputSize);

    void render(const Camera& camera, double time_s, glm::ivec2 outputSize, GLuint framebuffer);

    // The label pass (render/label_pass.cpp) for a camera at the simulated time.
    FrameLabels drawLabels(const Camera& camera, glm::ivec2 size);
    void drawLabelPass(const Camera& camera, const View& view, glm::ivec2 size, const std::vector<ObjectLabel>& objects);

    // Makes `next` the scene and `nextSceneModel` (when given) its model,
    // rebuilding what `effects` and a changed model file ask for. Everything
    // that can fail is built first; the renderer changes only when all did.
    void apply(const Scene& next, ParameterEffect effects, std::shared_ptr<const WaveModel> nextSceneModel,
               std::shared_ptr<const WaveModel> nextOverride, bool first,
               std::vector<std::shared_ptr<const SurfaceSource>> nextHostSources);
};

} // namespace swell
