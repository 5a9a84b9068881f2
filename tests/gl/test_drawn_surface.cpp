// swell::DrawnSurface is the water the GPU draws: at the centroid of each
// triangle a frame draws, its height equals the captured triangle's (the mean
// of its three vertices' heights) within 1 mm, for the Gerstner and the
// spectral model, near the origin and far from it, at t = 0, 10^3 and 10^6 s.
#include "support/gl_test.h"
#include "wave_capture.h"

#include "swell/debug.h"
#include "swell/drawn_surface.h"
#include "swell/error.h"
#include "swell/flat_model.h"
#include "swell/gl/handle.h"
#include "swell/renderer.h"
#include "swell/scene/scene.h"
#include "swell/scene/scene_file.h"
#include "swell/surface_source.h"

#include <epoxy/gl.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

class DrawnSurfaceTest : public swell::test::GlTest {};

// Float positions carry ~1e-7 of up to ~100 lattice steps: far below this
// (as in test_wave_agreement.cpp).
constexpr double kDrawnSurfaceTieMargin = 1e-4;

struct DrawnSurfaceResult {
    int compared = 0, missed = 0;
    double worst_m = 0.0;
};

// The comparison in a given renderer (its scene: scene), which may have drawn
// other times before: what it draws at a time does not depend on the frames
// before (BodiesRender.SameTimeSameImageHoweverTheFramesFell).
DrawnSurfaceResult compareAtCentroids(swell::Renderer& renderer, const swell::Scene& scene, glm::dvec3 eye_m, double time_s)
{
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    camera.position_m = eye_m;
    const glm::ivec2 size(640, 360);
    const int count = swell::RendererTesting::waterVertexCount(renderer);
    swell::gl::Buffer buffer = swell::gl::Buffer::create();
    glNamedBufferStorage(buffer.id(), GLsizeiptr(count) * 8 * 4, nullptr, 0);
    std::vector<std::uint32_t> triangles;
    swell::RendererTesting::captureWaterVertices(renderer, camera, time_s, buffer.id(), size, &triangles);
    std::vector<float> data(size_t(count) * 8);
    glGetNamedBufferSubData(buffer.id(), 0, GLsizeiptr(data.size() * 4), data.data());
    // Which vertices the CPU twin flags as near a snapping tie (either lattice
    // point may be drawn) or on the skirt (float spacing ~1 mm there).
    const std::vector<swell::test::WaterVertex> cpu = swell::test::computeCpu(renderer, camera, time_s);
    const int last = int(std::lround(std::sqrt(double(count)))) - 1;
    auto usable = [&](std::uint32_t v) {
        const swell::test::WaterVertex& w = cpu[v];
        return w.snapMargin >= kDrawnSurfaceTieMargin && w.i > 0 && w.j > 0 && w.i < last && w.j < last;
    };

    const swell::DrawnSurface drawn = renderer.drawnSurface(camera, time_s);
    const glm::dvec3 origin(eye_m.x, 0.0, eye_m.z);
    DrawnSurfaceResult r;
    // Every 7th drawn triangle: thousands, spread over the whole view.
    for (size_t t = 0; t + 2 < triangles.size(); t += 3 * 7) {
        if (!usable(triangles[t]) || !usable(triangles[t + 1]) || !usable(triangles[t + 2]))
            continue;
        glm::dvec3 centroid(0.0);
        for (int k = 0; k < 3; ++k) {
            const float* v = &data[size_t(triangles[t + size_t(k)]) * 8 + 2];
            centroid += origin + glm::dvec3(v[0], v[1], v[2]);
        }
        centroid /= 3.0;
        const std::optional<swell::DrawnPoint> hit = drawn.at({centroid.x, centroid.z});
        if (!hit) {
            ++r.missed;
            continue;
        }
        r.worst_m = std::max(r.worst_m, std::abs(hit->position_m.y - centroid.y));
        ++r.compared;
    }
    return r;
}

