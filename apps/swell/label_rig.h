// A frame JSON's `platform` and `rig` blocks (docs/LABELS.md, "Rigs and the
// platform"): the platform's pose, velocities, acceleration and IMU
// readings (swell/dataset/platform.h), and a rig camera's place on it.
#pragma once

#include "label_files.h"

#include "swell/camera.h"
#include "swell/dataset/labels.h"
#include "swell/dataset/platform.h"
#include "swell/scene/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace swell::app {

// The camera names of a scene's frames: its rig's, in order, or {""} for
// the one camera of a scene without a rig (whose files carry no name).
std::vector<std::string> frameCameras(const Scene& scene);

// The platform at the frame's time: world quantities in `frame`'s axes
// (labels.world_frame), the IMU's in the platform's own. `platform` is the
// scene's camera the motion belongs to (its angles give the heading, pitch
// and roll). `previous`: the platform at the clip's frame before, whose
// interval the IMU's increment covers (imu.increment; null without one: a
// clip's first frame, a still).
Json platformJson(const PlatformMotion& motion, const Camera& platform, LabelWorldFrame frame,
                  const std::optional<PlatformMotion>& previous);

// Where the rig camera `name` (whose calibration `camera` is, Swell's axes)
// stands on the platform: platform_from_camera (its OpenCV axes to the
// platform's) and its inverse, with the rig's camera names.
Json rigJson(const std::string& name, const CameraCalibration& camera, const PlatformMotion& motion,
             const std::vector<std::string>& cameras);

} // namespace swell::app
