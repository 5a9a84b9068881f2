// Which lenses a frame can be drawn through (docs/SCENE.md, "The lens"): the
// one rule the scene checks, sweeps, Python and the sensor's resampling
// (render/sensor_frame.cpp) all apply.
//
// A distorted frame is drawn as a pinhole frame wide enough to hold every
// output pixel's ray, then resampled (swell/dataset/sensor.h). That needs, for the
// output of the size asked at the field of view asked:
//   1. every pixel of the output's border to have a ray: undistort() finds a
//      point the lens maps onto it (within 1e-9 of a focal length);
//   2. the lens not to fold between the image's centre and that ray: the
//      distortion's Jacobian stays positive along the way (a lens that folds
//      shows two places of the scene in one pixel, and the resampling could
//      draw either);
//   3. the pinhole frame to be at most kMaxPinholeOverOutput times the
//      output's side (it is drawn at kPinholeScale times the output's focal
//      length, so that labels stay within half a pixel).
#pragma once

#include "swell/dataset/labels.h"
#include "swell/dataset/sensor.h"

#include <glm/vec2.hpp>

#include <string>

namespace swell::detail {

// The pinhole frame is drawn at this many times the output's focal length,
// so that a label taken from its nearest pixel lies within 0.5/1.5 of a
// pinhole pixel on each axis, 0.47 of an output pixel at most (where the
// lens does not magnify), inside the half pixel the labels promise.
inline constexpr double kPinholeScale = 1.5;
inline constexpr int kMaxPinholeOverOutput = 4;
// The widest field across the diagonal that the pinhole frame lets a
// fisheye draw, degrees: an equidistant fisheye (theta_d = theta) at 4 times
// the image's side reaches 147.3 at 640x480 and 147.5 at 1280x720
// (docs/SCENE.md, "The lens").
inline constexpr double kFisheyeDiagonalField_deg = 147.0;

// The pinhole frame's size (each side even, centred on the optical axis)
// that holds the ray of every pixel of the distorted output: the output's
// border undistorted, plus a pixel.
glm::ivec2 pinholeSize(const LensDistortion& lens, const CameraCalibration& c);

// Why the lens cannot draw the output `c` describes (rules 1 to 3 above),
// in words that name no key; "" when it can.
std::string lensFoldProblem(const LensDistortion& lens, const CameraCalibration& c, double fovY_deg);

} // namespace swell::detail