DrawnSurfaceResult compareAtCentroids(const swell::Scene& scene, glm::dvec3 eye_m, double time_s,
                          std::shared_ptr<const swell::SurfaceSource> source = nullptr)
{
    swell::Renderer renderer(scene);
    if (source)
        renderer.addSurfaceSource(source);
    return compareAtCentroids(renderer, scene, eye_m, time_s);
}

void expectAgreement(const DrawnSurfaceResult& r, double time_s)
{
    SCOPED_TRACE("t = " + std::to_string(time_s));
    EXPECT_GT(r.compared, 1000);
    EXPECT_EQ(r.missed, 0);
    // The issue's bound; the vertices themselves agree to well under it
    // (WaveAgreement.*), and interpolating adds nothing.
    EXPECT_LT(r.worst_m, 1e-3);
}

void expectDrawnSurface(const swell::Scene& scene, glm::dvec3 eye_m, std::vector<double> times = {0.0, 1.0e3, 1.0e6})
{
    for (const double t : times)
        expectAgreement(compareAtCentroids(scene, eye_m, t), t);
}

swell::Scene plainScene()
{
    swell::Scene scene = swell::defaultScene();
    scene.objects.clear();
    scene.showTerrain = false;
    return scene;
}

TEST_F(DrawnSurfaceTest, GerstnerEqualsTheDrawnTriangles)
{
    expectDrawnSurface(plainScene(), {3.7, 6.0, -12.2});
}

// Over the sea floor (swell/coast_field.h): the coast preset's swell
// shoaling and cut where it breaks, from a camera over 2.5 m of water with
// the shore and the dry sand in view.
TEST_F(DrawnSurfaceTest, OverTheSeaFloorTheWaterIsTheDrawnTriangles)
{
    const swell::Scene scene = swell::loadScene(std::filesystem::path(SWELL_SOURCE_DIR) / "scenes" / "coast.toml");
    expectDrawnSurface(scene, {-40.0, 6.0, 200.0}, {0.0, 37.5});
}

// The spectral ocean over the same floor: the longest band carried by the
// trains near the shore (src/ocean/spectral/spectral_coast.h).
TEST_F(DrawnSurfaceTest, SpectralOverTheSeaFloorIsTheDrawnTriangles)
{
    swell::Scene scene = swell::loadScene(std::filesystem::path(SWELL_SOURCE_DIR) / "scenes" / "coast.toml");
    scene.waves.model = swell::WaveModelKind::Spectral;
    scene.sea.wind->windSpeed_mps = 10.0;
    expectDrawnSurface(scene, {-40.0, 6.0, 200.0}, {0.0, 37.5});
}

TEST_F(DrawnSurfaceTest, SpectralEqualsTheDrawnTriangles)
{
    swell::Scene scene = plainScene();
    scene.waves.model = swell::WaveModelKind::Spectral;
    scene.sea.wind->windSpeed_mps = 14.0;
    expectDrawnSurface(scene, {3.7, 6.0, -12.2});
}

TEST_F(DrawnSurfaceTest, SpectralFarFromTheOriginAndHigh)
{
    swell::Scene scene = plainScene();
    scene.waves.model = swell::WaveModelKind::Spectral;
    scene.sea.wind->windSpeed_mps = 14.0;
    expectDrawnSurface(scene, {1.0e5 + 0.37, 45.0, -1.0e5 - 0.81}, {1.0e6});
}

// The GPU's drawn water under world point p: the captured triangle whose
// x,z projection holds it, interpolated. Empty when no drawn triangle does.
std::optional<double> gpuWaterUnder(glm::dvec2 p, const std::vector<float>& data,
                                    const std::vector<std::uint32_t>& triangles, glm::dvec3 origin)
{
    for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
        glm::dvec3 v[3];
        for (int k = 0; k < 3; ++k) {
            const float* f = &data[size_t(triangles[t + size_t(k)]) * 8 + 2];
            v[k] = origin + glm::dvec3(f[0], f[1], f[2]);
        }
        const glm::dvec2 a(v[0].x, v[0].z), b(v[1].x, v[1].z), c(v[2].x, v[2].z);
        const glm::dvec2 ab = b - a, ac = c - a, ap = p - a;
        const double det = ab.x * ac.y - ab.y * ac.x;
        if (std::abs(det) < 1e-12)
            continue;
        const double wb = (ap.x * ac.y - ap.y * ac.x) / det, wc = (ab.x * ap.y - ab.y * ap.x) / det;
        if (wb >= 0.0 && wc >= 0.0 && wb + wc <= 1.0)
            return v[0].y * (1.0 - wb - wc) + v[1].y * wb + v[2].y * wc;
    }
    return std::nullopt;
}

