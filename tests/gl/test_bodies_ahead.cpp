// The floating bodies stepping ahead on their worker thread while a frame
// is drawn (Renderer::anticipate, objects/scene_bodies.h): a video of
// scenes/gale-under-way.toml (a boat under way with its wake and bow spray,
// a buoy, both rigid bodies) is the same bit for bit with and without it,
// frame by frame, and the steps ahead were taken by the worker.
#include "support/gl_test.h"
#include "swell/debug.h"
#include "swell/renderer.h"
#include "swell/scene/scene_file.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace {

using namespace swell;

class BodiesAhead : public test::GlTest {};

TEST_F(BodiesAhead, AVideoIsTheSameBitForBitWithTheStepsTakenAhead)
{
    Scene scene = loadScene(std::filesystem::path(SWELL_SOURCE_DIR) / "scenes" / "gale-under-way.toml");
    // Two seconds of steps before the first frame rather than the preset's
    // developed history: the same code, a shorter test.
    scene.historyStart_s = -2.0;
    Renderer plain(scene), ahead(scene);
    const glm::ivec2 size(160, 90);
    const double fps = 30.0;
    const int frames = 6;
    double aheadCpu_ms = 0.0;
    for (int i = 0; i < frames; ++i) {
        const double t = 0.25 + i / fps;
        const Camera camera = plain.sceneCameraAt(t);
        const Image a = plain.renderImage(camera, t, size);
        const Image b = ahead.renderImage(ahead.sceneCameraAt(t), t, size);
        // What `swell render` does after each frame of a video.
        ahead.anticipate(t + 1.0 / fps);
        ASSERT_EQ(a.rgba.size(), b.rgba.size());
        EXPECT_TRUE(a.rgba == b.rgba) << "frame " << i;
        EXPECT_EQ(plain.objectTransforms(), ahead.objectTransforms()) << "frame " << i;
        EXPECT_EQ(plain.counters().bodySteps, ahead.counters().bodySteps) << "frame " << i;
        EXPECT_EQ(plain.counters().wakeSteps, ahead.counters().wakeSteps) << "frame " << i;
        EXPECT_EQ(plain.counters().bodiesAheadCpu_ms, 0.0);
        if (i > 0) {
            // Every step of this frame was taken ahead, on the worker's clock.
            EXPECT_GT(ahead.counters().bodiesAheadCpu_ms, 0.0) << "frame " << i;
            aheadCpu_ms += ahead.counters().bodiesAheadCpu_ms;
        }
        EXPECT_EQ(ahead.counters().floatingBodies, 2);
    }
    // The last frame's anticipation is waited for when the renderer goes.
    EXPECT_GT(aheadCpu_ms, 0.0);
}

} // namespace
