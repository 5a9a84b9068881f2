#include "viewer/dynamic_scale.h"

#include <algorithm>
#include <cmath>

namespace swell::app::viewer {

DynamicScale::DynamicScale(double target_ms, double minScale, double maxScale)
    : target_ms_(target_ms), min_(minScale), max_(maxScale)
{
}

void DynamicScale::restart()
{
    smoothed_ms_ = 0.0;
    settle_ = kSettleFrames;
}

double DynamicScale::next(double frame_ms, double scale)
{
    // An exponential mean over about the last three frames: one slow frame
    // (a shader reload, a panel's edit) does not throw the scale down.
    smoothed_ms_ = smoothed_ms_ > 0.0 ? 0.6 * smoothed_ms_ + 0.4 * frame_ms : frame_ms;
    if (settle_ > 0) {
        --settle_;
        return scale;
    }
    double wanted = scale;
    // Most of a frame's cost is its pixels, which go with the scale's square:
    // the scale that would land at 90 % of the target, moved towards at most
    // a quarter per change upward (the cost that does not shrink with the
    // pixels makes the model too hopeful there).
    const double ideal = scale * std::sqrt(0.9 * target_ms_ / smoothed_ms_);
    if (smoothed_ms_ > target_ms_)
        wanted = std::min(ideal, scale - kStep);
    else if (smoothed_ms_ < kLow * target_ms_)
        wanted = std::clamp(ideal, scale + kStep, scale * 1.25);
    // On the steps' lattice, so that the frame's size repeats.
    wanted = std::clamp(std::round(wanted / kStep) * kStep, min_, max_);
    if (wanted != scale) {
        settle_ = kSettleFrames;
        smoothed_ms_ = 0.0;
    }
    return wanted;
}

} // namespace swell::app::viewer
