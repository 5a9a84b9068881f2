// A scene's wake: one wake field (wake_field.h) stirred by the scene's
// floating bodies, stepped with them (objects/scene_bodies.h), and the
// surface the bodies float on: the wave model plus the wake. The renderer
// draws frameAt() of it; swell::DrawnSurface queries the same frame.
//
// The wake steps at the bodies' water-sample times (kWakeStep_s = 4 body
// steps): wake step k -> k + 1 takes the bodies' footprints where they stand
// at time k dt, after which the bodies can sample the water at (k + 1) dt.
// So bodies feel the waves every body makes, theirs included, and all of it
// follows from the scene and the time alone.
#pragma once

#include "objects/wake_field.h"
#include "objects/wake_frame.h"
#include "swell/scene.h"
#include "swell/wave_model.h"

#include <memory>
#include <vector>

namespace swell::detail {

class SceneWake {
public:
    // The wake of `settings` over water of depth depth_m on `waves`, which
    // must outlive this.
    SceneWake(const WakeSettings& settings, double depth_m, const WaveModel& waves);
    ~SceneWake();
    SceneWake(const SceneWake&) = delete;
    SceneWake& operator=(const SceneWake&) = delete;

    // The waves plus the wake at the query's time: what bodies float on.
    const WaveModel& surface() const { return *surface_; }

    // Flat water at time 0, the grid centred on focus_m.
    void reset(glm::dvec2 focus_m);
    // Wake steps taken since the last reset: the state is at time steps() * kWakeStep_s.
    std::int64_t steps() const { return field_.steps(); }
    // One step from the sources as they stand now, the grid first moved to centre on focus_m.
    void step(const std::vector<WakeSource>& sources, glm::dvec2 focus_m);

    // The wake's height at a world point and time, m, between the two last
    // states (the latest for later times): exact at whole steps, where the
    // bodies sample it.
    double heightAt(glm::dvec2 world_m, double time_s) const;
    // The frame the renderer draws at time_s (between the two last states).
    WakeFrame frameAt(double time_s) const;

    const WakeField& field() const { return field_; }

private:
    // Where time_s falls: 0 at the previous state, 1 at the current one.
    double blendAt(double time_s) const;

    WakeField field_;
    // The state before the current one, on its own grid.
    std::vector<float> previousHeights_, previousFoam_;
    glm::ivec2 previousCorner_{0};
    std::unique_ptr<WaveModel> surface_;
};

} // namespace swell::detail
