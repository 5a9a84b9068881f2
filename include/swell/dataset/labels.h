// Ground truth for a frame, aligned pixel for pixel with its colour image
// (docs/LABELS.md): the range along each pixel's ray, its surface normal,
// its semantic class and instance, each object's boxes, the camera's
// calibration and the sea's horizon line. Image conventions: x to the right,
// y down, the top-left pixel's top-left corner at (0, 0), so pixel (i, j)'s
// centre is (i + 0.5, j + 0.5); arrays hold rows top first.
#pragma once

#include "swell/export.h"

#include "swell/camera.h"
#include "swell/gpu/label_classes.h"
#include "swell/scene/scene.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace swell {

// A pinhole camera as perception code calibrates one. Camera axes as in
// computer vision: x right, y down, z forward (OpenCV's); with its lens's
// model and coefficients (all 0 for a pinhole).
struct SWELL_API CameraCalibration {
    glm::ivec2 size{0};          // pixels
    double fx_px = 0.0, fy_px = 0.0; // focal lengths, pixels
    double cx_px = 0.0, cy_px = 0.0; // principal point, pixels (image conventions above)
    glm::dmat4 cameraFromWorld{1.0}; // absolute world (m, y up) to camera axes
    glm::dmat4 worldFromCamera{1.0};
    // The lens (swell/dataset/sensor.h). Brown-Conrady: its coefficients in
    // OpenCV's order k1, k2, p1, p2, k3 (k4 0); all 0 for a pinhole.
    // Kannala-Brandt's fisheye: k1..k4 as OpenCV's cv2.fisheye takes them
    // (p1, p2 0).
    LensModel lensModel = LensModel::BrownConrady;
    double k1 = 0.0, k2 = 0.0, p1 = 0.0, p2 = 0.0, k3 = 0.0, k4 = 0.0;
};

// The calibration of the image `size` that a Camera renders.
SWELL_API CameraCalibration calibrationOf(const Camera& camera, glm::ivec2 size);

// Where a world point (absolute, m) lands in the image, pixels, through the
// lens's distortion when it has one; empty behind the camera, and empty
// past the lens's fold (insideFold(), swell/dataset/sensor.h), where the
// image shows another ray at the place the distortion gives.
SWELL_API std::optional<glm::dvec2> projectToImage(const CameraCalibration& camera, glm::dvec3 world_m);

// The sea's horizon as it is drawn: the vanishing line of the sea-level
// plane (the sea is drawn flat, without the Earth's curvature; the labels'
// water continues past the drawn grid to it). In pixels, a x + b y + c = 0
// with (a, b) a unit vector pointing to the sky's side.
struct SWELL_API HorizonLine {
    glm::dvec3 line{0.0};
    bool visible = false;      // the line crosses the image
    glm::dvec2 from_px{0.0}, to_px{0.0}; // where it meets the image's border (when visible)
    // Through a distorting lens the horizon is a curve: points along it in
    // the image (every 4 px of the line), the line above holding for the
    // undistorted (pinhole) image. Only the line's points inside the lens's
    // fold, whose rays the image shows; empty for a pinhole.
    std::vector<glm::dvec2> curve_px;
};
SWELL_API HorizonLine horizonOf(const CameraCalibration& camera);
// The curve_px of `horizon` (horizonOf(camera)) through the camera's lens.
SWELL_API std::vector<glm::dvec2> horizonCurveOf(const CameraCalibration& camera, const HorizonLine& horizon);

// The true horizon of a round Earth for an eye eyeHeight_m above the sea:
// its geometric dip below the horizontal, rad, acos(R / (R + h)) with the
// mean radius R = 6371 km (without the atmosphere's refraction, which
// lessens it by about a twelfth; Bowditch 2002, The American Practical
// Navigator, table 22's geometric dip 1.93' sqrt(h)). 0 at or below the sea.
SWELL_API double horizonDip_rad(double eyeHeight_m);
// Points along that true horizon in the image (the directions at -dip all
// round the eye, projected through the lens), every ~2 px; empty when none
// falls in the image.
SWELL_API std::vector<glm::dvec2> trueHorizonOf(const CameraCalibration& camera, double eyeHeight_m);

