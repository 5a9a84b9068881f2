// Far from the origin and after long times the ocean looks as it does near
// the origin at small times: render the same wave field (phases shifted so
// the field is identical) at 10^6 m and 10^6 s and compare the images.
#include "support/gl_test.h"
#include "support/golden.h"
#include "swell/renderer.h"
#include "swell/scene/grid.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>

namespace {

class Precision : public swell::test::GlTest {};

swell::Scene precisionOpenSea()
{
    swell::Scene scene = swell::defaultScene();
    scene.objects.clear();
    scene.showTerrain = false;
    scene.waves.listed = swell::resolveWaves(scene).waves;
    scene.sea.wind.reset();
    return scene;
}

// The same field moved by `offset_m` and advanced by `time_s`: each phase
// absorbs k.d.offset and omega.t, computed in double and wrapped.
swell::Scene shifted(swell::Scene scene, glm::dvec2 offset_m, double time_s)
{
    for (swell::Wave& w : scene.waves.listed) {
        const double k = 2.0 * glm::pi<double>() / w.wavelength_m;
        const double omega = swell::angularFrequency(k, scene.sea.depth_m);
        const double shift = -k * glm::dot(glm::normalize(w.direction), offset_m) + omega * time_s;
        w.phase_rad = std::remainder(w.phase_rad + shift, 2.0 * glm::pi<double>());
    }
    return scene;
}

swell::Image render(const swell::Scene& scene, glm::dvec2 cameraXZ, double time_s)
{
    swell::Renderer renderer(scene);
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    camera.position_m.x = cameraXZ.x;
    camera.position_m.z = cameraXZ.y;
    return renderer.renderImage(camera, time_s, {240, 135});
}

void expectSameOcean(const swell::Image& a, const swell::Image& b, const char* name)
{
    const swell::ImageDifference d = swell::compareImages(a, b);
    // The two renders differ only by float rounding of the (wrapped, double)
    // phases: a few levels on glints at most, nothing visible on average.
    if (d.maxChannel > 24 || d.meanChannel > 0.25) {
        ADD_FAILURE() << name << ": max " << d.maxChannel << ", mean " << d.meanChannel << "; images: "
                      << swell::test::saveTestImage(a, std::string(name) + ".reference") << " and "
                      << swell::test::saveTestImage(b, std::string(name) + ".actual");
    }
}

TEST_F(Precision, AMillionMetresOutLooksLikeTheOrigin)
{
    const swell::Scene scene = precisionOpenSea();
    // About 10^6 m out, on a point of every LOD level's lattice (the finest
    // step times 2^12), so the grid samples the field where it does at the origin.
    const double lattice = swell::finestGridStep(swell::gridShapeFor(scene.grid, scene.camera)) * 4096.0;
    const glm::dvec2 far(std::round(1.0e6 / lattice) * lattice, -std::round(1.0e6 / lattice) * lattice);
    expectSameOcean(render(scene, {0.0, 0.0}, 20.0), render(shifted(scene, far, 0.0), far, 20.0), "precision_far");
}

TEST_F(Precision, AMillionSecondsLaterLooksLikeTheStart)
{
    const swell::Scene scene = precisionOpenSea();
    // Rendering at t = 20 + 10^6 s with phases that undo the extra 10^6 s.
    expectSameOcean(render(scene, {0.0, 0.0}, 20.0), render(shifted(scene, {0.0, 0.0}, 1.0e6), {0.0, 0.0}, 20.0 + 1.0e6),
                    "precision_late");
}

TEST_F(Precision, ConsecutiveFramesAtSixtyHertzDoNotJitterFarOut)
{
    // With time frozen, two frames whose camera moved by one 60 Hz step of a
    // slow drift (0.05 m) 10^6 m out must differ no more than near the origin.
    const swell::Scene scene = precisionOpenSea();
    auto frameDelta = [&](glm::dvec2 at) {
        const swell::ImageDifference d =
            swell::compareImages(render(scene, at, 5.0), render(scene, at + glm::dvec2(0.05 / 60.0, 0.0), 5.0));
        return d.meanChannel;
    };
    const double near = frameDelta({0.0, 0.0});
    const double far = frameDelta({1.0e6, 1.0e6});
    EXPECT_LT(far, near + 0.2) << "near " << near << ", far " << far;
}

} // namespace
