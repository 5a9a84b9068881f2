// The ocean renderer: owns the GPU state of a scene and draws its passes.
// Programs are render/programs.*, the world's assets and poses
// render/world.*, the shared uniforms render/frame_uniforms.*; the surface
// comes from a swell::WaveModel, never from a particular model.
#include "swell/renderer.h"

#include "objects/wake_surface.h"
#include "ocean/waves_with_sources.h"
#include "render/frame_uniforms.h"
#include "render/gl_state.h"
#include "render/host_depth.h"
#include "render/programs.h"
#include "render/render_target.h"
#include "render/scene_world.h"
#include "render/sky_cubemap.h"
#include "render/slope_statistics.h"
#include "render/view_setup.h"
#include "render/wake_texture.h"
#include "render/water_grid.h"
#include "render/waterline.h"
#include "render/surface_sources.h"
#include "render/world.h"
#include "swell/error.h"
#include "swell/gl/shader.h"
#include "swell/grid.h"
#include "swell/scene_changes.h"
#include "swell/shader_constants.h"
#include "swell/wave_model_gpu.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace swell {

using namespace detail;

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

enum Pass { PassReflection = 0, PassRefraction = 1, PassMain = 2, PassWaterline = 3, PassCount = 4 };

} // namespace

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
    ShaderVariant variant;
    Programs programs;
    gl::Buffer frameUbo[PassCount];
    gl::VertexArray emptyVao;
    WaterGrid waterGrid;
    World world;
    RenderTarget reflection, refraction, output;
    WaterlineMask waterline;
    // Where the main pass draws when anti-aliased or scaled (render_target.h).
    MainTarget mainTarget;
    double renderScale = 1.0;
    bool interactive = false; // see Renderer::setInteractive
    FrameCounters counters;
    PassObserver* observer = nullptr;
    // The sun and sky world.skyCube was baked for; empty when it must be (re)baked.
    std::optional<SkyBakeKey> bakedSky;

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
    };
    std::optional<Simulated> simulated;
    // The floating rigid bodies, stepped to the simulated time (objects/scene_bodies.h).
    SceneBodies bodies;
    // Bodies of drawnSurface()'s queries at times other than the simulated
    // one: stepped apart from those drawn, so a query changes no frame.
    mutable std::optional<SceneBodies> queryBodies;
    WakeTexture wakeTexture;
    SurfaceSourceParametersBuffer sourceParameters;
    HostDepthCopy hostDepth; // draw()'s copy of the host's depth, for its geometry under the water

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

    void addWork(const WaveModelGpu::Work& work)
    {
        counters.oceanTransforms += work.transforms;
        counters.foamSteps += work.foamSteps;
    }

    void notify(bool begin, const char* pass) const
    {
        if (observer)
            begin ? observer->beginPass(pass) : observer->endPass(pass);
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
    void advanceTo(double time_s, glm::dvec3 viewpointWorld)
    {
        const glm::dvec3 viewpoint = toSea(viewpointWorld);
        if (simulated && simulated->time_s == time_s && simulated->viewpoint == viewpoint) {
            counters = {};
            return;
        }
        counters = {};
        counters.simulationSteps = 1;
        Simulated next;
        next.time_s = time_s;
        next.viewpoint = viewpoint;
        const GridPlacement grid = placeGrid(gridShape, viewpoint);
        notify(true, "ocean");
        modelGpu->prepareFrame(grid.center_m, time_s);
        addWork(modelGpu->takeWork());
        notify(false, "ocean");
        notify(true, "bodies");
        const std::int64_t stepsBefore = bodies.stepsTaken(), wakeStepsBefore = bodies.wakeStepsTaken();
        const double wakeBefore_ms = bodies.wakeSteps_ms();
        bodies.advanceTo(time_s);
        if (bodies.wake())
            next.wake = std::make_shared<const WakeFrame>(bodies.wakeFrameAt(time_s));
        next.sources = sourcesWith(next.wake);
        const DrawnSurface drawn = drawnSurfaceAt(viewpoint, time_s, next.sources, 0.0);
        next.poses = objectPoses(seaScene, model(), drawn, bodies, time_s);
        counters.floatingBodies = int(bodies.count());
        counters.bodySteps = bodies.stepsTaken() - stepsBefore;
        counters.wakeSteps = bodies.wakeStepsTaken() - wakeStepsBefore;
        counters.wakeSteps_ms = bodies.wakeSteps_ms() - wakeBefore_ms;
        notify(false, "bodies");
        // The wake's frame: blended, its slopes found and uploaded. It raises
        // and lowers the water beyond the waves' reach: the grid's tiles are
        // culled, and the near plane placed, with it.
        notify(true, "wake");
        wakeTexture.upload(next.wake.get());
        for (const std::shared_ptr<const SurfaceSource>& source : next.sources)
            next.sourcesReach_m += std::abs(source->reach_m(time_s));
        notify(false, "wake");
        simulated = std::move(next);
    }

    // What every pass of one view shares.
    struct ViewFrame {
        FrameUniforms base{};
        glm::dvec3 origin{0.0};   // the render origin, sea frame: the eye's x, z at the mean level
        glm::dvec3 eye{0.0};      // sea frame
        glm::dmat4 viewRelative{1.0}; // render origin relative to eye
        glm::dmat4 viewProj{1.0};     // the view's projection of it
        DepthConvention depth;
        std::vector<glm::mat4> poses; // each object's transform relative to the origin
        glm::mat4 island{1.0f};
        glm::ivec2 size{0};       // every pass's size, pixels
        glm::ivec4 viewport{0};   // the main pass's viewport in its framebuffer
    };

    // Per-view setup shared by drawing and capture: the render origin is the
    // eye's x,z; the surface is phased at the snapped grid centre around the
    // LOD viewpoint; the water tiles in view are chosen.
    ViewFrame prepareView(const View& view, glm::ivec2 size, bool hostGeometry)
    {
        ViewFrame v;
        v.size = size;
        v.viewport = view.viewport;
        v.depth = depthConventionOf(view.depth);
        v.eye = toSea(view.eye_m());
        v.origin = glm::dvec3(v.eye.x, 0.0, v.eye.z);
        const glm::dvec3 lod = view.lodViewpoint_m ? toSea(*view.lodViewpoint_m) : v.eye;
        const GridPlacement grid = placeGrid(gridShape, lod);
        modelGpu->prepareView(grid.center_m);
        addWork(modelGpu->takeWork()); // none, unless a view simulated: the counters would show it
        modelGpu->bind();
        // World = sea + level: relative = world - (origin + level).
        v.viewRelative = view.view * glm::translate(glm::dmat4(1.0), v.origin + glm::dvec3(0.0, level(), 0.0));
        v.viewProj = view.projection * v.viewRelative;
        const glm::dmat4& viewProj = v.viewProj;
        FrameUniforms& f = v.base;
        f = frameUniforms(scene, gridShape, grid, v.eye, viewProj, v.origin, size);
        setDepthConvention(f, view.depth);
        f.projectionFocalY = float(view.projection[1][1]);
        f.waveHeightDeviation_m = float(model().heightDeviation_m());
        f.waveMeanSquareSlope = float(seaMeanSquareSlope);
        wakeTexture.place(v.origin);
        wakeTexture.bind();
        sourceParameters.upload(simulated->sources, simulated->time_s, v.origin + glm::dvec3(0.0, level(), 0.0));
        const WaveReach reach = simulatedReach();
        // What the waterline mask's rays that meet no water are judged by
        // (shaders/underwater.glsl): the band the surface stays in, and the
        // eye's own side of it.
        f.waveReachVertical_m = float(reach.vertical_m);
        f.eyeUnderwater = eyeUnderwater(v.eye, model(), simulated->time_s) ? 1 : 0;
        for (const glm::dmat4& pose : simulated->poses)
            v.poses.emplace_back(glm::translate(glm::dmat4(1.0), -v.origin) * pose);
        v.island = glm::mat4(glm::translate(glm::dmat4(1.0), kIslandPosition_m - v.origin));
        // A host's geometry has no boxes Swell knows of: every reflected ray
        // is marched.
        f.worldBoxCount =
            hostGeometry ? -1 : worldBoxes(world, seaScene, reach, v.origin, simulated->poses, f.worldBoxes);
        waterGrid.cull(gridShape, grid, reach, viewProj, v.depth.zeroToOne(), grid.center_m - glm::dvec2(v.origin.x, v.origin.z));
        return v;
    }

    void bindFrame(Pass pass, const FrameUniforms& f)
    {
        glNamedBufferSubData(frameUbo[pass].id(), 0, sizeof(f), &f);
        glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_FRAME, frameUbo[pass].id());
    }

    void drawSky(bool inAir, const DepthConvention& depth)
    {
        (inAir ? programs.skyInAir : programs.sky).use();
        glBindTextureUnit(SWELL_UNIT_SKY, world.skyCube.id());
        glDepthFunc(depth.testOrFar);
        glDepthMask(GL_FALSE);
        glBindVertexArray(emptyVao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        ++counters.drawCalls;
        glDepthMask(GL_TRUE);
        glDepthFunc(depth.test);
    }

    void drawWater(bool inAir)
    {
        (inAir ? programs.waterInAir : programs.water).use();
        glBindTextureUnit(SWELL_UNIT_SKY, world.skyCube.id());
        glBindTextureUnit(SWELL_UNIT_REFLECTION_COLOR, reflection.color());
        glBindTextureUnit(SWELL_UNIT_REFLECTION_DEPTH, reflection.depth());
        glBindTextureUnit(SWELL_UNIT_REFRACTION_COLOR, refraction.color());
        glBindTextureUnit(SWELL_UNIT_REFRACTION_DEPTH, refraction.depth());
        wakeTexture.bind();
        glBindVertexArray(waterGrid.vertexArray());
        if (scene.debugView == DebugView::Wireframe)
            glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
        counters.waterTriangles += waterGrid.draw();
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        ++counters.drawCalls;
    }

    // The waterline mask for the main pass (render/waterline.h): drawn from
    // the water grid when the near plane can lie on either side of the
    // waves, else cleared to the side it lies on. Draws into its own target
    // with its own frame uniforms (the viewport at its origin).
    void drawWaterline(NearPlaneMedium medium, const ViewFrame& v)
    {
        waterline.resize(v.size);
        if (medium != NearPlaneMedium::Both) {
            waterline.fill(medium);
            return;
        }
        notify(true, "waterline");
        FrameUniforms f = v.base;
        f.viewportOrigin = glm::vec2(0.0f);
        bindFrame(PassWaterline, f);
        beginPass(waterline.framebuffer(), glm::ivec4(0, 0, v.size), v.depth, glm::vec4(SWELL_WATERLINE_NO_HIT));
        glBindTextureUnit(SWELL_UNIT_WATERLINE, waterline.allAbove()); // never the target itself
        programs.waterline.use();
        wakeTexture.bind();
        glBindVertexArray(waterGrid.vertexArray());
        waterGrid.draw();
        ++counters.drawCalls;
        notify(false, "waterline");
    }

    // Every pass sets all the state it depends on, so passes can be
    // reordered; a clear colour clears colour and depth, none keeps both.
    void beginPass(GLuint framebuffer, glm::ivec4 viewport, const DepthConvention& depth,
                   std::optional<glm::vec4> clear)
    {
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        setPassState(viewport, depth);
        if (clear) {
            glClearColor(clear->r, clear->g, clear->b, clear->a);
            glClearDepth(depth.cleared);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        }
    }

    void setPassState(glm::ivec4 viewport, const DepthConvention& depth)
    {
        glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
        glDisable(GL_SCISSOR_TEST);
        glDisable(GL_RASTERIZER_DISCARD);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(depth.test);
        glDepthMask(GL_TRUE);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glClipControl(GL_LOWER_LEFT, depth.clipDepth);
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        // The shaders write display-ready (sRGB-encoded) colour, or linear
        // colour for a linear target: never encoded again on the way.
        glDisable(GL_FRAMEBUFFER_SRGB);
        // Filter across cubemap face edges (off by default even in core profiles).
        glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    }

    // Calls a host's geometry for a pass and puts back the state the pass
    // draws with: the host may change any of it.
    void drawHost(PassGeometry& geometry, const PassView& pass, Pass uniforms, const FrameUniforms& f,
                  GLuint framebuffer, bool mirrored)
    {
        geometry.drawPass(pass);
        const GLenum error = glGetError();
        if (error != GL_NO_ERROR)
            throw Error(fmt::format("the host's geometry left GL error 0x{:04x} in the {} pass", error,
                                    passName(pass.pass)));
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        setPassState(pass.viewport, depthConventionOf(pass.depth));
        glFrontFace(mirrored ? GL_CW : GL_CCW);
        if (pass.pass == PassKind::Reflection || pass.pass == PassKind::Refraction)
            glEnable(GL_CLIP_DISTANCE0);
        bindFrame(uniforms, f);
        modelGpu->bind();
        wakeTexture.bind();
        sourceParameters.bind();
    }

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
                      const FrameUniforms& f, GLuint framebuffer, glm::ivec4 viewport)
    {
        const bool mirrored = kind == PassKind::Reflection;
        PassView pass;
        pass.pass = kind;
        pass.view = mirrored ? view.view * mirrorAbout(level()) : view.view;
        pass.projection = view.projection;
        pass.viewport = viewport;
        pass.depth = view.depth;
        const glm::dvec3 eye = view.eye_m();
        pass.eye_m = mirrored ? glm::dvec3(eye.x, 2.0 * level() - eye.y, eye.z) : eye;
        // The pass's clip plane, relative to the render origin, is the
        // world's plane moved by the origin (its y at the sea level).
        const glm::dvec4 plane(f.clipPlane);
        pass.clipPlane_m = glm::dvec4(glm::dvec3(plane), plane.w - plane.y * level());
        glFrontFace(mirrored ? GL_CW : GL_CCW);
        if (own)
            own->drawPass(pass);
        if (host)
            drawHost(*host, pass, uniforms, f, framebuffer, mirrored);
        glFrontFace(GL_CCW);
    }

    // The passes of one view. ownsFrame: render()'s frame (cleared, the main
    // pass through mainTarget at the render scale); else draw()'s
    // compositing into the host's framebuffer at the view's viewport.
    void drawView(const View& view, GLuint framebuffer, const DrawOptions& options, bool ownsFrame,
                  glm::ivec2 outputSize)
    {
        const glm::ivec2 size = ownsFrame ? scaledFrameSize(outputSize, renderScale) : glm::ivec2(view.viewport.z, view.viewport.w);
        ViewFrame v = prepareView(view, size, options.geometry != nullptr);
        ++counters.views;
        SceneWorld own(world, programs.meshInAir, programs.mesh, v.poses, v.island, counters);
        SceneWorld* ownWorld = options.sceneWorld ? &own : nullptr;
        const FrameUniforms& base = v.base;
        // The procedural sky is baked into the cubemap when first needed and
        // after the sun or sky changed (the bake reads the frame uniforms).
        if (scene.sky.cubemapFaces.empty() && bakedSky != skyBakeKeyOf(scene)) {
            bindFrame(PassMain, base);
            glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
            bakeProceduralSky(programs.skyBake, world.skyCube, emptyVao.id());
            bakedSky = skyBakeKeyOf(scene);
        }
        const glm::ivec2 scaled = glm::max(glm::ivec2(glm::dvec2(size) * scene.reflection.resolutionScale), glm::ivec2(1));
        const glm::ivec4 passViewport(0, 0, scaled);
        reflection.resize(scaled);
        refraction.resize(scaled);
        // Passes before the main one see nothing from below the water.
        waterline.resize(size);
        glBindTextureUnit(SWELL_UNIT_WATERLINE, waterline.allAbove());

        // Pass 1: the world mirrored about the water plane, clipped just below it.
        FrameUniforms f = base;
        const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, -1.0f, 1.0f));
        f.passViewProj = base.cameraViewProj * mirror;
        f.passInvViewProj = glm::inverse(f.passViewProj);
        f.clipPlane = glm::vec4(0.0f, 1.0f, 0.0f, float(scene.reflection.clipOffset_m));
        f.eyePosition.y = -base.eyePosition.y;
        setViewport(f, scaled);
        notify(true, "reflection");
        bindFrame(PassReflection, f);
        beginPass(reflection.framebuffer(), passViewport, v.depth, glm::vec4(0.0f));
        glEnable(GL_CLIP_DISTANCE0);
        // The mirror turns every triangle's winding around on screen: without
        // the front face turned too, the faces seen would count as back
        // faces, and mesh.frag, which turns a back face's normal round,
        // would light each object's reflection from the wrong side.
        drawGeometry(PassKind::Reflection, ownWorld, options.geometry, view, PassReflection, f,
                     reflection.framebuffer(), passViewport);
        glDisable(GL_CLIP_DISTANCE0);
        drawSky(true, v.depth);
        notify(false, "reflection");

        // Pass 1b: the world below the water, for refraction.
        f = base;
        f.clipPlane = glm::vec4(0.0f, -1.0f, 0.0f, float(scene.reflection.clipOffset_m));
        // Underwater hook: an eye below the surface looks up through it, so
        // this pass holds the world above the water instead.
        if (base.eyeUnderwater != 0)
            f.clipPlane = glm::vec4(0.0f, 1.0f, 0.0f, float(scene.reflection.clipOffset_m));
        setViewport(f, scaled);
        notify(true, "refraction");
        bindFrame(PassRefraction, f);
        beginPass(refraction.framebuffer(), passViewport, v.depth, glm::vec4(0.0f));
        glEnable(GL_CLIP_DISTANCE0);
        drawGeometry(PassKind::Refraction, ownWorld, options.geometry, view, PassRefraction, f,
                     refraction.framebuffer(), passViewport);
        glDisable(GL_CLIP_DISTANCE0);
        notify(false, "refraction");

        // Pass 2: the world (Swell's frame only: a host drew its own), the
        // water depth-tested against it, so objects crossing the surface meet
        // it cleanly; the sky last, only where nothing else was drawn (its
        // depth test passes at the far plane alone), so its shader runs on
        // the visible sky's pixels only.
        f = base;
        f.passEncodesSrgb = options.encoding == OutputEncoding::Srgb ? 1 : 0;
        // The waterline mask is drawn at the main pass's size, so the main
        // pass (multisampled or not) reads it on the same pixel grid.
        const WaveReach reach = simulatedReach();
        const NearPlaneMedium medium = nearPlaneMedium(nearPlaneCorners(glm::inverse(v.viewProj), v.depth.nearNdcZ), reach);
        drawWaterline(medium, v);
        glBindTextureUnit(SWELL_UNIT_WATERLINE, waterline.texture());
        const bool inAir = medium == NearPlaneMedium::Air;
        own.setMainPassInAir(inAir);
        notify(true, "main");
        GLuint mainFramebuffer = framebuffer;
        glm::ivec4 mainViewport = view.viewport;
        if (ownsFrame) {
            mainFramebuffer = mainTarget.begin(size, outputSize, framebuffer, scene.antialiasing);
            mainViewport = glm::ivec4(0, 0, size);
        }
        f.viewportOrigin = glm::vec2(mainViewport.x, mainViewport.y);
        bindFrame(PassMain, f);
        beginPass(mainFramebuffer, mainViewport, v.depth,
                  ownsFrame ? std::optional<glm::vec4>(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)) : std::nullopt);
        if (ownsFrame) {
            drawGeometry(PassKind::Main, ownWorld, options.geometry, view, PassMain, f, mainFramebuffer, mainViewport);
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            drawGeometry(PassKind::WaterMask, ownWorld, options.geometry, view, PassMain, f, mainFramebuffer,
                         mainViewport);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        } else {
            // The host's geometry seen from below the water: fogged by it,
            // as Swell's own is (before Swell's own is drawn in).
            if (medium != NearPlaneMedium::Air)
                fogHostUnderwater(framebuffer, mainViewport, v.depth);
        }
        if (!ownsFrame && ownWorld) {
            // The host drew its opaque scene; Swell's own world joins it.
            drawGeometry(PassKind::Main, ownWorld, nullptr, view, PassMain, f, mainFramebuffer, mainViewport);
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            drawGeometry(PassKind::WaterMask, ownWorld, nullptr, view, PassMain, f, mainFramebuffer, mainViewport);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        }
        notify(true, "water");
        drawWater(inAir);
        notify(false, "water");
        if (ownsFrame || options.sky)
            drawSky(inAir, v.depth);
        notify(false, "main");

        // The MSAA resolve, the FXAA filter and the render scale's filtering.
        if (ownsFrame && mainTarget.presents()) {
            notify(true, "present");
            glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
            mainTarget.present(programs.fxaa, emptyVao.id());
            notify(false, "present");
        }
    }

    // The underwater pass over the host's geometry (underwater_host.frag):
    // on its copied depth, blending in-scattering and transmittance.
    void fogHostUnderwater(GLuint framebuffer, glm::ivec4 viewport, const DepthConvention& depth)
    {
        notify(true, "underwater host");
        const GLuint copy = hostDepth.copy(framebuffer, viewport);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        setPassState(viewport, depth);
        glDisable(GL_DEPTH_TEST);
        glDepthMask(GL_FALSE);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_SRC1_COLOR);
        programs.underwaterHost.use();
        glBindTextureUnit(SWELL_UNIT_HOST_DEPTH, copy);
        glBindVertexArray(emptyVao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        ++counters.drawCalls;
        glDisable(GL_BLEND);
        setPassState(viewport, depth);
        notify(false, "underwater host");
    }

    void requireSimulation() const
    {
        if (!simulated)
            throw Error("nothing to draw yet: call advanceTo() with the frame's time before draw()");
    }

    // Draws a view with the GL state put back afterwards, whatever happens.
    void drawRestoring(const View& view, GLuint framebuffer, const DrawOptions& options, bool ownsFrame,
                       glm::ivec2 outputSize)
    {
        const SavedGlState saved;
        try {
            drawView(view, framebuffer, options, ownsFrame, outputSize);
        } catch (...) {
            saved.restore();
            throw;
        }
        saved.restore();
    }

    void render(const Camera& camera, double time_s, glm::ivec2 outputSize, GLuint framebuffer)
    {
        counters = {};
        if (outputSize.x <= 0 || outputSize.y <= 0)
            return;
        advanceTo(time_s, camera.position_m);
        DrawOptions options;
        options.sceneWorld = true;
        options.sky = true;
        drawRestoring(viewOf(camera, scaledFrameSize(outputSize, renderScale)), framebuffer, options, true, outputSize);
    }

    // Makes `next` the scene and `nextSceneModel` (when given) its model,
    // rebuilding what `effects` and a changed model file ask for. Everything
    // that can fail is built first; the renderer changes only when all did.
    void apply(const Scene& next, ParameterEffect effects, std::shared_ptr<const WaveModel> nextSceneModel,
               std::shared_ptr<const WaveModel> nextOverride, bool first,
               std::vector<std::shared_ptr<const SurfaceSource>> nextHostSources)
    {
        const std::shared_ptr<const WaveModel>& nextModelPtr = nextOverride ? nextOverride : nextSceneModel;
        const WaveModel& nextModel = *nextModelPtr;
        const bool modelChanged = first || &nextModel != &model();
        std::unique_ptr<WaveModelGpu> gpu = modelChanged ? nextModel.createGpu(sources) : nullptr;
        const ShaderVariant nextVariant = shaderVariantOf(next, gpu ? gpu->shaderFile() : variant.oceanFile, omittedWaterTerms,
                                                          sourceCodes(next, nextHostSources));
        const bool programsChanged = first || nextVariant != variant;
        Programs nextPrograms;
        if (programsChanged) {
            try {
                nextPrograms = buildPrograms(sources, nextVariant);
            } catch (...) {
                // The files of the sources still drawn, for a later reload.
                setSurfaceSourceFiles(sources, variant.surfaceSources);
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
            seaMeanSquareSlope = meanSquareSlope(model());
        }
        if (programsChanged) {
            variant = nextVariant;
            programs = std::move(nextPrograms);
        }
        if (worldChanged) {
            world = std::move(nextWorld);
            bakedSky.reset();
        }
        hostSources = std::move(nextHostSources);
        if (bodiesChanged) {
            bodies = std::move(nextBodies);
            bodyModel = std::move(nextBodyModel);
            queryBodies.reset();
        }
        // What was simulated was for the scene before (the poses of objects
        // that float without being bodies follow their positions): the next
        // advanceTo() takes it again, at no cost where nothing moved.
        simulated.reset();
        if (first || hasEffect(effects, ParameterEffect::Grid))
            buildGrid();
    }
};

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
    s.programs = buildPrograms(s.sources, s.variant);
    s.bakedSky.reset(); // the bake shader may have changed
}

void Renderer::advanceTo(double time_s, glm::dvec3 viewpoint_m)
{
    if (!std::isfinite(time_s) || !std::isfinite(viewpoint_m.x + viewpoint_m.y + viewpoint_m.z))
        throw Error(fmt::format("advanceTo: the time ({}) and the viewpoint must be finite", time_s));
    impl_->advanceTo(time_s, viewpoint_m);
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