// An object's pose: where its model's axes (m, as its glTF file or the
// built-in gives them: the built-in boat's bow at +x, up +y) stand in the
// world. Its rotation is R = Ry(yaw) Rz(pitch) Rx(roll), each right-handed
// about the axis named: yaw about the world's +y (the sense of the scene's
// objects[].yaw_deg, so a fixed object's yaw_deg is its own), then pitch
// about the model's +z (+x, the bow, up for pitch > 0), then roll about the
// model's +x (+y, the deck's up, towards +z for roll > 0: a boat heeling to
// starboard, +z at its bow's right). world_from_object = T(position_m)
// R S(scale).
struct SWELL_API ObjectPose {
    glm::dmat4 worldFromObject{1.0}; // model axes (m) to absolute world (m, y up), scale included
    glm::dvec3 position_m{0.0};      // its model's origin, absolute world, m
    double yaw_deg = 0.0;            // -180..180
    double pitch_deg = 0.0;          // -90..90
    double roll_deg = 0.0;           // -180..180
    // The bearing of its model's +x axis (the built-in boat's bow) on the
    // sea, measured as headings are (docs/SCENE.md: from -z, north, towards
    // +x, east), 0..360: 90 - yaw_deg for an object that does not tilt.
    double heading_deg = 0.0;
    double scale = 1.0;
};
// The pose a model-to-world transform (a rotation, a uniform scale and a
// translation, as the renderer places objects) describes.
SWELL_API ObjectPose objectPoseOf(const glm::dmat4& worldFromObject);
// The transform of a pose's position, angles and scale (the inverse of
// objectPoseOf, up to the angles' ranges).
SWELL_API glm::dmat4 worldFromObjectOf(glm::dvec3 position_m, double yaw_deg, double pitch_deg, double roll_deg,
                                       double scale);

// One scene object in a frame.
struct SWELL_API ObjectLabel {
    std::uint16_t instance = 0;      // its value in FrameLabels::instance (its index in scene.objects + 1)
    std::uint16_t semanticClass = 0; // its value in FrameLabels::semantic
    std::string className;           // FrameLabels::classes[semanticClass]
    long long visiblePixels = 0;
    // The smallest box of its visible pixels: x0, y0 (its top-left pixel's
    // corner), x1, y1 (one past its bottom-right pixel), pixels; zero when
    // none is visible.
    glm::ivec4 box_px{0};
    // Its mesh's bounding box in its own axes, placed at its pose: the
    // eight corners, absolute world, m.
    std::array<glm::dvec3, 8> box3d_m{};
    // Its pose this frame (a floating body's heave, roll and pitch included).
    ObjectPose pose;
    // How it moves this frame, world axes: its model origin's (position_m's)
    // velocity, m/s, and its angular velocity, rad/s (along the axis it turns
    // about, right-handed, its length the rate). A floating rigid body's from
    // the simulation's state (FloatingBody::velocityAt), a fixed object's
    // zero; not known (velocityKnown false, both zero) for an object that
    // rides the drawn water without being a rigid body (it has no state).
    bool velocityKnown = false;
    glm::dvec3 velocity_m_per_s{0.0};
    glm::dvec3 angularVelocity_rad_per_s{0.0};
    // How much of it shows. Its silhouette is the object drawn alone (the
    // label pass with no other object, no island and no sea floor; the
    // water's surface kept, so the hull under the waterline is no part of
    // it): FrameLabels::amodal, amodalPixels of them in the image.
    // occlusion: the share of those that something nearer hides, 1 -
    // visiblePixels / amodalPixels. truncation: the share of its whole
    // silhouette that falls outside the image, measured on a render of it
    // alone over a field three times the image's width and height (one
    // image past each border: a part farther out is not counted). With no
    // silhouette pixel in the image, occlusion is 0 and truncation 1.
    long long amodalPixels = 0;
    double occlusion = 0.0;
    double truncation = 0.0;
    // The whole silhouette's pixels in the pinhole frame it was drawn in,
    // inside the image and out (the lens's resampling measures the
    // truncation of its own image against it).
    long long silhouettePixels = 0;
};

