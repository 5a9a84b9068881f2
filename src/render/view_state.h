// What Swell keeps for one view between frames (Filament's per-view cache):
// its passes' targets and its temporal history. Kept per view, so that
// split screen and two eyes each keep their own history, and views of other
// sizes do not make each other's targets again every frame. render()'s
// frame is a view of its own; draw()'s views are told apart by
// DrawOptions::viewId. Library-internal.
#pragma once

#include "render/host_copy.h"
#include "render/render_target.h"
#include "render/temporal_resolve.h"
#include "render/water_visibility.h"
#include "render/waterline.h"

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <map>
#include <vector>

namespace swell::detail {

// What the host's motion vectors (render/motion_vectors.h) keep of a
// view's last draw that wrote them.
struct MotionHistory {
    bool drawn = false;
    double time_s = 0.0;      // the simulated time drawn, s
    glm::dmat4 viewProj{1.0}; // the host's view and projection then: absolute world to clip
    std::vector<glm::dmat4> poses; // each object's transform then, object to sea frame
};

struct ViewState {
    RenderTarget reflection, refraction;
    WaterlineMask waterline;
    // Where the main pass draws when the view is anti-aliased, scaled or
    // resolved over time (render_target.h).
    MainTarget mainTarget;
    // draw()'s copies of the host's picture under the viewport: its depth,
    // for its geometry under the water, and its colour and depth drawn into
    // the main target when the view is drawn through it.
    HostCopy hostDepth, hostPictureDepth, hostPictureColour;
    // The water's visibility pass's targets (render/water_visibility.h).
    WaterVisibility waterVisibility;
    TemporalResolve temporal;
    // Whether the last frame was resolved over time: turning it on or off
    // starts the history again.
    bool temporalOn = false;
    MotionHistory motion;
};

class ViewStates {
public:
    // render()'s own frame.
    ViewState& own() { return own_; }
    // draw()'s view `id`, made when first drawn.
    ViewState& host(std::uint32_t id) { return hosts_[id]; }
    // Gives a view's targets and history back (Renderer::releaseView).
    void release(std::uint32_t id) { hosts_.erase(id); }
    // Starts every view's history again.
    void resetHistories()
    {
        own_.temporal.reset();
        for (auto& [id, state] : hosts_)
            state.temporal.reset();
    }
    // The views drawn, render()'s included.
    std::size_t count() const { return hosts_.size() + 1; }

private:
    ViewState own_;
    std::map<std::uint32_t, ViewState> hosts_; // node-based: a view's state stays where it is
};

} // namespace swell::detail
