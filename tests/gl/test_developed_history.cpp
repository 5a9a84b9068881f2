// A still at any time, t = 0 included, shows the sea as if it had been going
// before (issue 28, item 3): scenes/under-way.toml's boat trails its wake at
// t = 0, because its bodies start kDevelopedHistory_s before it, passing
// their position_m at t = 0; unless the scene's history_start_s says the
// simulation starts at 0, when the water at t = 0 has no wake yet. Checked
// on the water as drawn (Renderer::drawnSurface, the grid's triangles with
// the wake's heights) against the same scene without a wake.
#include "support/gl_test.h"
#include "swell/renderer.h"
#include "swell/scene/scene_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

namespace {

using namespace swell;

class DevelopedHistory : public test::GlTest {};

// The largest difference of the drawn water's height between the scene and
// the scene without its wake, over the 80 m astern of the boat (which makes
// 4 m/s towards -z from (0, -30) at t = 0) and 30 m to either side, at time_s.
double largestWakeHeight_m(Scene scene, double time_s)
{
    const Camera camera = cameraAt(scene.camera, time_s);
    Renderer with(scene);
    scene.wake.enabled = false;
    Renderer without(scene);
    const DrawnSurface a = with.drawnSurface(camera, time_s), b = without.drawnSurface(camera, time_s);
    double largest = 0.0;
    for (double z = -20.0; z <= 50.0; z += 1.3)
        for (double x = -30.0; x <= 30.0; x += 1.7) {
            const auto p = a.at({x, z}), q = b.at({x, z});
            if (p && q)
                largest = std::max(largest, std::abs(p->position_m.y - q->position_m.y));
        }
    return largest;
}

TEST_F(DevelopedHistory, UnderWayShowsItsWakeAtTimeZero)
{
    const Scene scene = loadScene(std::filesystem::path(SWELL_SOURCE_DIR) / "scenes" / "under-way.toml");
    ASSERT_TRUE(std::isinf(scene.historyStart_s)) << "the preset keeps the default: a developed sea";
    const double developed_m = largestWakeHeight_m(scene, 0.0);
    std::printf("under-way at t = 0: the wake raises or lowers the water astern by up to %.3f m\n", developed_m);
    EXPECT_GT(developed_m, 0.05) << "no wake trailing astern at t = 0";

    // The simulation starting at t = 0: no wake there yet.
    Scene fromZero = scene;
    fromZero.historyStart_s = 0.0;
    EXPECT_EQ(largestWakeHeight_m(fromZero, 0.0), 0.0);
}

// A body under way passes its position_m at t = 0 whenever its history
// starts (x(t) = x0 + v t), so a scene's camera finds it where the scene put it.
TEST_F(DevelopedHistory, ABodyPassesItsPositionAtTimeZero)
{
    const Scene scene = loadScene(std::filesystem::path(SWELL_SOURCE_DIR) / "scenes" / "under-way.toml");
    for (const double start_s : {-std::numeric_limits<double>::infinity(), -20.0, 0.0}) {
        Scene s = scene;
        s.historyStart_s = start_s;
        Renderer renderer(s);
        renderer.renderImage(cameraAt(s.camera, 0.0), 0.0, {16, 9});
        const glm::dmat4 boat = renderer.objectTransforms().at(0);
        // Within the sway of its heave, roll and pitch about its centre of mass.
        EXPECT_NEAR(boat[3].x, s.objects[0].position_m.x, 0.5) << "history from " << start_s;
        EXPECT_NEAR(boat[3].z, s.objects[0].position_m.z, 0.5) << "history from " << start_s;
    }
}

} // namespace
