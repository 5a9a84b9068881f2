// The frame's own queries of the water (render/surface_probe.h) are answered
// on the GPU from what it draws, and equal what the CPU's DrawnSurface and
// wave model answer: each floating object stands on the drawn water within
// 1 mm and tilts with the exact surface's normal, for the spectral and the
// Gerstner model, with and without a surface source; and a frame asks the
// wave model's CPU queries nothing (for the spectral model, each new time's
// queries there cost every cascade's inverse FFTs).
#include "support/gl_test.h"

#include "swell/debug.h"
#include "swell/drawn_surface.h"
#include "swell/renderer.h"
#include "swell/scene/scene.h"
#include "swell/scene/scene_file.h"
#include "swell/surface_source.h"
#include "swell/wave_model.h"
#include "swell/wave_model_gpu.h"

#include <glm/geometric.hpp>

#include <atomic>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace {

class FrameQueries : public swell::test::GlTest {};

// A scene's objects replaced by small floating buoys (not rigid bodies) on
// rings round the camera, from 0.3 m to 400 m: near the eye, where the
// grid's cells are finest and the waves move vertices across several, and
// far out, where one cell holds many waves.
swell::Scene withBuoysAround(swell::Scene scene, glm::dvec3 eye_m)
{
    scene.objects.clear();
    const double radii_m[] = {0.3, 1.1, 2.7, 6.0, 13.0, 29.0, 61.0, 140.0, 400.0};
    int k = 0;
    for (double r : radii_m)
        for (int a = 0; a < 5; ++a, ++k) {
            swell::SceneObject buoy;
            buoy.path = "builtin:buoy";
            buoy.floats = true;
            const double angle = 2.399963 * k; // the golden angle: no two share a direction
            buoy.position_m = {eye_m.x + r * std::cos(angle), scene.sea.level_m, eye_m.z + r * std::sin(angle)};
            scene.objects.push_back(buoy);
        }
    return scene;
}

struct Agreement {
    int objects = 0;
    double worstHeight_m = 0.0;  // |pose height - drawn height|
    double worstTilt_rad = 0.0;  // the pose's up against the exact normal's half-way tilt
};

// The renderer's poses at time_s against the CPU's answers: the drawn water
// (Renderer::drawnSurface, the model's queries) under each object, and the
// tilt half way to the exact surface's normal there.
Agreement compare(swell::Renderer& renderer, const swell::Scene& scene, glm::dvec3 eye_m, double time_s)
{
    renderer.advanceTo(time_s, eye_m);
    const swell::FrameCounters counters = renderer.counters();
    // The viewpoint's side of the water is asked only within the waves' reach.
    const bool viewpointAsked = std::abs(eye_m.y - scene.sea.level_m) <= renderer.waveModel().reach().vertical_m;
    EXPECT_EQ(counters.queriesOnGpu, int(scene.objects.size()) + (viewpointAsked ? 1 : 0));
    EXPECT_EQ(counters.queriesOnCpu, 0) << "queries whose triangle lay beyond the GPU's block";
    const std::vector<glm::dmat4> poses = renderer.objectTransforms();
    const swell::DrawnSurface drawn = renderer.drawnSurface(eye_m);
    const swell::WaveModel& model = renderer.waveModel();
    Agreement out;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const swell::SceneObject& o = scene.objects[i];
        const glm::dvec2 at(o.position_m.x, o.position_m.z);
        const std::optional<swell::DrawnPoint> water = drawn.at(at);
        if (!water) {
            ADD_FAILURE() << "no drawn water under object " << i;
            continue;
        }
        ++out.objects;
        // Stands at its own height above the drawn water (both in the world's frame).
        const double expected_m = o.position_m.y - scene.sea.level_m + water->position_m.y;
        out.worstHeight_m = std::max(out.worstHeight_m, std::abs(poses[i][3].y - expected_m));
        const glm::dvec3 normal = model.surfaceAt(model.restPointUnder(at, time_s), time_s).normal;
        const glm::dvec3 up = glm::normalize(glm::mix(glm::dvec3(0.0, 1.0, 0.0), normal, 0.5));
        const glm::dvec3 poseUp = glm::normalize(glm::dvec3(poses[i][1]));
        out.worstTilt_rad = std::max(out.worstTilt_rad, std::acos(std::min(1.0, glm::dot(up, poseUp))));
    }
    return out;
}