// The water's edge in the image: a chain of the pixel grid's corners along
// which drawn water (the water and foam classes) meets land (the terrain
// class: the island, the sea floor's shapes) across a pixel's side.
struct SWELL_API ShoreLine {
    // Pixel corners, image coordinates (x right, y down; pixel (i, j)
    // covers [i, i + 1] x [j, j + 1]), in order along the edge.
    std::vector<glm::dvec2> points_px;
    // For each, the water's point at that corner: the range of a water
    // pixel that touches it along that pixel's centre ray, absolute world,
    // m; NaN where that range is infinite (the water's depths from below).
    std::vector<glm::dvec3> points_m;
};

struct SWELL_API FrameLabels {
    glm::ivec2 size{0};
    // Per pixel, rows top first. range_m: the distance from the eye along
    // the pixel's ray to what it shows, m; +infinity for the sky and the
    // water's depths seen from below. The water runs on past the drawn grid
    // to the horizon as the plane of the sea level.
    std::vector<float> range_m;
    std::vector<glm::vec3> normal; // unit, world axes; zero for the sky
    std::vector<std::uint16_t> semantic; // SWELL_LABEL_* and the objects' classes
    std::vector<std::uint16_t> instance; // 0, or an object's ObjectLabel::instance
    // Each object's amodal mask, in the order of `objects`: 1 where its
    // silhouette (ObjectLabel::amodalPixels) covers the pixel, hidden or
    // not, else 0; object k's mask at [k * W * H, (k + 1) * W * H), rows top first.
    std::vector<std::uint8_t> amodal;
    // Each semantic class's name by its value ("" where none): "none",
    // "sky", "water", "whitecap_foam", "wake_foam", "terrain", then from
    // SWELL_LABEL_FIRST_OBJECT_CLASS the objects' classes in the order they
    // first appear in the scene.
    std::vector<std::string> classes;
    std::vector<ObjectLabel> objects;
    CameraCalibration camera;
    HorizonLine horizon;
    // The true horizon of a round Earth for the camera's height: its dip,
    // degrees, and points along it in the image (horizonDip_rad,
    // trueHorizonOf). Swell draws the sea flat, so the drawn sea meets the
    // sky on `horizon`; the true horizon lies this far below it.
    double trueHorizonDip_deg = 0.0;
    std::vector<glm::dvec2> trueHorizon_px;
    // Where the water meets the land in this frame (measureShoreline): each
    // chain at least two corners long; none without land in view.
    std::vector<ShoreLine> shoreline;
};

// Each pixel's z-depth, m: the depth along the camera's optical axis
// (OpenCV's camera z) of the point its range measures, range / sqrt(1 + x^2
// + y^2) with (x, y) the normalised place of the pixel's centre ray
// (undistorted through the calibration's lens); +infinity where the range
// is. Rows top first, as range_m.
SWELL_API std::vector<float> zDepthOf(const FrameLabels& labels);

// A scene object's class: its `class` key (SceneObject::className) when
// given, else the built-in's name ("boat" for "builtin:boat"), else its
// model file's name without folder or extension.
SWELL_API std::string objectClassOf(const SceneObject& object);

// The class names of a scene: the fixed ones, then each object class once.
SWELL_API std::vector<std::string> labelClassesOf(const Scene& scene);

// Whether a semantic class is the sea's surface (the water and its foam,
// the surf's included) or the ground it meets (the terrain, wet or dry).
inline bool isSeaClass(std::uint16_t semantic)
{
    return semantic == SWELL_LABEL_WATER || semantic == SWELL_LABEL_WHITECAP_FOAM ||
           semantic == SWELL_LABEL_WAKE_FOAM || semantic == SWELL_LABEL_SURF;
}
inline bool isGroundClass(std::uint16_t semantic)
{
    return semantic == SWELL_LABEL_TERRAIN || semantic == SWELL_LABEL_WET_SAND;
}

// Fills each object's visible pixels and box from the instance image.
SWELL_API void measureObjectBoxes(FrameLabels& labels);

// Fills each object's amodalPixels from labels.amodal, and its occlusion
// from them and its visiblePixels (measureObjectBoxes first).
SWELL_API void measureOcclusion(FrameLabels& labels);

// Fills labels.shoreline from the semantic image, the ranges and the
// camera: the pixel sides between a water pixel and a land pixel, joined
// corner to corner into chains.
SWELL_API void measureShoreline(FrameLabels& labels);

} // namespace swell
