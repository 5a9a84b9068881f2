#include "viewer/view_quality.h"

#include <algorithm>

namespace swell::app::viewer {

bool sameView(const Camera& a, const Camera& b)
{
    return a.position_m == b.position_m && a.yaw_deg == b.yaw_deg && a.pitch_deg == b.pitch_deg &&
           a.roll_deg == b.roll_deg && a.fovY_deg == b.fovY_deg;
}

ViewQuality::ViewQuality(double startScale)
    : scale_(std::clamp(startScale, kMinDynamicScale, kMaxDynamicScale))
{
}

FrameQuality ViewQuality::next(const QualitySettings& settings, const Camera& camera, double lastFrame_ms)
{
    stillFrames_ = lastCamera_ && sameView(*lastCamera_, camera) ? stillFrames_ + 1 : 0;
    lastCamera_ = camera;
    const bool resting = stillFrames_ >= kRestFrames;
    FrameQuality quality;
    quality.temporal = settings.temporal == TemporalMode::Always ||
                       (settings.temporal == TemporalMode::WhileStill && resting);

    if (!settings.dynamicScale || !dynamic_ || dynamic_->target_ms() != settings.frameTarget_ms)
        dynamic_.reset();
    if (!settings.dynamicScale) {
        quality.renderScale = settings.fixedScale;
        // Dynamic resolution switched on again starts from the scale shown.
        scale_ = std::clamp(settings.fixedScale, kMinDynamicScale, kMaxDynamicScale);
        lastTemporal_ = quality.temporal;
        return quality;
    }
    if (!dynamic_)
        dynamic_.emplace(settings.frameTarget_ms);
    else if (quality.temporal != lastTemporal_)
        // The resolve's pass costs what it costs whatever the scale: the last
        // frame's time says nothing of the next ones, measured afresh.
        dynamic_->restart();
    else if (lastFrame_ms > 0.0)
        scale_ = dynamic_->next(lastFrame_ms, scale_);
    lastTemporal_ = quality.temporal;
    quality.renderScale = scale_;
    return quality;
}

} // namespace swell::app::viewer