// A model's GPU half that answers the frame's queries on the GPU whatever
// its model's CPU queries cost: the GPU's queries tested on Gerstner waves,
// whose CPU queries the renderer otherwise takes.
class AnsweringGpu final : public swell::WaveModelGpu {
public:
    explicit AnsweringGpu(std::unique_ptr<swell::WaveModelGpu> inner) : inner_(std::move(inner)) {}
    std::string shaderFile() const override { return inner_->shaderFile(); }
    void prepareFrame(glm::dvec2 centre_m, double time_s) override { inner_->prepareFrame(centre_m, time_s); }
    void prepareView(glm::dvec2 centre_m) override { inner_->prepareView(centre_m); }
    void bind() const override { inner_->bind(); }
    bool answersFrameQueries() const override { return true; }

private:
    std::unique_ptr<swell::WaveModelGpu> inner_;
};

// A model that draws and answers what `inner` does, counting the CPU
// queries asked of it; with answerOnGpu its GPU half answers the frame's
// queries (AnsweringGpu).
class ForwardingModel final : public swell::WaveModel {
public:
    ForwardingModel(std::shared_ptr<const swell::WaveModel> inner, bool answerOnGpu)
        : inner_(std::move(inner)), answerOnGpu_(answerOnGpu)
    {
    }
    std::string_view name() const override { return inner_->name(); }
    std::string summary() const override { return inner_->summary(); }
    swell::WaveReach reach() const override { return inner_->reach(); }
    double heightDeviation_m() const override { return inner_->heightDeviation_m(); }
    swell::SurfacePoint surfaceAt(glm::dvec2 r, double t, const swell::SurfaceFilter& f) const override
    {
        ++queries;
        return inner_->surfaceAt(r, t, f);
    }
    glm::dvec3 displacementAt(glm::dvec2 r, double t, const swell::SurfaceFilter& f) const override
    {
        ++queries;
        return inner_->displacementAt(r, t, f);
    }
    glm::dvec2 restPointUnder(glm::dvec2 p, double t, const swell::SurfaceFilter& f) const override
    {
        ++queries;
        return inner_->restPointUnder(p, t, f);
    }
    std::unique_ptr<swell::WaveModelGpu> createGpu(const swell::gl::ShaderSources& shaders) const override
    {
        std::unique_ptr<swell::WaveModelGpu> gpu = inner_->createGpu(shaders);
        if (answerOnGpu_)
            return std::make_unique<AnsweringGpu>(std::move(gpu));
        return gpu;
    }
    mutable std::atomic<long long> queries{0};

private:
    std::shared_ptr<const swell::WaveModel> inner_;
    bool answerOnGpu_;
};

// onGpu: the scene's model answers on the GPU (the spectral model does by
// itself; Gerstner waves are made to).
void expectAgreement(const std::string& preset, double time_s, std::shared_ptr<const swell::SurfaceSource> source = nullptr,
                     bool forceGpu = false)
{
    SCOPED_TRACE(preset);
    swell::Scene base = swell::loadScene(std::string(SWELL_SOURCE_DIR) + "/scenes/" + preset + ".toml");
    const glm::dvec3 eye_m = swell::cameraAt(base.camera, time_s).position_m;
    const swell::Scene scene = withBuoysAround(base, eye_m);
    swell::Renderer renderer(scene);
    if (forceGpu)
        renderer.setWaveModel(std::make_shared<ForwardingModel>(swell::makeWaveModel(scene), true));
    if (source)
        renderer.addSurfaceSource(source);
    const Agreement a = compare(renderer, scene, eye_m, time_s);
    EXPECT_EQ(a.objects, int(scene.objects.size()));
    EXPECT_LT(a.worstHeight_m, 1e-3);
    EXPECT_LT(a.worstTilt_rad, 5e-3);
    std::printf("%s: %d objects, worst height %.3g m, worst tilt %.3g rad\n", preset.c_str(), a.objects,
                a.worstHeight_m, a.worstTilt_rad);
}

