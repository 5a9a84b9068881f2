// Moving the camera must not make the surface crawl: with time frozen, a move
// smaller than the finest cell leaves every vertex where it was, and after any
// move every vertex sits on a world-fixed lattice point of its LOD level.
#include "support/gl_test.h"
#include "support/param_names.h"
#include "swell/renderer.h"
#include "swell/scene/grid.h"
#include "wave_capture.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace {

// Both grid layouts keep the guarantee.
class NoSwimming : public swell::test::GlTest, public testing::WithParamInterface<swell::GridLayout> {};

swell::Scene swimScene(swell::GridLayout layout)
{
    swell::Scene scene = swell::defaultScene();
    scene.objects.clear();
    scene.showTerrain = false;
    scene.grid.resolution = 129;
    scene.grid.layout = layout;
    return scene;
}

TEST_P(NoSwimming, SubCellMotionChangesNoVertex)
{
    const swell::Scene scene = swimScene(GetParam());
    swell::Renderer renderer(scene);
    const swell::GridShape shape = swell::gridShapeFor(scene.grid, scene.camera);
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    const double step = swell::placeGrid(shape, {0.0, 6.0, 0.0}).finestStep_m;
    // Start just past a snap point so that moving 0.3 cells crosses none.
    camera.position_m = {200.0 * step + 0.05 * step, 6.0, -80.0 * step + 0.05 * step};
    const auto before = swell::test::captureGpu(renderer, camera, 42.0);
    camera.position_m += glm::dvec3(0.3 * step, 0.0, 0.2 * step);
    const auto after = swell::test::captureGpu(renderer, camera, 42.0);
    ASSERT_EQ(before.size(), after.size());
    double worst = 0.0;
    for (size_t k = 0; k < before.size(); ++k) {
        // The skirt lies 18 km out, where a float relative to the moved render
        // origin rounds to ~2 mm steps; its waves are faded to zero anyway.
        if (before[k].i == 0 || before[k].j == 0 || before[k].i == shape.cells || before[k].j == shape.cells)
            continue;
        worst = std::max(worst, glm::length(before[k].position_m - after[k].position_m));
    }
    // Swimming would move vertices by about the motion, 0.3 cells (~0.15 m).
    // What may change: float rounding of positions relative to the moved
    // origin (1.2e-4 m per ulp at 1..2 km) and the horizon fade, which depends
    // on the eye; both stay far below half a millimetre.
    EXPECT_LT(worst, 5e-4) << "the surface moved with the camera (finest cell " << step << " m)";
}

TEST_P(NoSwimming, EveryVertexSitsOnItsLevelsWorldFixedLattice)
{
    const swell::Scene scene = swimScene(GetParam());
    swell::Renderer renderer(scene);
    const swell::GridShape shape = swell::gridShapeFor(scene.grid, scene.camera);
    // The lattices of every height scale are lattices of the finest step at scale 1.
    const double step0 = swell::finestGridStep(shape);
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    // Heights that give the geometric layout scales 1, 2 and 8.
    for (glm::dvec3 p : {glm::dvec3(0.0, 6.0, 0.0), glm::dvec3(7.31, 6.0, -3.17), glm::dvec3(1234.5, 13.0, 987.6),
                         glm::dvec3(-5.0e5 + 0.123, 50.0, 2.5e5 - 0.456)}) {
        camera.position_m = p;
        const auto vertices = swell::test::captureGpu(renderer, camera, 0.0);
        const swell::GridPlacement placement = swell::placeGrid(shape, p);
        int checked = 0;
        for (const auto& v : vertices) {
            if (v.i == 0 || v.j == 0 || v.i == shape.cells || v.j == shape.cells)
                continue; // the skirt, beyond the fog
            const swell::GridPoint point = swell::gridPoint(shape, placement, v.i, v.j);
            for (int axis = 0; axis < 2; ++axis) {
                const double step = point.latticeStep_m[axis];
                // Each level's lattice is a power-of-two multiple of scale 1's finest step.
                EXPECT_NEAR(std::exp2(std::round(std::log2(step / step0))), step / step0, 1e-9);
                const double along = axis == 0 ? v.rest_m.x : v.rest_m.y;
                const double off = along / step - std::round(along / step);
                // In units of the lattice step; float rest positions near 2 km carry ~1e-4 m.
                EXPECT_LT(std::abs(off) * step, 2e-3) << "vertex (" << v.i << ", " << v.j << ") off its lattice at camera " << p.x;
                ++checked;
            }
        }
        EXPECT_GT(checked, 30000);
    }
}

INSTANTIATE_TEST_SUITE_P(Layouts, NoSwimming, testing::Values(swell::GridLayout::Geometric, swell::GridLayout::Paper),
                         [](const testing::TestParamInfo<swell::GridLayout>& layout) { return swell::paramName(layout.param); });

} // namespace
