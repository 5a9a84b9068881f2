// The camera as a sensor: its lens's distortion, its exposure and its noise
// (the scene's camera.distortion_*, exposure_ev, noise_*), applied to a
// rendered frame and to its labels alike (docs/LABELS.md).
//
// Distortion is Brown-Conrady's (Brown 1966, "Decentering distortion of
// lenses", eq. 9-10; Conrady 1919), in OpenCV's form: for normalised
// undistorted image coordinates (x, y) (x right, y down, 1 unit = the focal
// length) and r^2 = x^2 + y^2,
//   x_d = x (1 + k1 r^2 + k2 r^4 + k3 r^6) + 2 p1 x y + p2 (r^2 + 2 x^2)
//   y_d = y (1 + k1 r^2 + k2 r^4 + k3 r^6) + p1 (r^2 + 2 y^2) + 2 p2 x y;
// or Kannala-Brandt's fisheye (Kannala & Brandt 2006, "A generic camera
// model and calibration method for conventional, wide-angle, and fish-eye
// lenses", IEEE TPAMI 28(8), eq. 6), in OpenCV's cv2.fisheye form: with
// r = sqrt(x^2 + y^2) and theta = atan(r) the ray's angle from the axis,
//   theta_d = theta (1 + k1 theta^2 + k2 theta^4 + k3 theta^6 + k4 theta^8)
//   (x_d, y_d) = (theta_d / r) (x, y).
// A fisheye's focal length follows from the field: the rays of the top and
// bottom borders' middles lie fovY / 2 from the axis, so
// f = (height / 2) / theta_d(fovY / 2) (a pinhole's is (height / 2) /
// tan(fovY / 2)).
// A distorted frame is drawn as a pinhole frame wide enough to hold every
// distorted pixel's ray, then resampled: colour bilinear, labels nearest
// (never a blend of two), ranges and normals with their labels. The
// pinhole frame bounds the field a fisheye can draw (docs/SCENE.md, "The
// lens": about 147 degrees across the diagonal).
#pragma once

#include "swell/export.h"

#include "swell/camera.h"
#include "swell/dataset/labels.h"
#include "swell/image.h"
#include "swell/scene/scene.h"