// With a boat under way, its wake is in the drawn water alike on both sides:
// the GPU's vertices and swell::DrawnSurface agree within 1 mm over the
// wake, and the wake is there (the vertices move by decimetres without it).
TEST_F(DrawnSurfaceTest, TheWakeIsInTheDrawnTrianglesAlike)
{
    swell::Scene scene = plainScene();
    swell::SceneObject boat;
    boat.path = "builtin:boat";
    boat.position_m = {0.0, 0.0, -30.0};
    boat.yaw_deg = 90.0;
    boat.floats = true;
    boat.density_kg_per_m3 = 250.0;
    boat.velocity_m_per_s = {0.0, 0.0, -4.0};
    scene.objects = {boat};
    const glm::dvec3 eye(3.0, 12.0, -40.0); // above the wake, 30 m astern of the boat at 10 s

    // The wake's own share: the vertices captured with it and without.
    auto capture = [&](swell::Renderer& renderer, const swell::Scene& s) {
        swell::Camera camera = swell::cameraAt(s.camera, 0.0);
        camera.position_m = eye;
        swell::gl::Buffer buffer = swell::gl::Buffer::create();
        const int count = swell::RendererTesting::waterVertexCount(renderer);
        glNamedBufferStorage(buffer.id(), GLsizeiptr(count) * 8 * 4, nullptr, 0);
        swell::RendererTesting::captureWaterVertices(renderer, camera, 10.0, buffer.id());
        std::vector<float> data(size_t(count) * 8);
        glGetNamedBufferSubData(buffer.id(), 0, GLsizeiptr(data.size() * 4), data.data());
        return data;
    };
    // One renderer simulates the boat's first 10 s of wake once, for both
    // times and the capture with the wake: a fresh renderer for each gave the
    // same figures to the last digit and simulated the wake three times, most
    // of the test's time. The later time last, so no frame goes back in time.
    swell::Renderer withWake(scene);
    expectAgreement(compareAtCentroids(withWake, scene, eye, 10.0), 10.0);
    const std::vector<float> with = capture(withWake, scene);
    expectAgreement(compareAtCentroids(withWake, scene, eye, 10.0 + 1.0 / 70.0), 10.0 + 1.0 / 70.0);
    scene.wake.enabled = false;
    swell::Renderer withoutWake(scene);
    const std::vector<float> without = capture(withoutWake, scene);
    ASSERT_EQ(with.size(), without.size());
    double largest_m = 0.0;
    for (size_t v = 0; v < with.size(); v += 8)
        largest_m = std::max(largest_m, double(std::abs(with[v + 3] - without[v + 3]))); // vPosition.y
    EXPECT_GT(largest_m, 0.1);
}

