// Forward optical flow between two labelled frames (docs/LABELS.md, "Optical
// flow"): for each pixel of the frame at time t, where the point its centre
// ray meets is seen in the frame at t + dt, and whether it is seen there at
// all. Computed on the CPU from the first frame's range and class per pixel
// and the exact motion of what the pixel shows: a water point is the same
// material point of the sea (its rest point displaced by the waves at
// t + dt), an object's point keeps its place in the object's axes (the
// body's pose at t + dt), the land stays; each is projected with the second
// frame's camera (which may ride a body) through its lens.
#pragma once

#include "swell/export.h"

#include "swell/dataset/labels.h"
#include "swell/scene/grid.h"
#include "swell/scene/scene.h"
#include "swell/sea_frame.h"
#include "swell/surface_query.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

namespace swell {

// How the sea's points move: the wave model drawn (each rest point's
// displacement at a time), filtered as the drawn grid filters it, in the
// world the sea frame gives. `surface` is borrowed: it must outlive the
// SeaMotion's use.
struct SWELL_API SeaMotion {
    const SurfaceQuery* surface = nullptr;
    GridShape shape;   // the drawn grid (its cells' sizes drive the waves' filter)
    HorizonFade fade;  // where wave heights fade to the flat plane
    SeaFrame sea;      // the mean sea level
};
// The motion of the sea `surface` draws for `scene` (Renderer::waveModel()
// and Renderer::scene()).
SWELL_API SeaMotion seaMotionOf(const Scene& scene, const SurfaceQuery& surface);

// Rows top first, as FrameLabels.
struct SWELL_API FrameFlow {
    glm::ivec2 size{0};
    double interval_s = 0.0; // dt: the second frame's time less the first's, s
    // Per pixel, pixels in the image conventions of LABELS.md: where the
    // point is seen at t + dt less the pixel's centre. For the sky (no
    // point), the motion of its direction (a point at infinity: the
    // camera's turn alone).
    std::vector<glm::vec2> flow_px;
    // 1 where the point is seen at t + dt: in front of the camera, inside
    // the image (and the lens's fold), and not behind something nearer
    // there (visibleAt()); 0 elsewhere, and always for the sky.
    std::vector<std::uint8_t> valid;
};

// The flow from `now` (drawn at time_s) to `next` (drawn at time_s +
// interval_s, with the same size and objects). Their cameras, objects'
// poses and ranges are the labels' own; the sea's motion is `sea`'s.
SWELL_API FrameFlow opticalFlowOf(const FrameLabels& now, double time_s, const FrameLabels& next, double interval_s,
                                  const SeaMotion& sea);

// Whether a point at `range_m` from the second frame's eye, seen at
// `place_px` there, is what that frame shows: some pixel of the 2 x 2
// around the place (the four whose centres surround it) shows something at
// least as far, less a tolerance of 2% of the range and 5 cm (the drawn
// surface's triangles and the label's float32 within it). Outside the
// image: false.
SWELL_API bool visibleAt(const FrameLabels& next, glm::dvec2 place_px, double range_m);

} // namespace swell
