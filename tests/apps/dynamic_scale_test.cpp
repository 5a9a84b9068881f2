// The viewer's dynamic resolution (apps/swell/viewer/dynamic_scale.h): the
// scale goes down when frames are over the target and up when they are well
// under it, stays put in between (hysteresis: no see-sawing), keeps within
// its bounds and on its steps, and lands a modelled frame cost inside the
// band.
#include "viewer/dynamic_scale.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace {

using swell::app::viewer::DynamicScale;

// A frame's cost that goes with its pixels plus a part that does not, ms.
double modelFrame_ms(double scale, double fixed_ms, double fullPixels_ms)
{
    return fixed_ms + fullPixels_ms * scale * scale;
}

// Runs `frames` frames of the model from `scale`, returning the scales taken.
std::vector<double> run(DynamicScale& dynamic, double scale, int frames, double fixed_ms, double fullPixels_ms)
{
    std::vector<double> scales;
    for (int i = 0; i < frames; ++i) {
        scale = dynamic.next(modelFrame_ms(scale, fixed_ms, fullPixels_ms), scale);
        scales.push_back(scale);
    }
    return scales;
}

TEST(DynamicScale, ASlowViewSettlesInsideTheBand)
{
    // The default scene on llvmpipe, roughly: 200 ms at full size, 30 of it
    // not pixels.
    DynamicScale dynamic(100.0);
    const std::vector<double> scales = run(dynamic, 1.0, 60, 30.0, 170.0);
    const double last = scales.back();
    const double frame_ms = modelFrame_ms(last, 30.0, 170.0);
    EXPECT_LE(frame_ms, 100.0) << "scale " << last;
    EXPECT_GE(frame_ms, DynamicScale::kLow * 100.0) << "scale " << last;
    // Settled: the last 30 frames at one scale.
    EXPECT_EQ(std::set<double>(scales.end() - 30, scales.end()).size(), 1u);
    for (double s : scales) {
        EXPECT_NEAR(std::round(s / DynamicScale::kStep) * DynamicScale::kStep, s, 1e-9) << "off the steps";
    }
}

TEST(DynamicScale, AFastViewRisesToFullSizeAndNoFurther)
{
    DynamicScale dynamic(100.0);
    const std::vector<double> scales = run(dynamic, 0.3, 60, 5.0, 40.0);
    EXPECT_DOUBLE_EQ(scales.back(), 1.0);
}

TEST(DynamicScale, AViewTooSlowForTheTargetStopsAtTheFloor)
{
    DynamicScale dynamic(100.0);
    const std::vector<double> scales = run(dynamic, 1.0, 60, 400.0, 600.0);
    EXPECT_DOUBLE_EQ(scales.back(), swell::app::viewer::kMinDynamicScale);
}

TEST(DynamicScale, InsideTheBandNothingMoves)
{
    // 85 ms a frame whatever the scale: between 70 % and 100 % of the target.
    DynamicScale dynamic(100.0);
    double scale = 0.6;
    for (int i = 0; i < 30; ++i) {
        scale = dynamic.next(85.0, scale);
        EXPECT_DOUBLE_EQ(scale, 0.6) << "frame " << i;
    }
}

TEST(DynamicScale, ItWaitsAfterEachChange)
{
    DynamicScale dynamic(100.0);
    double scale = 1.0;
    int changes = 0, lastChange = -100;
    for (int i = 0; i < 40; ++i) {
        const double next = dynamic.next(300.0, scale);
        if (next != scale) {
            EXPECT_GT(i - lastChange, DynamicScale::kSettleFrames) << "frame " << i;
            lastChange = i;
            ++changes;
        }
        scale = next;
    }
    EXPECT_GT(changes, 0);
}

} // namespace
