// The ocean renderer: owns the GPU state of a scene and draws its passes.
// Programs are render/programs.*, the world's assets and poses
// render/world.*, the shared uniforms render/frame_uniforms.*; the surface
// comes from a swell::WaveModel, never from a particular model.
#include "swell/renderer.h"

#include "render/frame_uniforms.h"
#include "render/programs.h"
#include "render/render_target.h"
#include "render/sky_cubemap.h"
#include "render/slope_statistics.h"
#include "render/wake_texture.h"
#include "render/water_grid.h"
#include "render/waterline.h"
#include "render/wave_model_gpu.h"
#include "render/world.h"
#include "swell/error.h"
#include "swell/gl/shader.h"
#include "swell/grid.h"
#include "swell/scene_changes.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <optional>
#include <string>

namespace swell {

using namespace detail;

namespace {

enum Pass { PassReflection = 0, PassRefraction = 1, PassMain = 2, PassCount = 3 };

} // namespace

struct Renderer::Impl {
    Scene scene;
    // The scene's wave model, and the one setWaveModel() put in its place.
    std::shared_ptr<const WaveModel> sceneModel, overrideModel;
    std::unique_ptr<WaveModelGpu> modelGpu;
    double seaMeanSquareSlope = 0.0; // of model(), for the reflection's masking (slope_statistics.h)
    GridShape gridShape;
    gl::ShaderSources sources;
    // Water shading terms left out, for the benchmark (RendererOptions).
    unsigned omittedWaterTerms = 0;
    ShaderVariant variant;
    Programs programs;
    // Whether the pass being drawn has no pixel that looks out from below the
    // water, so the programs without underwater shading draw it (programs.h).
    bool passInAir = true;
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
    // This frame's object transforms, one per scene object (see world.h).
    std::vector<glm::mat4> poses;
    // The floating rigid bodies, stepped to each frame's time (objects/scene_bodies.h),
    // and their wake; stepped by drawnSurface() too, which is const to callers.
    mutable SceneBodies bodies;
    // The wake as the last frame (or drawnSurface() query) drew it, at wakeFrameTime_s.
    mutable std::shared_ptr<const WakeFrame> wakeFrame;
    mutable double wakeFrameTime_s = -1.0;
    WakeTexture wakeTexture;
    double wakeReach_m = 0.0; // the largest wake height this frame, m
    glm::dvec3 posesOrigin{0.0}; // the render origin poses are relative to

    explicit Impl(RendererOptions options)
        : sources(std::move(options.shaders)), omittedWaterTerms(options.omittedWaterTerms)
    {
    }

    const WaveModel& model() const { return overrideModel ? *overrideModel : *sceneModel; }

    // How far this frame's surface can move from rest: the model's reach,
    // and the wake's height above it (wakeReach_m, set by prepareFrame).
    WaveReach frameReach() const
    {
        WaveReach reach = model().reach();
        reach.vertical_m += wakeReach_m;
        return reach;
    }

    // The bodies' wake at time_s (null when the scene has none), stepping
    // the bodies there: it depends on time_s alone.
    std::shared_ptr<const WakeFrame> wakeAt(double time_s) const
    {
        bodies.advanceTo(time_s);
        if (!bodies.wake())
            return nullptr;
        if (!wakeFrame || wakeFrameTime_s != time_s) {
            wakeFrame = std::make_shared<const WakeFrame>(bodies.wakeFrameAt(time_s));
            wakeFrameTime_s = time_s;
        }
        return wakeFrame;
    }