#include <glm/vec2.hpp>

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace swell {

class Renderer;

// A lens: Brown-Conrady's k1, k2, k3, p1, p2, or (model KannalaBrandt) the
// fisheye's k1, k2, k3, k4 (p1, p2 unused).
struct SWELL_API LensDistortion {
    double k1 = 0.0, k2 = 0.0, k3 = 0.0, p1 = 0.0, p2 = 0.0;
    double k4 = 0.0;
    LensModel model = LensModel::BrownConrady;
    // A pinhole: Brown-Conrady with every coefficient 0 (a fisheye with
    // every coefficient 0 is the equidistant fisheye, theta_d = theta).
    bool none() const
    {
        return model == LensModel::BrownConrady && k1 == 0.0 && k2 == 0.0 && k3 == 0.0 && p1 == 0.0 && p2 == 0.0;
    }
};

SWELL_API LensDistortion lensOf(const CameraSettings& camera);
// The lens a calibration holds, and a lens written into one.
SWELL_API LensDistortion lensOf(const CameraCalibration& calibration);
SWELL_API void setLens(CameraCalibration& calibration, const LensDistortion& lens);
// The calibration of the image `size` that `camera` draws through `lens`:
// calibrationOf() with the lens's coefficients, and for a fisheye the focal
// length that puts the field's borders fovY_deg / 2 from the axis (above).
SWELL_API CameraCalibration sensorCalibrationOf(const Camera& camera, const LensDistortion& lens, glm::ivec2 size);

// The fisheye's theta_d for a ray theta_rad from the axis (the equation
// above; the coefficients of a Kannala-Brandt lens).
SWELL_API double fisheyeThetaD(const LensDistortion& lens, double theta_rad);

// Normalised undistorted coordinates to distorted (the equations above, by
// the lens's model).
SWELL_API glm::dvec2 distort(const LensDistortion& lens, glm::dvec2 undistorted);
// The inverse: Brown-Conrady's by fixed-point iteration (converging where
// the lens maps the image one to one; within 1e-12 or after 50 steps), the
// fisheye's by Newton's method on theta_d(theta) (as OpenCV's
// fisheye::undistortPoints), within 1e-14 rad.
SWELL_API glm::dvec2 undistort(const LensDistortion& lens, glm::dvec2 distorted);
// Whether the ray at normalised undistorted coordinates `undistorted` lies
// inside the lens's fold: the distortion keeps the image's orientation all
// the way from the centre out to it (its Jacobian stays positive), so
// distort() gives the one place in the image that shows that ray. Past the
// fold, distort() lands on a place that shows another ray, nearer the axis
// (a radial k1 < 0 alone folds at r = 1 / sqrt(-3 k1)): no pixel shows it.
// A fisheye keeps it while theta_d grows with theta.
SWELL_API bool insideFold(const LensDistortion& lens, glm::dvec2 undistorted);

// Why `lens` cannot draw an image of `size` pixels at fovY_deg degrees of
// vertical field ("" when it can), by the one rule of docs/SCENE.md ("The
// lens"): every pixel of the image's border must have a ray, the lens must
// not fold between the image's centre and it (a fisheye's theta_d must grow
// with theta out to the farthest pixel's ray), and the pinhole frame drawn
// to hold those rays must be at most 4 times the image's side.
SWELL_API std::string lensProblem(const LensDistortion& lens, double fovY_deg, glm::ivec2 size);
// The same for a scene's lens (camera.distortion_*, or camera.lens and
// camera.fisheye_*): throws InputError naming every coefficient it sets
// (and a fisheye's camera.lens), at the first coefficient's place
// (Scene::keyPlaces), else camera.lens's, else at `sceneFile` ("camera"
// when empty).
SWELL_API void checkLens(const Scene& scene, glm::ivec2 size, double fovY_deg, const std::filesystem::path& sceneFile = {});

// When each row of the sensor gathers light (camera.shutter_s, readout_s,
// motion_samples). The frame's time is the middle of the exposure of the
// image's middle: row y (0 at the top, of `rows`) is read out at
//   t_y = t + ((y + 0.5) / rows - 0.5) readout_s
// (a rolling shutter reads the rows in turn from the top; readout_s = 0 is a
// global shutter) and gathers light over [t_y - shutter_s / 2,
// t_y + shutter_s / 2] (motion blur: the light of that window averaged,
// a box filter in time). The frame is drawn motion_samples times, evenly
// over the span [t - (readout_s + shutter_s) / 2, t + (readout_s +
// shutter_s) / 2], each draw at the middle of its share of it; a row
// averages, in linear light, the draws whose times lie in its window, or
// takes the draw nearest t_y when none does (a shutter shorter than the
// draws' spacing). With neither set, one draw at t. A draw that would come
// before time 0, when the simulation starts, is drawn at 0.
struct SWELL_API SensorTiming {
    std::vector<double> drawTimes_s; // ascending
    // For each row, the first and last draw (indices into drawTimes_s,
    // inclusive) it averages.
    std::vector<glm::ivec2> rowDraws;
};
SWELL_API SensorTiming sensorTimingOf(const CameraSettings& camera, double time_s, int rows);

// A frame as the scene's camera sees it: drawn by `renderer` for `camera`
// at time_s (Renderer::renderImage, advancing to time_s), distorted,
// exposed and noised as the renderer's scene says; with `labels`, its
// labels (Renderer::renderLabels) resampled through the same lens, with
// the lens's coefficients in their calibration, the horizon's distorted
// curve and the boxes measured on the distorted masks. Throws
// swell::InputError (checkLens()) for a lens that cannot draw the frame (it
// is drawn at 1.5 times the output's focal length, so labels are within half
// a pixel).
struct SWELL_API SensorFrame {
    Image image;
    std::optional<FrameLabels> labels;
    Camera camera; // the camera of time_s (of the labels' instant)
};
SWELL_API SensorFrame renderSensorFrame(Renderer& renderer, const Camera& camera, double time_s, glm::ivec2 size,
                                        bool labels);
// The same for a camera that moves while the sensor gathers light
// (SensorTiming): each draw is seen by cameraAt(its time), e.g.
// Renderer::sceneCameraAt for the scene's own camera (on its path or on a
// deck). The labels are of time_s alone, seen by cameraAt(time_s): the
// instant at the middle of the middle row's exposure (docs/LABELS.md).
using CameraAt = std::function<Camera(double time_s)>;
// `simulatedAround`: the camera whose eye the simulation is advanced around
// at each draw's time (a rig's platform, so that its cameras are drawn
// from one state); empty: the drawn camera's own.
SWELL_API SensorFrame renderSensorFrame(Renderer& renderer, const CameraAt& cameraAt, double time_s, glm::ivec2 size,
                                        bool labels, const CameraAt& simulatedAround = {});
// The labels renderSensorFrame() gives, without drawing the image (the
// next frame's labels a still's optical flow is measured to).
SWELL_API FrameLabels renderSensorLabels(Renderer& renderer, const Camera& camera, double time_s, glm::ivec2 size);
// When the first draw of the frame at time_s is (SensorTiming): a host that
// anticipates its next frame (Renderer::anticipate) anticipates this.
SWELL_API double firstDrawTime_s(const CameraSettings& camera, double time_s);

// The frames of the scene's rig ([[camera.rig]], swell/dataset/platform.h)
// at time_s: the simulation advanced around the platform (the scene's
// camera, Renderer::sceneCameraAt), once for each time drawn, and every rig
// camera drawn from that state, in the rig's order, through the scene's
// lens and sensor.
struct SWELL_API RigFrame {
    std::string name;  // the rig camera's name
    Camera camera;     // where it stands at time_s, world
    SensorFrame frame;
};
SWELL_API std::vector<RigFrame> renderRigFrames(Renderer& renderer, double time_s, glm::ivec2 size, bool labels);

} // namespace swell