TEST_F(FrameQueries, ObjectsStandOnTheDrawnWaterInTheSpectralStorm) { expectAgreement("storm", 20.0); }

TEST_F(FrameQueries, ObjectsStandOnTheDrawnWaterOfGerstnerWaves) { expectAgreement("calm", 7.5, nullptr, true); }

// Gerstner waves' CPU queries cost microseconds: the frame asks them, and
// the CPU does not wait for the GPU.
TEST_F(FrameQueries, GerstnerWavesAreAskedOnTheCpuWithoutWaitingForTheGpu)
{
    swell::Scene base = swell::loadScene(std::string(SWELL_SOURCE_DIR) + "/scenes/calm.toml");
    const glm::dvec3 eye_m = swell::cameraAt(base.camera, 7.5).position_m;
    const swell::Scene scene = withBuoysAround(base, eye_m);
    swell::Renderer renderer(scene);
    renderer.advanceTo(7.5, eye_m);
    const swell::FrameCounters counters = renderer.counters();
    EXPECT_EQ(counters.queriesOnGpu, 0);
    EXPECT_GE(counters.queriesOnCpu, int(scene.objects.size()));
    EXPECT_EQ(counters.simulationGpu.dispatches, 0);
}

// A host's source: a mound the probe must add as the vertex shader does.
class Mound final : public swell::SurfaceSource {
public:
    glm::dvec3 heightAt(glm::dvec2 p, double) const override
    {
        const glm::dvec2 d = p - centre_;
        const double h = 0.4 * std::exp(-glm::dot(d, d) / 50.0);
        return {h, -h * 2.0 * d.x / 50.0, -h * 2.0 * d.y / 50.0};
    }
    double reach_m(double) const override { return 0.4; }
    std::string glsl() const override
    {
        return "vec4 SWELL_SOURCE_FUNCTION(vec2 p_m, vec4 parameters[4])\n"
               "{\n"
               "    vec2 q = p_m - parameters[0].xy;\n"
               "    float h = 0.4 * exp(-dot(q, q) / 50.0);\n"
               "    return vec4(h, -h * 2.0 * q / 50.0, 0.0);\n"
               "}\n";
    }
    swell::SurfaceSourceParameters gpuParameters(double, glm::dvec3 origin) const override
    {
        return {glm::vec4(glm::vec2(centre_ - glm::dvec2(origin.x, origin.z)), 0.0f, 0.0f), glm::vec4(0.0f),
                glm::vec4(0.0f), glm::vec4(0.0f)};
    }

private:
    glm::dvec2 centre_{3.0, -2.0};
};

TEST_F(FrameQueries, ObjectsStandOnTheDrawnWaterWithASurfaceSource)
{
    expectAgreement("trade-wind", 20.0, std::make_shared<const Mound>());
}

// The storm (two floating objects, no rigid bodies): after the first frame,
// frames at new times and viewpoints draw without a single CPU query of the
// wave model. The frame answered its queries with the model's before.
TEST_F(FrameQueries, AFrameAsksTheWaveModelsCpuQueriesNothing)
{
    const swell::Scene scene = swell::loadScene(std::string(SWELL_SOURCE_DIR) + "/scenes/storm.toml");
    swell::Renderer renderer(scene);
    auto model = std::make_shared<ForwardingModel>(swell::makeWaveModel(scene), false);
    renderer.setWaveModel(model);
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    renderer.renderImage(camera, 1.0, {64, 36});
    model->queries = 0;
    // Low over the waves, so the eye's side of the water is asked too.
    camera.position_m.y = scene.sea.level_m + 1.0;
    for (int frame = 0; frame < 3; ++frame) {
        camera.position_m.x += 5.0;
        renderer.renderImage(camera, 2.0 + frame / 60.0, {64, 36});
        EXPECT_EQ(renderer.counters().queriesOnGpu, 3) << "the boat's, the buoy's and the eye's";
    }
    EXPECT_EQ(model->queries.load(), 0);
}

} // namespace
