// Dynamic resolution for the viewer (docs/VIEWER.md): the render scale
// follows the frame time towards a target, so that the view keeps its frame
// rate on a slow GPU (or none); the renderer's temporal resolve turns the
// frames drawn at a lower scale back into the window's full resolution
// while the camera rests (viewer/view_quality.h chooses when).
#pragma once

namespace swell::app::viewer {

// The lowest scale the controller goes to: half the window's size. Below it
// a moving view is worse than the plain `--scale 0.5` whatever the resolve
// does (tests/apps/view_quality_image_test.cpp: the storm, moving, drawn at
// 0.3 with the resolve strays 3.1 levels a channel from the full-resolution
// frame, at 0.5 without it 2.9), and on llvmpipe the frame saves little
// there: most of its cost does not shrink with the pixels (docs/VIEWER.md
// "Speed").
inline constexpr double kMinDynamicScale = 0.5;
inline constexpr double kMaxDynamicScale = 1.0;

class DynamicScale {
public:
    // target_ms: the frame time aimed at (over it, the scale drops).
    explicit DynamicScale(double target_ms, double minScale = kMinDynamicScale, double maxScale = kMaxDynamicScale);

    // The scale to draw the next frame at, given the last frame's time (ms,
    // the whole frame: drawing, panel, swap) and the scale it was drawn at.
    // The frame times are smoothed; the scale moves only when the smoothed
    // time leaves the band kLow..1 of the target (hysteresis: a scale that
    // fits is left alone), by steps of kStep, and waits kSettleFrames after
    // each change (the first frame at a new size allocates its targets).
    double next(double frame_ms, double scale);
    double target_ms() const { return target_ms_; }
    // The frames' cost changed for another reason than the scale (the
    // temporal resolve came on or went off): forgets the smoothed time and
    // waits kSettleFrames before the next change.
    void restart();

    // Below this share of the target the scale may rise.
    static constexpr double kLow = 0.7;
    static constexpr double kStep = 0.05;
    static constexpr int kSettleFrames = 3;

private:
    double target_ms_, min_, max_;
    double smoothed_ms_ = 0.0;
    int settle_ = kSettleFrames; // frames still to wait before the next change
};

} // namespace swell::app::viewer