    // The water as the grid draws it for this camera (swell/drawn_surface.h).
    DrawnSurface drawnSurface(const Camera& camera, double time_s) const
    {
        return DrawnSurface(model(), gridShape, horizonFadeFor(scene.grid, gridShape), camera.position_m, time_s,
                            wakeAt(time_s));
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

    // Per-frame setup shared by drawing and capture: the render origin is the
    // camera's x,z; the surface is phased at the snapped grid centre; object
    // poses are computed; the water tiles in view are chosen.
    FrameUniforms prepareFrame(const Camera& camera, double time_s, glm::ivec2 size, glm::dvec3& origin)
    {
        origin = glm::dvec3(camera.position_m.x, 0.0, camera.position_m.z);
        const GridPlacement grid = placeGrid(gridShape, camera.position_m);
        // The wave model's own work for the frame (the spectral model's FFTs).
        notify(true, "ocean");
        modelGpu->prepareFrame(grid.center_m, time_s);
        modelGpu->bind();
        counters.oceanTransforms = modelGpu->lastWork().transforms;
        counters.foamSteps = modelGpu->lastWork().foamSteps;
        notify(false, "ocean");
        const glm::dmat4 viewProj = camera.projection(double(size.x) / double(size.y)) * camera.viewRelativeTo(origin);
        FrameUniforms f = frameUniforms(scene, gridShape, grid, camera, viewProj, origin, size);
        f.waveHeightDeviation_m = float(model().heightDeviation_m());
        f.waveMeanSquareSlope = float(seaMeanSquareSlope);
        // Bodies step on the CPU to this frame's time: fixed steps, so the
        // poses depend on time_s alone, never on the frames before. Their
        // wake steps with them (the cost of its steps counted apart).
        notify(true, "bodies");
        const std::int64_t stepsBefore = bodies.stepsTaken(), wakeStepsBefore = bodies.wakeStepsTaken();
        const double wakeBefore_ms = bodies.wakeSteps_ms();
        const std::shared_ptr<const WakeFrame> wake = wakeAt(time_s);
        const DrawnSurface drawn = drawnSurface(camera, time_s);
        poses = objectPoses(scene, model(), drawn, bodies, origin, time_s);
        counters.floatingBodies = int(bodies.count());
        counters.bodySteps = bodies.stepsTaken() - stepsBefore;
        counters.wakeSteps = bodies.wakeStepsTaken() - wakeStepsBefore;
        counters.wakeSteps_ms = bodies.wakeSteps_ms() - wakeBefore_ms;
        notify(false, "bodies");
        // The wake's frame: blended, its slopes found and uploaded.
        notify(true, "wake");
        wakeTexture.upload(wake.get(), origin);
        wakeTexture.bind();
        // The wake raises and lowers the water beyond the waves' reach: the
        // grid's tiles are culled, and the near plane placed, with it.
        wakeReach_m = 0.0;
        if (wake)
            for (const glm::vec4& texel : wake->texels)
                wakeReach_m = std::max(wakeReach_m, double(std::abs(texel.x)));
        const WaveReach reach = frameReach();
        notify(false, "wake");
        // What the waterline mask's rays that meet no water are judged by
        // (shaders/underwater.glsl): the band the surface stays in, and the
        // eye's own side of it.
        f.waveReachVertical_m = float(reach.vertical_m);
        f.eyeUnderwater = eyeUnderwater(camera, model(), time_s) ? 1 : 0;
        posesOrigin = origin;
        f.worldBoxCount = worldBoxes(world, scene, reach, origin, poses, f.worldBoxes);
        waterGrid.cull(gridShape, grid, reach, viewProj, grid.center_m - glm::dvec2(origin.x, origin.z));
        return f;
    }

    void bindFrame(Pass pass, const FrameUniforms& f)
    {
        glNamedBufferSubData(frameUbo[pass].id(), 0, sizeof(f), &f);
        glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_FRAME, frameUbo[pass].id());
    }

    const MeshProgram& meshProgram() const { return passInAir ? programs.meshInAir : programs.mesh; }

    void drawWorld(glm::dvec3 origin)
    {
        const MeshProgram& mesh = meshProgram();
        mesh.use();
        const GpuMesh& island = world.island;
        if (island.indexCount() > 0) {
            mesh.setModel(glm::mat4(glm::translate(glm::dmat4(1.0), kIslandPosition_m - origin)));
            island.draw();
            counters.worldTriangles += island.indexCount() / 3;
            ++counters.drawCalls;
        }
        for (size_t i = 0; i < world.meshes.size(); ++i) {
            mesh.setModel(poses[i]);
            world.meshes[i]->draw();
            counters.worldTriangles += world.meshes[i]->indexCount() / 3;
            ++counters.drawCalls;
        }
    }

    // Pass 3's clean intersections: each open hull's closed volume is drawn
    // into depth only, after the world and before the water. Its outer surface
    // coincides with the hull's, so only its lid at the gunwale changes the
    // depth buffer: a ray into the open hull meets the lid before the water
    // inside, and that water fails the depth test. (The reflection and
    // refraction passes draw no water, so they need no mask.)
    void drawHullVolumes()
    {
        const MeshProgram& mesh = meshProgram();
        mesh.use();
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        for (size_t i = 0; i < world.hullVolumes.size(); ++i)
            if (world.hullVolumes[i]) {
                mesh.setModel(poses[i]);
                world.hullVolumes[i]->draw();
                ++counters.drawCalls;
            }
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }

