// What the viewer draws each frame at (docs/VIEWER.md "Dynamic resolution
// and the temporal resolve"): the render scale and whether the renderer's
// temporal resolve is on, chosen from the last frame's time and whether the
// camera moved. No window and no GL: tests/apps/view_quality_test.cpp and
// tests/apps/view_quality_image_test.cpp drive it as the viewer does.
//
// The policy, and why (measured on llvmpipe, docs/VIEWER.md "Speed"):
//   - while the camera moves, no temporal resolve: its history cannot
//     converge on a view that changes every frame, so a frame drawn below the
//     window's size shows its jitter as a regular zig-zag dither;
//   - once the camera has rested kRestFrames frames, the resolve comes on
//     (its history starts afresh: Renderer::setTemporalResolve resets it) and
//     converges to the full-resolution picture whatever the scale;
//   - the scale follows the frame time (DynamicScale), never below
//     kMinDynamicScale: a frame drawn at less than half the window's size
//     and scaled up looks worse than --scale 0.5.
#pragma once

#include "viewer/dynamic_scale.h"

#include "swell/camera.h"

#include <optional>

namespace swell::app::viewer {

// When the temporal resolve is on (--temporal).
enum class TemporalMode {
    WhileStill, // while the camera rests (the default: `auto`)
    Always,     // every frame, moving or not (`on`)
    Off,        // never: the scene's antialiasing instead (`off`)
};

// What the panel and the command line ask for.
struct QualitySettings {
    TemporalMode temporal = TemporalMode::WhileStill;
    // Dynamic resolution towards frameTarget_ms; off: `fixedScale` always.
    bool dynamicScale = true;
    double frameTarget_ms = 150.0;
    double fixedScale = 1.0;
};

// How the next frame is drawn.
struct FrameQuality {
    double renderScale = 1.0;
    bool temporal = false;
};

class ViewQuality {
public:
    // startScale: where dynamic resolution starts (clamped to its range).
    explicit ViewQuality(double startScale = kMaxDynamicScale);

    // Before each frame: how to draw it, given the settings, the camera about
    // to be drawn and the last frame's time (ms, the whole frame; 0 or less
    // for none: the first frames, which replay the simulation's history and
    // measure nothing).
    FrameQuality next(const QualitySettings& settings, const Camera& camera, double lastFrame_ms);

    // Frames the camera holds still before the resolve comes on: one frame
    // unchanged is often only a slow frame between two moves (a key held
    // across a slow frame still moves the camera every frame, but a mouse's
    // look may pause for one).
    static constexpr int kRestFrames = 2;

private:
    std::optional<DynamicScale> dynamic_;
    double scale_;
    std::optional<Camera> lastCamera_;
    int stillFrames_ = 0;
    bool lastTemporal_ = false;
};

// Whether two cameras draw the same view (pose and lens).
bool sameView(const Camera& a, const Camera& b);

} // namespace swell::app::viewer
