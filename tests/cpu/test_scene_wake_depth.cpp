// A scene's wake feels the sea floor under it (objects/scene_wake.h): its
// dispersion takes the depth under the grid's centre, taken again as the
// grid moves, so a boat running from deep water onto a shelf leaves the
// shelf's wider wake (WakeField.ShallowWaterWidensTheWakeAsHavelockSays).
#include "objects/scene_wake.h"

#include "swell/scene/scene.h"
#include "swell/scene/seabed.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

namespace {

TEST(SceneWake, TakesTheDepthOfTheFloorUnderItsGrid)
{
    swell::Scene scene = swell::defaultScene();
    scene.showTerrain = false;
    // A shelf 2 m deep: its flat top from z = 0 to -500 m, its edge falling
    // at 1:20 towards +z to the toe's 100 m, deep water beyond.
    swell::SeabedShelf shelf;
    shelf.edgePoint_m = {0.0, 0.0};
    shelf.seawardAzimuth_deg = 180.0; // the edge slopes down towards +z
    shelf.depth_m = 2.0;
    shelf.slope = 0.05;
    shelf.width_m = 500.0;
    shelf.length_m = 2000.0;
    scene.seabed.shelves.push_back(shelf);
    const auto seabed = std::make_shared<const swell::Seabed>(scene);
    const double inf = std::numeric_limits<double>::infinity();
    ASSERT_NEAR(-seabed->elevation_m({0.0, -250.0}), 2.0, 1e-9) << "the shelf's top";

    swell::detail::SceneWake wake(scene.wake, inf, seabed);
    wake.reset({0.0, -250.0});
    EXPECT_DOUBLE_EQ(wake.field().settings().depth_m, 2.0);
    // Off the shelf into deep water, where the slope has ended.
    for (int n = 0; n < 3; ++n)
        wake.step({}, {0.0, 3000.0});
    EXPECT_EQ(wake.field().settings().depth_m, inf);
    // Down the shelf's edge: each step's depth within 3% of the floor's.
    for (double z : {20.0, 40.0, 60.0}) {
        wake.step({}, {0.0, z});
        const double floor_m = -seabed->elevation_m({0.0, z});
        EXPECT_NEAR(wake.field().settings().depth_m, floor_m, 0.03 * floor_m) << "z = " << z;
    }
    // Without a floor: the sea's depth everywhere.
    swell::detail::SceneWake open(scene.wake, 40.0);
    open.reset({0.0, -250.0});
    EXPECT_EQ(open.field().settings().depth_m, 40.0);
}

} // namespace
