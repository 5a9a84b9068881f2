// The parts of a frame's JSON (label_files.h) that say how each object moves
// and how much of it shows: its velocity in world and camera axes, its
// occlusion and truncation shares (docs/LABELS.md, "objects").
#pragma once

#include "swell/dataset/labels.h"

#include <nlohmann/json.hpp>

namespace swell::app {

// {"linear_mps", "angular_radps", "camera_linear_mps", "camera_angular_radps"}
// (world axes, then the camera's: OpenCV's, as camera_from_world turns
// them), or null where the object's velocity is not known.
nlohmann::ordered_json velocityJson(const ObjectLabel& object, const CameraCalibration& camera);

} // namespace swell::app
