// The water grid's tile bounds are computed once per grid scale and morph
// band, not once per frame: they hold wherever the grid's centre snaps, so a
// camera flying level across hundreds of snaps reuses them. (That they hold
// is test_grid_culling's job, which also culls from a camera elsewhere first.)
#include "support/gl_test.h"
#include "render/water_grid.h"
#include "swell/grid.h"
#include "swell/scene.h"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

namespace {

class GridBoundsCache : public swell::test::GlTest {};

TEST_F(GridBoundsCache, ComputedOncePerScaleAndMorphBandNotPerSnap)
{
    const swell::Scene scene = swell::defaultScene();
    const swell::GridShape shape = swell::gridShapeFor(scene.grid, scene.camera);
    swell::detail::WaterGrid grid;
    grid.build(shape);
    const swell::WaveReach reach{1.0, 0.5};
    const glm::dmat4 viewProj = glm::perspective(1.0, 16.0 / 9.0, 0.1, 2.0e4) *
                                glm::lookAt(glm::dvec3(0.0, 6.0, 0.0), glm::dvec3(0.0, 5.0, -10.0), glm::dvec3(0.0, 1.0, 0.0));
    auto cullAt = [&](glm::dvec3 camera_m) {
        const swell::GridPlacement placement = swell::placeGrid(shape, camera_m);
        grid.cull(shape, placement, reach, viewProj, false, placement.center_m - glm::dvec2(camera_m.x, camera_m.z));
        return placement;
    };
    // 6 m up, flying 37 cm a frame for 200 frames: a new grid centre every frame.
    int snaps = 0;
    glm::dvec2 lastCenter(1e30);
    for (int frame = 0; frame < 200; ++frame) {
        const swell::GridPlacement placement = cullAt({0.37 * frame, 6.0, -0.11 * frame});
        snaps += placement.center_m != lastCenter ? 1 : 0;
        lastCenter = placement.center_m;
    }
    EXPECT_EQ(snaps, 200);
    EXPECT_EQ(grid.boundsComputed(), 1);
    // Climbing through the morph from scale 1 to 2 (13.2 .. 47 m) 1 cm a
    // frame changes them once per morph band, not per frame.
    const long long before = grid.boundsComputed();
    for (double h = 13.0; h <= 48.0; h += 0.01)
        cullAt({5.0, h, 3.0});
    EXPECT_EQ(grid.boundsComputed() - before, 1 + swell::detail::kMorphBands);
}

} // namespace
