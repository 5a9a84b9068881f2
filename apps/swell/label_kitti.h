// A frame's objects as KITTI's 3D object benchmark labels them (the object
// development kit's readme.txt, Geiger et al. 2012): NAME.kitti.txt, one
// object a line, and NAME.kitti_calib.txt, the calibration that projects its
// boxes (docs/LABELS.md, "KITTI boxes"). The boxes stand in the levelled
// camera: at the eye, y down along gravity, z the view's heading on the
// sea, x right; P2 projects from there into the image.
#pragma once

#include "swell/dataset/labels.h"

#include <glm/mat4x4.hpp>

#include <string>

namespace swell::app {

// The levelled camera's axes from absolute world axes (rows: right, down,
// the heading on the sea), placed at the eye; `up`: the world's up in its
// axes (unit). A camera looking straight up or down takes its own y (down
// in the image) turned level for z.
glm::dmat4 levelFromWorld(const CameraCalibration& camera, glm::dvec3 up);

// The label file: for each object with some silhouette in the image
// (amodalPixels > 0): type, truncated, occluded, alpha, bbox (4), dimensions
// h w l, location x y z (its box's bottom centre), rotation_y. `up` as above.
std::string kittiLabels(const FrameLabels& labels, glm::dvec3 up);

// The calibration file: P0 to P3 (each K [R | 0], R the camera's axes from
// the levelled camera's), R0_rect (identity), Tr_velo_to_cam (the levelled
// camera from absolute world, 3x4: the world stands in for the laser
// scanner), Tr_imu_to_velo (identity).
std::string kittiCalibration(const FrameLabels& labels, glm::dvec3 up);

} // namespace swell::app