// The default scene's floating buoy sits on the water the GPU draws, within
// 1 cm (the issue's bound), frame after frame. Placed on the exact surface
// instead, it is off by 6 cm in one of these frames.
TEST_F(DrawnSurfaceTest, FloatingObjectsSitOnTheDrawnWater)
{
    const swell::Scene scene = swell::defaultScene();
    swell::Renderer renderer(scene);
    const swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    const int count = swell::RendererTesting::waterVertexCount(renderer);
    swell::gl::Buffer buffer = swell::gl::Buffer::create();
    glNamedBufferStorage(buffer.id(), GLsizeiptr(count) * 8 * 4, nullptr, 0);
    std::vector<float> data(size_t(count) * 8);
    std::vector<std::uint32_t> triangles;
    const glm::dvec3 origin(camera.position_m.x, 0.0, camera.position_m.z);
    int floating = 0;
    for (const double t : {0.0, 0.7, 3.1, 12.9, 400.0}) {
        SCOPED_TRACE("t = " + std::to_string(t));
        swell::RendererTesting::captureWaterVertices(renderer, camera, t, buffer.id(), {1280, 720}, &triangles);
        glGetNamedBufferSubData(buffer.id(), 0, GLsizeiptr(data.size() * 4), data.data());
        const std::vector<glm::dmat4> transforms = renderer.objectTransforms();
        ASSERT_EQ(transforms.size(), scene.objects.size());
        for (size_t o = 0; o < scene.objects.size(); ++o) {
            if (!scene.objects[o].floats)
                continue;
            const glm::dvec3 at(transforms[o][3]);
            const std::optional<double> water = gpuWaterUnder({at.x, at.z}, data, triangles, origin);
            ASSERT_TRUE(water) << "object " << o << " is not over drawn water";
            EXPECT_NEAR(at.y - scene.objects[o].position_m.y, *water, 0.01) << "object " << o;
            ++floating;
        }
    }
    EXPECT_GE(floating, 5);
}

// A surface source of the host's own (swell/surface_source.h): a ring
// expanding from an explosion at centre_m since start_s, a Gaussian ridge of
// height amplitude_m and half-width width_m at radius speed * (t - start).
// Its GLSL evaluates the same function about the render origin.
class ExpandingRing final : public swell::SurfaceSource {
public:
    glm::dvec2 centre_m{10.0, -80.0};
    double start_s = 0.0, speed_mps = 8.0, amplitude_m = 1.5, width_m = 6.0;

    glm::dvec3 heightAt(glm::dvec2 rest_m, double time_s) const override
    {
        const glm::dvec2 d = rest_m - centre_m;
        const double r = glm::length(d), s = (r - radius_m(time_s)) / width_m;
        const double h = amplitude_m * std::exp(-s * s), dhdr = -2.0 * s / width_m * h;
        const glm::dvec2 slope = r > 1e-9 ? d / r * dhdr : glm::dvec2(0.0);
        return {h, slope.x, slope.y};
    }
    double reach_m(double) const override { return amplitude_m; }
    std::string glsl() const override
    {
        return R"(
vec4 SWELL_SOURCE_FUNCTION(vec2 p_m, vec4 parameters[4])
{
    vec2 d = p_m - parameters[0].xy;
    float r = length(d);
    float s = (r - parameters[0].z) / parameters[1].x;
    float h = parameters[0].w * exp(-s * s);
    float dhdr = -2.0 * s / parameters[1].x * h;
    vec2 slope = r > 1e-6 ? d / r * dhdr : vec2(0.0);
    return vec4(h, slope, 0.0);
}
)";
    }
    swell::SurfaceSourceParameters gpuParameters(double time_s, glm::dvec3 origin_m) const override
    {
        // The centre relative to the render origin, subtracted in double.
        const glm::dvec2 centre = centre_m - glm::dvec2(origin_m.x, origin_m.z);
        return {glm::vec4(glm::dvec4(centre, radius_m(time_s), amplitude_m)), glm::vec4(float(width_m), 0.0f, 0.0f, 0.0f),
                glm::vec4(0.0f), glm::vec4(0.0f)};
    }

private:
    double radius_m(double time_s) const { return speed_mps * std::max(time_s - start_s, 0.0); }
};

