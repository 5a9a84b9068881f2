// The host's motion vectors (DrawOptions::motionVectors; docs/LIBRARY.md
// "Motion vectors"): after draw() presented the view, Swell's surfaces are
// drawn again into the host's attachment at the host's viewport, depth-
// tested against the host's depth as it now stands (the water's written
// into it), each fragment writing where its point was in the view's
// previous draw: the water's grid vertex displaced at the previous time
// (WaveModelGpu::prepareEarlierView), Swell's objects at their previous
// poses, the island and seabed where they are, the sky's directions turned
// with the camera alone; all through the previous draw's view and
// projection. Library-internal.
#pragma once

#include "render/programs.h"
#include "render/view_frame.h"
#include "render/view_passes.h"
#include "render/view_state.h"
#include "swell/gl/handle.h"

#include <cstddef>
#include <optional>

namespace swell::detail {

class MotionVectors {
public:
    // Writes the view's motion vectors into request.output's attachment
    // request.options.motionVectors and keeps what the view's next draw
    // needs in state.motion. Builds its programs when first asked.
    void draw(RenderContext& context, ViewState& state, const ViewFrame& v, const ViewRequest& request);

private:
    // The water grid's vertices at the previous time, into previousWater_.
    void placePreviousWater(RenderContext& context, const ViewFrame& v, std::optional<double> previous_s);

    std::optional<MotionPrograms> programs_;
    gl::Buffer previousWater_; // a vec4 a grid vertex (water_previous.vert)
    std::size_t previousWaterBytes_ = 0;
};

} // namespace swell::detail
