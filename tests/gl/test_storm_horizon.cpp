// The storm from a bridge's height shows its swell out to the haze (issue
// #47, item 9: from its own camera the storm read as a rough plain). From
// the storm preset's camera, 10 m up, the drawn water 600 to 1500 m off
// rises and falls with the swell: the heights where the pixels' rays meet
// it spread with a standard deviation of at least 0.5 m, a quarter of the
// sea's own (Hs 8 m: 2 m). When far vertices dropped the first cascade
// (beyond 470 m from this eye) and the preset faded its waves from 600 m,
// the sea there was flat under its textured skin.
//
// (Not the horizon's row: from 10 m the horizon is the water 4.5 km off,
// the grid's flat skirt, above every far crest; a crest stands above it only
// where it is higher than the eye.)
#include "support/camera_rays.h"
#include "support/gl_test.h"
#include "swell/dataset/labels.h"
#include "swell/renderer.h"
#include "swell/scene/scene_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace {

class StormHorizon : public swell::test::GlTest {};

TEST_F(StormHorizon, TheFarSeaRisesAndFallsWithTheSwell)
{
    swell::Scene scene = swell::loadScene(std::string(SWELL_SOURCE_DIR) + "/scenes/storm.toml");
    scene.objects.clear(); // the boat and the buoy hide some water, and are not water
    swell::Renderer renderer(scene);
    const glm::ivec2 size(480, 270);
    for (const double time_s : {5.0, 12.0, 20.0}) {
        const swell::Camera camera = swell::cameraAt(scene.camera, time_s);
        renderer.renderImage(camera, time_s, size);
        const swell::FrameLabels labels = renderer.renderLabels(camera, size);
        double sum = 0.0, sumSquares = 0.0;
        int n = 0;
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const double range_m = double(labels.range_m[std::size_t(y) * std::size_t(size.x) + std::size_t(x)]);
                if (!(range_m >= 600.0 && range_m <= 1500.0))
                    continue;
                const double height_m = camera.position_m.y + range_m * swell::test::pixelRay(camera, size, x, y).y;
                sum += height_m;
                sumSquares += height_m * height_m;
                ++n;
            }
        ASSERT_GT(n, 1000) << "the view shows too little water 600 to 1500 m off";
        const double mean = sum / n, spread = std::sqrt(std::max(sumSquares / n - mean * mean, 0.0));
        std::printf("t = %.0f s: %d pixels of water 600 to 1500 m off, height %.2f m +- %.2f m\n", time_s, n, mean,
                    spread);
        EXPECT_GE(spread, 0.5) << "at t = " << time_s << " s the far sea is flat";
    }
}

} // namespace
