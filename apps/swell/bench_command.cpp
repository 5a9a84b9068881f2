// `swell bench`: renders a scene (the default one unless named) headless along a fixed camera path
// and reports, for each pass, its wall time, what the driver counted, its cost
// relative to a floor frame with trivial shading, and how well the water
// grid's level of detail fits the view. docs/PERFORMANCE.md explains the figures.
#include "bench.h"
#include "commands.h"
#include "progress.h"
#include "scene_loading.h"

#include "swell/dataset/flow.h"
#include "swell/dataset/sensor.h"
#include "swell/debug.h"
#include "swell/error.h"
#include "swell/gl/context.h"
#include "swell/renderer.h"
#include "swell/scene/parameters.h"
#include "swell/scene/scene.h"
#include "swell/view.h"

#include <epoxy/gl.h>
#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <unistd.h>

namespace swell::app {

namespace bench {

namespace {

namespace fs = std::filesystem;

// Simulation time between frames, s.
constexpr double kFrameStep_s = 1.0 / 60.0;
// Frames of the floor drawn and discarded before its measured ones (at most
// --warmup): it has no caches to fill beyond its first frame.
constexpr int kFloorWarmup = 3;
// Where on the path the LOD is measured: the default view, the far side of
// the circle, half way up the climb, near its top, the grazing pass.
constexpr std::array<double, 5> kLodPathPoints{0.0, 0.25, 0.625, 0.74, 0.875};

double smoothstep01(double x)
{
    x = std::clamp(x, 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
}

// The benchmark's camera path at s in [0, 1). Measured frame k of n sits at
// s = k / n, so any --frames walks the whole path (more frames sample it more
// finely); warm-up frames stand at s = 0. Field of view and clip planes are
// the scene's.
//
//   s 0    .. 0.5   a circle of radius 40 m at 6 m height, looking along the
//                   motion at pitch -5: it starts at the default camera's pose
//                   (0, 6, 0) looking along -z and turns right, so every
//                   heading is seen once, the island included
//   s 0.5  .. 0.75  a further quarter turn while climbing to 40 m and pitching
//                   down to -20
//   s 0.75 .. 1     a low grazing pass: 2 m up, pitch -1, 100 m in a straight
//                   line from (0, 2, 0) towards the island (yaw -22)
Camera pathCamera(const CameraSettings& settings, double s)
{
    constexpr double kRadius_m = 40.0, kLow_m = 6.0, kHigh_m = 40.0;
    Camera c = cameraAt(settings, 0.0);
    const double twoPi = 2.0 * glm::pi<double>();
    auto onCircle = [&](double angle, double height_m, double pitch_deg) {
        // Centre (R, h, 0); at angle 0 the camera is at (0, h, 0) heading -z.
        // (+ 0.0 turns a -0 into 0 for the table.)
        c.position_m = {kRadius_m - kRadius_m * std::cos(angle), height_m, -kRadius_m * std::sin(angle) + 0.0};
        c.yaw_deg = std::remainder(glm::degrees(angle), 360.0);
        c.pitch_deg = pitch_deg;
    };
    if (s < 0.5) {
        onCircle(twoPi * s / 0.5, kLow_m, -5.0);
    } else if (s < 0.75) {
        const double u = (s - 0.5) / 0.25, e = smoothstep01(u);
        onCircle(twoPi + 0.25 * twoPi * u, kLow_m + (kHigh_m - kLow_m) * e, -5.0 - 15.0 * e);
    } else {
        const double u = (s - 0.75) / 0.25;
        constexpr double kYaw_deg = -22.0, kLength_m = 100.0;
        const double yaw = glm::radians(kYaw_deg);
        c.position_m = glm::dvec3(std::sin(yaw), 0.0, -std::cos(yaw)) * (kLength_m * u) + glm::dvec3(0.0, 2.0, 0.0);
        c.yaw_deg = kYaw_deg;
        c.pitch_deg = -1.0;
    }
    return c;
}

// Throws swell::Error naming `stage` when GL has recorded an error.
void checkGl(const char* stage)
{
    const GLenum error = glGetError();
    if (error == GL_NO_ERROR)
        return;
    while (glGetError() != GL_NO_ERROR) {
    }
    throw Error(fmt::format("swell bench: GL error 0x{:04x} while {}", error, stage));
}

} // namespace

} // namespace bench

int benchRendersPerFrameWithTerms()
{
    // The frame, each term variant, and the two reflection lookups
    // (measureReflectionModes: fixed and raymarch).
    constexpr int kReflectionModes = 2;
    return 1 + int(bench::termVariants().size()) + kReflectionModes;
}

int runBench(const BenchOptions& options)
{
    using namespace bench;
    if (options.frames < 1 || options.warmup < 0)
        throw InputError({"--frames"}, "need at least one measured frame and no negative warm-up");
    if (!options.jsonPath.empty()) {
        // Found out now rather than after minutes of rendering.
        const fs::path folder = fs::absolute(options.jsonPath).parent_path();
        if (!fs::is_directory(folder) || ::access(folder.c_str(), W_OK) != 0)
            throw InputError({"--json"}, fmt::format("cannot write '{}': '{}' is not a writable folder",
                                                     options.jsonPath, folder.string()));
    }
    Scene scene = loadSceneOrDefault(options.scenePath);
    options.outputSettings.applyTo(scene);
    // No debug context: its checks would be part of what is measured. GL
    // errors are polled after each stage instead.
    gl::HeadlessContext context(false);
    Renderer renderer(scene);
    RendererTesting::setWaterInTwoPasses(renderer, !options.waterOnePass);
    renderer.setRenderScale(options.outputSettings.renderScale);
    renderer.setTemporalResolve(options.temporal);
    renderer.setInteractive(options.interactive);
    checkGl("creating the renderer");

    Results r;
    r.machine = describeMachine();
    r.size = {options.width, options.height};
    // The floor draws at the size the renderer's passes do.
    const glm::ivec2 drawSize = scaledFrameSize(r.size, options.outputSettings.renderScale);
    r.passSize = glm::max(glm::ivec2(glm::dvec2(drawSize) * scene.reflection.resolutionScale), glm::ivec2(1));
    r.surface = renderer.waveModel().summary();
    r.output = fmt::format("antialiasing {}, render scale {}{}{}{}",
                           options.temporal ? std::string("temporal resolve")
                                            : std::string(findParameter("antialiasing")->choices[size_t(scene.antialiasing)]),
                           options.outputSettings.renderScale, options.still ? ", the scene's camera (--still)" : "",
                           options.interactive ? ", interactive (--interactive)" : "",
                           options.labels ? ", the label pass after each frame (--labels)" : "");
    r.gridCells = int(std::lround(std::sqrt(double(RendererTesting::waterVertexCount(renderer))))) - 1;
    r.frames = options.frames;
    r.warmup = options.warmup;
    r.frameStep_s = kFrameStep_s;
    r.pipelineStatistics = epoxy_has_gl_extension("GL_ARB_pipeline_statistics_query");
    r.gpuTimers = !gl::isSoftwareRasterizer();

    const OffscreenTarget output = makeOffscreenTarget(r.size, GL_RGBA8);
    PassRecorder recorder(r.pipelineStatistics, r.gpuTimers, options.stages);
    renderer.setPassObserver(&recorder);
    checkGl("creating the benchmark's targets and queries");

    // The same scene with water shading terms left out, one renderer each,
    // each frame drawn right after the full frame of the same camera and time.
    if (options.terms)
        r.terms = termVariants();
    std::vector<std::unique_ptr<Renderer>> termRenderers;
    for (const TermVariant& t : r.terms) {
        termRenderers.push_back(RendererTesting::create(scene, {}, t.omitted));
        termRenderers.back()->setRenderScale(options.outputSettings.renderScale);
        RendererTesting::setWaterInTwoPasses(*termRenderers.back(), !options.waterOnePass);
        termRenderers.back()->setPassObserver(&recorder);
    }
    checkGl("creating the water term variants");

    const int floorWarmup = std::min(options.warmup, kFloorWarmup);
    // Progress counts frames of the camera path, each phase on its own, so
    // that "60/60" means the 60 measured frames (with --terms, each of them
    // rendered once more per term variant and reflection lookup).
    Progress progress(options.warmup > 0 ? fmt::format("warm-up ({}) and measured frames", options.warmup)
                                         : std::string("measured frames"),
                      options.warmup + options.frames);
    // The real frames: warm-up at the path's start, then the measured ones.
    std::optional<FrameLabels> previousLabels; // with --labels: the last frame's, for the flow
    // With --sensor, a renderer of its own: the sensor's draws span the
    // frame's time on both sides, and time going back for the frame's own
    // renderer would simulate its bodies again from their start.
    std::unique_ptr<Renderer> sensorRenderer;
    if (options.sensor) {
        sensorRenderer = std::make_unique<Renderer>(scene);
        sensorRenderer->setRenderScale(options.outputSettings.renderScale);
        r.sensorDraws = int(sensorTimingOf(scene.camera, 0.0, 0).drawTimes_s.size());
    }
    // With --motion-vectors, a renderer and a host's framebuffer of their
    // own (colour, RG16F motion vectors, depth), drawn as a host draws.
    std::unique_ptr<Renderer> motionRenderer;
    OffscreenTarget motionTarget;
    gl::Texture motionVectors;
    if (options.motionVectors) {
        motionRenderer = std::make_unique<Renderer>(scene);
        motionRenderer->setPassObserver(&recorder);
        motionTarget = makeOffscreenTarget(r.size, GL_RGBA8);
        motionVectors = gl::Texture::create(GLenum(GL_TEXTURE_2D));
        glTextureStorage2D(motionVectors.id(), 1, GL_RG16F, r.size.x, r.size.y);
        glNamedFramebufferTexture(motionTarget.framebuffer.id(), GL_COLOR_ATTACHMENT1, motionVectors.id(), 0);
        checkGl("creating the motion vectors' target");
    }
    for (int i = 0; i < options.warmup + options.frames; ++i) {
        const bool measured = i >= options.warmup;
        const int k = i - options.warmup;
        const double t = double(i) * kFrameStep_s;
        const Camera camera = options.still ? cameraAt(scene.camera, t)
                                            : pathCamera(scene.camera, measured ? double(k) / double(options.frames) : 0.0);
        FrameSample frame = recorder.recordFrame([&] { renderer.render(camera, t, r.size, output.framebuffer.id()); });
        checkGl("rendering a frame");
        // The frame's own counts, before a label pass adds its view's
        // culling and draws to them.
        const FrameCounters counters = renderer.counters();
        // The label pass before the bodies' worker starts on the next frame,
        // so that it does not share the cores with it (`swell dataset` has no
        // next frame).
        std::optional<FrameSample> labels, flow;
        if (options.labels) {
            FrameLabels frameLabels;
            labels = recorder.recordFrame([&] {
                recorder.beginPass(kLabelsPass);
                frameLabels = renderer.renderLabels(camera, r.size);
                recorder.endPass(kLabelsPass);
            });
            checkGl("drawing the label pass");
            if (previousLabels)
                flow = recorder.recordFrame([&] {
                    recorder.beginPass(kFlowPass);
                    const double previous_s = double(i - 1) * kFrameStep_s;
                    (void)opticalFlowOf(*previousLabels, previous_s, frameLabels, t - previous_s,
                                        seaMotionOf(renderer.scene(), renderer.waveModel()));
                    recorder.endPass(kFlowPass);
                });
            previousLabels = std::move(frameLabels);
        }
        std::optional<FrameSample> sensor;
        if (options.sensor) {
            sensor = recorder.recordFrame([&] {
                recorder.beginPass(kSensorPass);
                (void)renderSensorFrame(*sensorRenderer, camera, t, r.size, false);
                recorder.endPass(kSensorPass);
            });
            checkGl("drawing the frame through the sensor");
        }
        std::optional<FrameSample> motion;
        if (motionRenderer) {
            const float far = 1.0f, none[4] = {0.0f, 0.0f, 0.0f, 1.0f};
            glClearNamedFramebufferfv(motionTarget.framebuffer.id(), GL_COLOR, 0, none);
            glClearNamedFramebufferfv(motionTarget.framebuffer.id(), GL_DEPTH, 0, &far);
            motion = recorder.recordFrame([&] {
                motionRenderer->advanceTo(t, camera.position_m);
                DrawOptions draw;
                draw.sceneWorld = true;
                draw.motionVectors = GL_COLOR_ATTACHMENT1;
                motionRenderer->draw(viewOf(camera, r.size), motionTarget.framebuffer.id(), draw);
            });
            checkGl("drawing the frame with motion vectors");
        }
        // As a video does (`swell render`): the bodies step towards the
        // next frame on their own thread meanwhile (Renderer::anticipate).
        renderer.anticipate(double(i + 1) * kFrameStep_s);
        if (measured) {
            r.real.push_back(std::move(frame));
            if (labels)
                r.labels.push_back(std::move(*labels));
            if (flow)
                r.flow.push_back(std::move(*flow));
            if (sensor)
                r.sensor.push_back(std::move(*sensor));
            if (motion) {
                r.motionVectors.push_back(std::move(*motion));
                r.motionVectorCounters.push_back(motionRenderer->counters());
            }
            r.realTimes_s.push_back(t);
            r.bodySteps.push_back(counters.bodySteps);
            r.wakeSteps.push_back(counters.wakeSteps);
            r.wakeSteps_ms.push_back(counters.wakeSteps_ms);
            r.counters.push_back(counters);
            r.floatingBodies = counters.floatingBodies;
            r.realCameras.push_back(camera);
        }
        for (size_t v = 0; v < termRenderers.size(); ++v) {
            FrameSample variant = recorder.recordFrame(
                [&] { termRenderers[v]->render(camera, t, r.size, output.framebuffer.id()); });
            checkGl("rendering a frame with a water term left out");
            if (measured)
                r.terms[v].frames.push_back(std::move(variant));
        }
        progress.advance();
    }
    progress.finish();
    termRenderers.clear();
    renderer.setPassObserver(nullptr);

    // The floor: the same passes at the same sizes with trivial shading.
    const bool presents = scene.antialiasing != Antialiasing::Off || drawSize != r.size;
    // Its water in two passes where the real frames' was (not with MSAA,
    // nor with --water-one-pass).
    const bool waterInTwoPasses = !r.real.empty() && r.real.front().find("water shading") != nullptr;
    FloorFrame floorFrame(r.passSize, drawSize, r.size, presents, waterInTwoPasses);
    Progress floorProgress("floor frames (trivial shading)", floorWarmup + options.frames);
    for (int i = 0; i < floorWarmup + options.frames; ++i) {
        FrameSample frame = recorder.recordFrame([&] { floorFrame.render(recorder, i % 2 == 0); });
        checkGl("rendering the floor");
        if (i >= floorWarmup)
            r.floor.push_back(std::move(frame));
        floorProgress.advance();
    }
    floorProgress.finish();
    if (options.terms) {
        r.reflectionModes = measureReflectionModes(scene, recorder, options.frames, r.size, output.framebuffer.id(),
                                                   r.realCameras, r.realTimes_s);
        checkGl("comparing the reflection lookups");
    }

    // The water grid's LOD at a few frames of the path, from the vertices
    // the water shader produces for the same camera and time.
    const int vertexCount = RendererTesting::waterVertexCount(renderer);
    gl::Buffer capture = gl::Buffer::create();
    glNamedBufferStorage(capture.id(), GLsizeiptr(vertexCount) * 8 * GLsizeiptr(sizeof(float)), nullptr, 0);
    std::vector<float> vertices(size_t(vertexCount) * 8);
    std::vector<int> lodFrames;
    for (const double s : kLodPathPoints) {
        const int k = std::min(options.frames - 1, int(std::floor(s * options.frames)));
        if (std::find(lodFrames.begin(), lodFrames.end(), k) == lodFrames.end())
            lodFrames.push_back(k);
    }
    const double aspect = double(r.size.x) / double(r.size.y);
    std::vector<std::uint32_t> triangles;
    for (const int k : lodFrames) {
        const Camera& camera = r.realCameras[size_t(k)];
        const int count = RendererTesting::captureWaterVertices(renderer, camera, r.realTimes_s[size_t(k)],
                                                                capture.id(), r.size, &triangles);
        glGetNamedBufferSubData(capture.id(), 0, GLsizeiptr(count) * 8 * GLsizeiptr(sizeof(float)), vertices.data());
        checkGl("capturing the water's vertices");
        const glm::dvec3 origin(camera.position_m.x, 0.0, camera.position_m.z);
        const glm::dmat4 viewProj = camera.projection(aspect) * camera.viewRelativeTo(origin);
        LodSample lod = measureLod(vertices, count, triangles, viewProj, r.size);
        lod.frame = k;
        lod.camera = camera;
        // The grid's triangles: the visibility pass's when the water is
        // drawn in two (the shading pass's are its tiles' points).
        const PassSample* grid = r.real[size_t(k)].find("water visibility");
        if (const PassSample* water = grid ? grid : r.real[size_t(k)].find("water"); water && r.pipelineStatistics) {
            lod.clipInput = water->counters.clippingInputPrimitives;
            lod.clipOutput = water->counters.clippingOutputPrimitives;
            if (lod.clipInput > 0)
                lod.clipShare = double(lod.clipOutput) / double(lod.clipInput);
        }
        r.lod.push_back(lod);
    }

    printReport(r);
    printTermReport(r);
    if (!options.terms)
        std::printf("\n(swell bench --terms adds what each water shading term and each reflection lookup costs)\n");
    if (!options.jsonPath.empty()) {
        writeJson(r, options.jsonPath);
        std::fprintf(stderr, "swell bench: results written to %s\n", options.jsonPath.c_str());
    }
    return kExitOk;
}

} // namespace swell::app
