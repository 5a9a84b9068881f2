// The labels' world quantities in the axes a scene asks for
// (labels.world_frame; docs/LABELS.md, "World frames"): Swell's own, ENU or
// NED, one rotation about Swell's origin. Quantities in the camera's or an
// object's own axes, pixels and angles do not change.
#pragma once

#include "swell/dataset/labels.h"
#include "swell/scene/scene.h"

#include <glm/mat3x3.hpp>

#include <string_view>

namespace swell::app {

// The rotation from Swell's world axes (x east, y up, z south) to the
// frame's: identity for Swell's; ENU (east, north, up) = (x, -z, y); NED
// (north, east, down) = (-z, x, -y).
glm::dmat3 frameFromSwell(LabelWorldFrame frame);

// The frame's name, as the scene key spells it.
std::string_view worldFrameName(LabelWorldFrame frame);

// `labels` with every world quantity turned into the frame's axes: the
// camera's world transforms, the normals, each object's box corners,
// world_from_object, position and velocities, the shoreline's points.
FrameLabels inWorldFrame(const FrameLabels& labels, LabelWorldFrame frame);

} // namespace swell::app