    void drawSky()
    {
        (passInAir ? programs.skyInAir : programs.sky).use();
        glBindTextureUnit(SWELL_UNIT_SKY, world.skyCube.id());
        glDepthFunc(GL_LEQUAL);
        glDepthMask(GL_FALSE);
        glBindVertexArray(emptyVao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        ++counters.drawCalls;
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LESS);
    }

    void drawWater()
    {
        (passInAir ? programs.waterInAir : programs.water).use();
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
    // waves, else cleared to the side it lies on. Expects the main pass's
    // frame uniforms bound.
    void drawWaterline(NearPlaneMedium medium, glm::ivec2 size)
    {
        waterline.resize(size);
        if (medium != NearPlaneMedium::Both) {
            waterline.fill(medium);
            return;
        }
        notify(true, "waterline");
        beginPass(waterline.framebuffer(), size, glm::vec4(SWELL_WATERLINE_NO_HIT));
        glBindTextureUnit(SWELL_UNIT_WATERLINE, waterline.allAbove()); // never the target itself
        programs.waterline.use();
        wakeTexture.bind();
        glBindVertexArray(waterGrid.vertexArray());
        waterGrid.draw();
        ++counters.drawCalls;
        notify(false, "waterline");
    }

    // Every pass sets all the state it depends on, so passes can be reordered.
    void beginPass(GLuint framebuffer, glm::ivec2 size, glm::vec4 clear)
    {
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glViewport(0, 0, size.x, size.y);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
        glDisable(GL_SCISSOR_TEST);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        // The shaders write display-ready (sRGB-encoded) colour: a host that
        // enabled sRGB writes would have it encoded twice.
        glDisable(GL_FRAMEBUFFER_SRGB);
        // Filter across cubemap face edges (off by default even in core profiles).
        glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
        glClearColor(clear.r, clear.g, clear.b, clear.a);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }

    void render(const Camera& camera, double time_s, glm::ivec2 outputSize, GLuint framebuffer)
    {
        counters = {};
        if (outputSize.x <= 0 || outputSize.y <= 0)
            return;
        // Every pass works at the render scale; present() brings the main
        // pass's image to the output's size.
        const glm::ivec2 size = scaledFrameSize(outputSize, renderScale);
        glm::dvec3 origin;
        const FrameUniforms base = prepareFrame(camera, time_s, size, origin);
        // The procedural sky is baked into the cubemap when first needed and
        // after the sun or sky changed (the bake reads the frame uniforms).
        if (scene.sky.cubemapFaces.empty() && bakedSky != skyBakeKeyOf(scene)) {
            bindFrame(PassMain, base);
            bakeProceduralSky(programs.skyBake, world.skyCube, emptyVao.id());
            bakedSky = skyBakeKeyOf(scene);
        }
        const glm::ivec2 scaled = glm::max(glm::ivec2(glm::dvec2(size) * scene.reflection.resolutionScale), glm::ivec2(1));
        reflection.resize(scaled);
        refraction.resize(scaled);
        // Passes before the main one see nothing from below the water.
        waterline.resize(size);
        glBindTextureUnit(SWELL_UNIT_WATERLINE, waterline.allAbove());
        passInAir = true;

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
        beginPass(reflection.framebuffer(), scaled, glm::vec4(0.0f));
        glEnable(GL_CLIP_DISTANCE0);
        // The mirror turns every triangle's winding around on screen: without
        // this the faces seen would count as back faces, and mesh.frag, which
        // turns a back face's normal round, would light each object's
        // reflection from the wrong side (a dark rock mirrored pale).
        glFrontFace(GL_CW);
        drawWorld(origin);
        glFrontFace(GL_CCW);
        drawSky();
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
        beginPass(refraction.framebuffer(), scaled, glm::vec4(0.0f));
        drawWorld(origin);
        glDisable(GL_CLIP_DISTANCE0);
        notify(false, "refraction");

        // Pass 2: world, then the water depth-tested against it, so objects
        // crossing the surface meet it cleanly; the sky last, only where
        // nothing else was drawn (its depth test passes at the far plane
        // alone), so its shader runs on the visible sky's pixels only.
        f = base;
        f.passEncodesSrgb = 1;
        bindFrame(PassMain, f);
        // The waterline mask is drawn at the main pass's size, so the main
        // pass (multisampled or not) reads it on the same pixel grid.
        const NearPlaneMedium medium = nearPlaneMedium(camera, double(size.x) / double(size.y), frameReach());
        drawWaterline(medium, size);
        glBindTextureUnit(SWELL_UNIT_WATERLINE, waterline.texture());
        passInAir = medium == NearPlaneMedium::Air;
        notify(true, "main");
        const GLuint mainFramebuffer = mainTarget.begin(size, outputSize, framebuffer, scene.antialiasing);
        beginPass(mainFramebuffer, size, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
        drawWorld(origin);
        drawHullVolumes();
        notify(true, "water");
        drawWater();
        notify(false, "water");
        drawSky();
        notify(false, "main");

        // The MSAA resolve, the FXAA filter and the render scale's filtering.
        if (mainTarget.presents()) {
            notify(true, "present");
            mainTarget.present(programs.fxaa, emptyVao.id());
            notify(false, "present");
        }
        glBindVertexArray(0);
        glUseProgram(0);
    }

    // Makes `next` the scene and `nextSceneModel` (when given) its model,
    // rebuilding what `effects` and a changed model file ask for. Everything
    // that can fail is built first; the renderer changes only when all did.
    void apply(const Scene& next, ParameterEffect effects, std::shared_ptr<const WaveModel> nextSceneModel,
               std::shared_ptr<const WaveModel> nextOverride, bool first)
    {
        const WaveModel& nextModel = nextOverride ? *nextOverride : *nextSceneModel;
        const bool modelChanged = first || &nextModel != &model();
        std::unique_ptr<WaveModelGpu> gpu = modelChanged ? nextModel.createGpu(sources) : nullptr;
        const ShaderVariant nextVariant = shaderVariantOf(next, gpu ? gpu->shaderFile() : variant.oceanFile, omittedWaterTerms);
        const bool programsChanged = first || nextVariant != variant;
        Programs nextPrograms;
        if (programsChanged)
            nextPrograms = buildPrograms(sources, nextVariant);
        const bool worldChanged = first || hasEffect(effects, ParameterEffect::World);
        World nextWorld;
        if (worldChanged)
            nextWorld = buildWorld(next);
        // Bodies start again from their start when what moves them changed.
        const bool bodiesChanged = worldChanged || modelChanged || !sameBodies(scene, next);
        SceneBodies nextBodies;
        if (bodiesChanged)
            nextBodies = buildBodies(worldChanged ? nextWorld : world, next, nextModel);

        scene = next;
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
        if (bodiesChanged) {
            bodies = std::move(nextBodies);
            wakeFrame.reset();
        }
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
    impl_->apply(scene, ParameterEffect::Frame, makeWaveModel(scene), nullptr, true);
}

Renderer::~Renderer() = default;

void Renderer::setScene(const Scene& scene)
{
    Impl& s = *impl_;
    const ParameterEffect effects = sceneChanges(s.scene, scene);
    // The waves are generated again only when a wave parameter changed.
    std::shared_ptr<const WaveModel> sceneModel =
        hasEffect(effects, ParameterEffect::Waves) ? makeWaveModel(scene) : s.sceneModel;
    s.apply(scene, effects, std::move(sceneModel), s.overrideModel, false);
}

const Scene& Renderer::scene() const { return impl_->scene; }
const WaveModel& Renderer::waveModel() const { return impl_->model(); }

void Renderer::setWaveModel(std::shared_ptr<const WaveModel> model)
{
    Impl& s = *impl_;
    s.apply(s.scene, ParameterEffect::Frame, s.sceneModel, std::move(model), false);
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
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(impl_->output.color(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(bottomUp.size()), bottomUp.data());
    const size_t row = size_t(size.x) * 4;
    for (int y = 0; y < size.y; ++y)
        std::copy_n(&bottomUp[size_t(size.y - 1 - y) * row], row, &image.rgba[size_t(y) * row]);
    return image;
}

std::vector<glm::dmat4> Renderer::objectTransforms() const
{
    std::vector<glm::dmat4> out;
    for (const glm::mat4& pose : impl_->poses)
        out.push_back(glm::translate(glm::dmat4(1.0), impl_->posesOrigin) * glm::dmat4(pose));
    return out;
}

DrawnSurface Renderer::drawnSurface(const Camera& camera, double time_s) const
{
    const Impl& s = *impl_;
    return s.drawnSurface(camera, time_s);
}

int Renderer::waterVertexCount() const { return (impl_->gridShape.cells + 1) * (impl_->gridShape.cells + 1); }

int Renderer::captureWaterVertices(const Camera& camera, double time_s, unsigned buffer, glm::ivec2 size,
                                   std::vector<std::uint32_t>* drawnIndices)
{
    Impl& s = *impl_;
    glm::dvec3 origin;
    s.bindFrame(PassMain, s.prepareFrame(camera, time_s, glm::max(size, glm::ivec2(1)), origin));
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
    glDisable(GL_RASTERIZER_DISCARD);
    glUseProgram(0);
    return count;
}

} // namespace swell