// The host's source is in the drawn water and in DrawnSurface alike (within
// 1 mm at the drawn triangles' centroids), on flat water and on the waves.
TEST_F(DrawnSurfaceTest, AHostsSurfaceSourceIsInTheDrawnTrianglesAlike)
{
    auto ring = std::make_shared<ExpandingRing>();
    ring->start_s = 5.0;
    const glm::dvec3 eye(3.7, 6.0, -12.2);
    for (const double t : {9.0, 12.0}) {
        SCOPED_TRACE("t = " + std::to_string(t));
        const DrawnSurfaceResult r = compareAtCentroids(plainScene(), eye, t, ring);
        EXPECT_GT(r.compared, 1000);
        EXPECT_EQ(r.missed, 0);
        EXPECT_LT(r.worst_m, 1e-3);
    }
    // It is there: the drawn water on the ring stands its height above the
    // water without it.
    swell::Renderer renderer(plainScene());
    swell::Camera camera = swell::cameraAt(plainScene().camera, 0.0);
    camera.position_m = eye;
    const glm::dvec2 onRing = ring->centre_m + glm::dvec2(0.0, 8.0 * (12.0 - 5.0));
    const double without = renderer.drawnSurface(camera, 12.0).at(onRing)->position_m.y;
    renderer.addSurfaceSource(ring);
    const double with = renderer.drawnSurface(camera, 12.0).at(onRing)->position_m.y;
    EXPECT_NEAR(with - without, ring->amplitude_m, 0.05);
}

// Floating bodies feel the host's source: a buoy on a standing mound of
// water 2 m high rides 2 m higher than without it.
TEST_F(DrawnSurfaceTest, FloatingBodiesRideAHostsSurfaceSource)
{
    swell::Scene scene = plainScene();
    swell::SceneObject buoy;
    buoy.path = "builtin:buoy";
    buoy.position_m = {10.0, 0.0, -80.0};
    buoy.floats = true;
    buoy.density_kg_per_m3 = 400.0;
    scene.objects = {buoy};
    auto mound = std::make_shared<ExpandingRing>();
    mound->speed_mps = 0.0;
    mound->amplitude_m = 2.0;
    mound->width_m = 40.0;
    const glm::dvec3 eye(3.7, 6.0, -12.2);
    auto heightAt = [&](bool withMound) {
        swell::Renderer renderer(scene);
        renderer.setWaveModel(std::make_shared<swell::FlatModel>()); // calm: the mound alone lifts it
        if (withMound)
            renderer.addSurfaceSource(mound);
        renderer.advanceTo(30.0, eye);
        return renderer.objectTransforms().at(0)[3].y;
    };
    const double without = heightAt(false), with = heightAt(true);
    EXPECT_NEAR(with - without, 2.0, 0.1) << "without " << without << " m, with " << with << " m";
}

// A source's bad GLSL is refused naming its file, and the sources drawn stay.
TEST_F(DrawnSurfaceTest, ASurfaceSourceWhoseGlslDoesNotBuildIsRefused)
{
    class Broken final : public swell::SurfaceSource {
    public:
        glm::dvec3 heightAt(glm::dvec2, double) const override { return glm::dvec3(0.0); }
        double reach_m(double) const override { return 0.0; }
        std::string glsl() const override { return "vec4 SWELL_SOURCE_FUNCTION(vec2 p_m, vec4 parameters[4]) { return p_m; }\n"; }
        swell::SurfaceSourceParameters gpuParameters(double, glm::dvec3) const override { return {}; }
    };
    swell::Renderer renderer(plainScene());
    auto ring = std::make_shared<ExpandingRing>();
    renderer.addSurfaceSource(ring);
    try {
        renderer.addSurfaceSource(std::make_shared<Broken>());
        ADD_FAILURE() << "a source that does not compile was added";
    } catch (const swell::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("surface_source_"), std::string::npos) << e.what();
    }
    EXPECT_THROW(renderer.addSurfaceSource(nullptr), swell::Error);
    EXPECT_THROW(renderer.addSurfaceSource(ring), swell::Error) << "added twice";
    // The ring is still drawn: the renderer draws as before.
    const swell::Camera camera = swell::cameraAt(plainScene().camera, 3.0);
    EXPECT_NO_THROW(renderer.renderImage(camera, 3.0, {64, 36}));
    swell::test::GlTest::messages().clear(); // the compiler's own report of the bad GLSL
}

} // namespace
