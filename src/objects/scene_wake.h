// A scene's wake: one wake field (wake_field.h) stirred by the scene's
// floating bodies, stepped with them (objects/scene_bodies.h), and the
// source (SceneWakeSource) that adds it to the surface the bodies float on
// (swell::ComposedSurface). The renderer draws frameAt() of it;
// swell::DrawnSurface queries the same frame.
//
// The wake steps at the bodies' water-sample times (kWakeStep_s = 4 body
// steps): wake step k -> k + 1 takes the bodies' footprints where they stand
// at time k dt, after which the bodies can sample the water at (k + 1) dt.
// So bodies feel the waves every body makes, theirs included, and all of it
// follows from the scene and the time alone.
#pragma once

#include "objects/wake_field.h"
#include "objects/wake_frame.h"
#include "swell/scene/scene.h"
#include "swell/scene/seabed.h"
#include "swell/surface_source.h"

#include <memory>
#include <vector>

namespace swell::detail {

class SceneWake {
public:
    // The wake of `settings` over water of depth depth_m or, with a sea
    // floor, of the floor's depth under the grid's centre (at most depth_m):
    // one depth for the whole grid (its waves are Fourier modes), taken
    // again as the grid moves, so a boat running into shallow water leaves
    // the wider wake of its depth (Havelock 1908).
    SceneWake(const WakeSettings& settings, double depth_m, std::shared_ptr<const Seabed> seabed = nullptr);
    SceneWake(const SceneWake&) = delete;
    SceneWake& operator=(const SceneWake&) = delete;

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
    // The largest |height| of the two last states, m: what any time's blend stays within.
    double reach_m() const;

    const WakeField& field() const { return field_; }

private:
    // Where time_s falls: 0 at the previous state, 1 at the current one.
    double blendAt(double time_s) const;

    // The floor's depth under focus_m, m: within [kShallowestWake_m, seaDepth_m_].
    double depthAt(glm::dvec2 focus_m) const;

    WakeField field_;
    double seaDepth_m_;
    std::shared_ptr<const Seabed> seabed_; // null: the sea's depth everywhere
    // The state before the current one, on its own grid.
    std::vector<float> previousHeights_, previousFoam_;
    glm::ivec2 previousCorner_{0};
};

// The wake as the bodies feel it: heightAt() at its states, blended
// between them (exact at whole steps, where the bodies sample it), added
// to the waves by a swell::ComposedSurface on the bodies' clock. Its slopes
// are left out (0): the bodies read heights alone, never the normal, and
// the drawn wake's slopes are its frame's (WakeSurfaceSource), which this
// shares its GLSL with. `wake` must outlive it.
class SceneWakeSource final : public SurfaceSource {
public:
    explicit SceneWakeSource(const SceneWake& wake) : wake_(wake) {}

    glm::dvec3 heightAt(glm::dvec2 restPoint_m, double time_s) const override;
    double reach_m(double time_s) const override;
    std::string glsl() const override;
    SurfaceSourceParameters gpuParameters(double time_s, glm::dvec3 renderOrigin_m) const override;

private:
    const SceneWake& wake_;
};

} // namespace swell::detail
