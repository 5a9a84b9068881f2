// The viewer never spirals (issue 28, item 1): an interactive renderer
// (Renderer::setInteractive, what `swell view` uses) takes one step of the
// spectral model per frame, however long after the last the frame is and
// however far the camera moved, where a renderer for stills and sequences
// replays the foam's history (about 20 transforms). Counted, not timed: the
// frame counters say how many sets of FFTs and foam steps each frame took.
#include "support/gl_test.h"
#include "swell/debug.h"
#include "swell/renderer.h"
#include "support/open_sea.h"

#include <gtest/gtest.h>

namespace {

using namespace swell;

class InteractiveFrames : public test::GlTest {};


constexpr glm::ivec2 kInteractiveFramesSize{32, 18};

TEST_F(InteractiveFrames, ALongFrameTakesOneStepNotAReplay)
{
    const Scene scene = test::openSpectralStorm();
    Renderer renderer(scene);
    renderer.setInteractive(true);
    Camera camera = cameraAt(scene.camera, 0.0);
    // The first frame has no history to go on from: it replays.
    renderer.renderImage(camera, 0.0, kInteractiveFramesSize);
    EXPECT_GT(renderer.counters().foamSteps, 1);
    // Frames 1.5 to 5 s apart, longer than the longest foam step (1 s),
    // each of which used to replay about 20 transforms, and the camera cut
    // 5 km away: one transform and one foam step each.
    double time_s = 0.0;
    for (const double frame_s : {1.5, 3.0, 5.0}) {
        time_s += frame_s;
        renderer.renderImage(camera, time_s, kInteractiveFramesSize);
        EXPECT_EQ(renderer.counters().oceanTransforms, 1) << "a frame of " << frame_s << " s";
        EXPECT_EQ(renderer.counters().foamSteps, 1) << "a frame of " << frame_s << " s";
    }
    camera.position_m.x += 5000.0;
    renderer.renderImage(camera, time_s, kInteractiveFramesSize);
    EXPECT_EQ(renderer.counters().oceanTransforms, 0) << "the same time, the camera cut";
    EXPECT_LE(renderer.counters().foamSteps, 1) << "the same time, the camera cut";
    renderer.renderImage(camera, time_s + 2.0, kInteractiveFramesSize);
    EXPECT_EQ(renderer.counters().oceanTransforms, 1);
    EXPECT_EQ(renderer.counters().foamSteps, 1);
    // Back in time (the viewer's restart or scrub): a replay, once.
    renderer.renderImage(camera, 1.0, kInteractiveFramesSize);
    EXPECT_GT(renderer.counters().foamSteps, 1);
}

// What the interactive rule departs from: for stills and sequences a frame
// more than 1 s after the last replays the history, so that it shows the
// foam a still at that time shows.
TEST_F(InteractiveFrames, ARenderersLongFrameReplaysTheHistory)
{
    const Scene scene = test::openSpectralStorm();
    Renderer renderer(scene);
    const Camera camera = cameraAt(scene.camera, 0.0);
    renderer.renderImage(camera, 0.0, kInteractiveFramesSize);
    renderer.renderImage(camera, 0.5, kInteractiveFramesSize);
    EXPECT_EQ(renderer.counters().foamSteps, 1) << "a sequence's frame goes on from the last";
    renderer.renderImage(camera, 2.5, kInteractiveFramesSize);
    EXPECT_GT(renderer.counters().foamSteps, 10) << "a long frame replays";
}

} // namespace
