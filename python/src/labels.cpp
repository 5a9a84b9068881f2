// Labels (swell/dataset/labels.h, docs/LABELS.md): the per-pixel range, normal,
// class and instance as NumPy arrays, each object's class and boxes, the
// camera's calibration and the horizon; the calibration and the horizon of
// any camera computed on the CPU too.
#include "labels.h"

#include "bindings.h"
#include "convert.h"
#include "swell/gpu/label_classes.h"

#include <pybind11/stl.h>

namespace swell::python {

namespace {

std::vector<py::ssize_t> imageShape(glm::ivec2 size) { return {size.y, size.x}; }

} // namespace

PyLabels toPython(FrameLabels&& labels)
{
    static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "glm::vec3 must be three packed floats");
    PyLabels out;
    out.size = labels.size;
    const std::vector<py::ssize_t> shape = imageShape(labels.size);
    out.depth_m = arrayOwning<float>(zDepthOf(labels), shape);
    out.range_m = arrayOwning<float>(std::move(labels.range_m), shape);
    out.normal = arrayOwning<float>(std::move(labels.normal), {labels.size.y, labels.size.x, 3});
    out.semantic = arrayOwning<std::uint16_t>(std::move(labels.semantic), shape);
    out.instance = arrayOwning<std::uint16_t>(std::move(labels.instance), shape);
    out.amodal = arrayOwning<std::uint8_t>(std::move(labels.amodal),
                                           {py::ssize_t(labels.objects.size()), labels.size.y, labels.size.x});
    out.classes = std::move(labels.classes);
    out.objects = std::move(labels.objects);
    out.camera = labels.camera;
    out.horizon = labels.horizon;
    out.trueHorizonDip_deg = labels.trueHorizonDip_deg;
    out.trueHorizon_px = std::move(labels.trueHorizon_px);
    out.shoreline = std::move(labels.shoreline);
    return out;
}

FrameLabels motionLabelsOf(const PyLabels& labels)
{
    FrameLabels out;
    out.size = labels.size;
    const std::size_t pixels = std::size_t(labels.size.x) * std::size_t(labels.size.y);
    out.range_m.assign(labels.range_m.data(), labels.range_m.data() + pixels);
    out.semantic.assign(labels.semantic.data(), labels.semantic.data() + pixels);
    out.instance.assign(labels.instance.data(), labels.instance.data() + pixels);
    out.camera = labels.camera;
    out.objects = labels.objects;
    return out;
}

void bindLabels(py::module_& m)
{
    py::class_<CameraCalibration>(m, "Calibration",
                                  "A pinhole camera as perception code calibrates one (OpenCV's axes: x right, y "
                                  "down, z forward), with its lens's distortion (Brown-Conrady's, or Kannala-Brandt's fisheye). Image conventions: x right, y down, pixel (i, j)'s "
                                  "centre at (i + 0.5, j + 0.5).")
        .def_property_readonly("size", [](const CameraCalibration& c) { return py::make_tuple(c.size.x, c.size.y); },
                               "(width, height), pixels.")
        .def_readonly("fx_px", &CameraCalibration::fx_px, "Focal length along x, pixels.")
        .def_readonly("fy_px", &CameraCalibration::fy_px, "Focal length along y, pixels.")
        .def_readonly("cx_px", &CameraCalibration::cx_px, "Principal point x, pixels.")
        .def_readonly("cy_px", &CameraCalibration::cy_px, "Principal point y, pixels.")
        .def_property_readonly(
            "intrinsics",
            [](const CameraCalibration& c) {
                py::array_t<double> k({3, 3});
                auto a = k.mutable_unchecked<2>();
                const double values[3][3] = {{c.fx_px, 0.0, c.cx_px}, {0.0, c.fy_px, c.cy_px}, {0.0, 0.0, 1.0}};
                for (int r = 0; r < 3; ++r)
                    for (int col = 0; col < 3; ++col)
                        a(r, col) = values[r][col];
                return k;
            },
            "The 3x3 matrix K = [[fx, 0, cx], [0, fy, cy], [0, 0, 1]].")
        .def_property_readonly(
            "camera_from_world", [](const CameraCalibration& c) { return toArray(c.cameraFromWorld); },
            "4x4, absolute world points (m, y up) to camera axes: p_camera = M @ [x, y, z, 1].")
        .def_property_readonly(
            "world_from_camera", [](const CameraCalibration& c) { return toArray(c.worldFromCamera); },
            "4x4, the inverse of camera_from_world.")
        .def_property_readonly(
            "distortion_model",
            [](const CameraCalibration& c) {
                return c.lensModel == LensModel::KannalaBrandt ? "kannala-brandt" : "brown-conrady";
            },
            "The lens's model, as the labels' JSON names it: \"brown-conrady\" or \"kannala-brandt\" (a fisheye, "
            "OpenCV's cv2.fisheye).")
        .def_property_readonly(
            "distortion",
            [](const CameraCalibration& c) {
                return c.lensModel == LensModel::KannalaBrandt ? py::make_tuple(c.k1, c.k2, c.k3, c.k4)
                                                                : py::make_tuple(c.k1, c.k2, c.p1, c.p2, c.k3);
            },
            "The lens's coefficients in OpenCV's order: Brown-Conrady's (k1, k2, p1, p2, k3), all 0 for a pinhole; "
            "a fisheye's (k1, k2, k3, k4), cv2.fisheye's D.")
        .def(
            "project",
            [](const CameraCalibration& c, py::handle world_m) -> py::object {
                const std::optional<glm::dvec2> p = projectToImage(c, toVec3(world_m, "world_m"));
                return p ? py::object(toTuple(*p)) : py::none();
            },
            py::arg("world_m"), "Where a world point (m) lands in the image, (x, y) pixels; None behind the camera.");

    py::class_<HorizonLine>(m, "Horizon",
                            "The sea's horizon as drawn: the vanishing line of the sea-level plane, "
                            "a x + b y + c = 0 in pixels with (a, b) a unit vector towards the sky.")
        .def_property_readonly("line", [](const HorizonLine& h) { return toTuple(h.line); }, "(a, b, c).")
        .def_readonly("visible", &HorizonLine::visible, "Whether the line crosses the image.")
        .def_property_readonly("from_px", [](const HorizonLine& h) { return toTuple(h.from_px); },
                               "Where it meets the image's border (x, y), pixels, when visible.")
        .def_property_readonly("to_px", [](const HorizonLine& h) { return toTuple(h.to_px); },
                               "The other border point (x, y), pixels, when visible.")
        .def_property_readonly(
            "curve_px",
            [](const HorizonLine& h) {
                py::list points;
                for (const glm::dvec2& p : h.curve_px)
                    points.append(toTuple(p));
                return points;
            },
            "Through a distorting lens, points (x, y) along the horizon's curve in the image; empty for a pinhole.");

    py::class_<ObjectLabel>(m, "ObjectLabel", "One scene object in a frame.")
        .def_readonly("instance", &ObjectLabel::instance, "Its value in Labels.instance: its index in the scene's objects + 1.")
        .def_readonly("class_id", &ObjectLabel::semanticClass, "Its value in Labels.semantic.")
        .def_readonly("class_name", &ObjectLabel::className, "Labels.classes[class_id]: 'boat', or the model file's name.")
        .def_readonly("visible_pixels", &ObjectLabel::visiblePixels, "How many pixels show it.")
        .def_property_readonly(
            "box_px", [](const ObjectLabel& o) { return py::make_tuple(o.box_px.x, o.box_px.y, o.box_px.z, o.box_px.w); },
            "(x0, y0, x1, y1), pixels: the smallest box of its visible pixels, x1 and y1 one past its last; "
            "all 0 when none is visible.")
        .def_property_readonly(
            "box3d_m",
            [](const ObjectLabel& o) {
                py::array_t<double> corners({8, 3});
                auto a = corners.mutable_unchecked<2>();
                for (int i = 0; i < 8; ++i)
                    for (int j = 0; j < 3; ++j)
                        a(i, j) = o.box3d_m[std::size_t(i)][j];
                return corners;
            },
            "(8, 3): the corners of its mesh's bounding box in its own axes, placed at its pose this frame; "
            "absolute world, m.")
        .def_property_readonly(
            "world_from_object", [](const ObjectLabel& o) { return toArray(o.pose.worldFromObject); },
            "4x4, its model's points (m, its own axes) to absolute world: T(position_m) Ry(yaw) Rz(pitch) Rx(roll) "
            "S(scale) (docs/LABELS.md).")
        .def_property_readonly(
            "position_m", [](const ObjectLabel& o) { return toArray(o.pose.position_m); },
            "(3,): its model's origin, absolute world, m.")
        .def_property_readonly("yaw_deg", [](const ObjectLabel& o) { return o.pose.yaw_deg; },
                               "About the world's +y, as the scene's objects[].yaw_deg, degrees.")
        .def_property_readonly("pitch_deg", [](const ObjectLabel& o) { return o.pose.pitch_deg; },
                               "About its model's +z after the yaw (+x up for > 0), degrees.")
        .def_property_readonly("roll_deg", [](const ObjectLabel& o) { return o.pose.roll_deg; },
                               "About its model's +x after the pitch (+y towards +z for > 0), degrees.")
        .def_property_readonly("heading_deg", [](const ObjectLabel& o) { return o.pose.heading_deg; },
                               "The bearing of its model's +x axis, from -z towards +x, 0..360 degrees.")
        .def_property_readonly("scale", [](const ObjectLabel& o) { return o.pose.scale; }, "Its uniform scale.")
        .def_readonly("amodal_pixels", &ObjectLabel::amodalPixels,
                      "How many pixels its silhouette (Labels.amodal) covers in the image, hidden or not.")
        .def_readonly("occlusion", &ObjectLabel::occlusion,
                      "The share of its silhouette's pixels in the image that something nearer hides, 0..1.")
        .def_readonly("truncation", &ObjectLabel::truncation,
                      "The share of its whole silhouette outside the image, 0..1 (1 when none of it is in the image).")
        .def_property_readonly(
            "velocity_mps",
            [](const ObjectLabel& o) { return o.velocityKnown ? py::object(toArray(o.velocity_m_per_s)) : py::none(); },
            "(3,): its model origin's velocity, world axes, m/s (a rigid body's from the simulation's state, a fixed "
            "object's 0); None for an object that rides the water without being a rigid body.")
        .def_property_readonly(
            "angular_velocity_radps",
            [](const ObjectLabel& o) {
                return o.velocityKnown ? py::object(toArray(o.angularVelocity_rad_per_s)) : py::none();
            },
            "(3,): its angular velocity, world axes, rad/s (the axis it turns about, right-handed, its length the "
            "rate); None where velocity_mps is.")
        .def("__repr__", [](const ObjectLabel& o) {
            return "<swell.ObjectLabel " + std::to_string(o.instance) + " " + o.className + ", "
                   + std::to_string(o.visiblePixels) + " px>";
        });

    py::class_<PyLabels>(m, "Labels",
                         "The ground truth of one frame (docs/LABELS.md), aligned pixel for pixel with its colour "
                         "image; arrays hold rows top first.")
        .def_property_readonly("size", [](const PyLabels& l) { return py::make_tuple(l.size.x, l.size.y); },
                               "(width, height), pixels.")
        .def_readonly("range_m", &PyLabels::range_m,
                      "float32 (H, W): metres from the eye along each pixel's ray to what it shows; inf for the sky.")
        .def_readonly("depth_m", &PyLabels::depth_m,
                      "float32 (H, W): z-depth, metres along the camera's optical axis to the point range_m measures; "
                      "inf for the sky.")
        .def_readonly("normal", &PyLabels::normal, "float32 (H, W, 3): the unit surface normal, world axes; 0 for the sky.")
        .def_readonly("semantic", &PyLabels::semantic,
                      "uint16 (H, W): the class id (classes[id]): 1 sky, 2 water, 3 whitecap foam, 4 wake foam, "
                      "5 terrain, 16 and up the objects' classes.")
        .def_readonly("instance", &PyLabels::instance, "uint16 (H, W): 0, or the instance id of the object shown.")
        .def_readonly("amodal", &PyLabels::amodal,
                      "uint8 (N, H, W): objects[k]'s amodal mask at [k]: 1 where its silhouette (the object drawn "
                      "alone, over the water) covers the pixel, hidden or not.")
        .def_readonly("classes", &PyLabels::classes, "Each class id's name ('' where none).")
        .def_readonly("objects", &PyLabels::objects, "Every scene object's ObjectLabel, in the scene's order.")
        .def_readonly("camera", &PyLabels::camera, "The Calibration of this frame.")
        .def_readonly("horizon", &PyLabels::horizon, "The sea's Horizon in this frame.")
        .def_readonly("true_horizon_dip_deg", &PyLabels::trueHorizonDip_deg,
                      "The true horizon's dip below the horizontal for the camera's height over a round Earth, "
                      "degrees (the sea is drawn flat: it meets the sky on `horizon`).")
        .def_property_readonly(
            "true_horizon_px",
            [](const PyLabels& l) {
                py::list points;
                for (const glm::dvec2& p : l.trueHorizon_px)
                    points.append(toTuple(p));
                return points;
            },
            "Points (x, y) along that true horizon in the image, pixels.")
        .def_property_readonly(
            "shoreline",
            [](const PyLabels& l) {
                py::list chains;
                for (const ShoreLine& line : l.shoreline) {
                    py::array_t<double> px({py::ssize_t(line.points_px.size()), py::ssize_t(2)});
                    py::array_t<double> world({py::ssize_t(line.points_m.size()), py::ssize_t(3)});
                    auto pxv = px.mutable_unchecked<2>();
                    auto mv = world.mutable_unchecked<2>();
                    for (std::size_t i = 0; i < line.points_px.size(); ++i) {
                        pxv(py::ssize_t(i), 0) = line.points_px[i].x;
                        pxv(py::ssize_t(i), 1) = line.points_px[i].y;
                    }
                    for (std::size_t i = 0; i < line.points_m.size(); ++i)
                        for (int k = 0; k < 3; ++k)
                            mv(py::ssize_t(i), k) = line.points_m[i][k];
                    chains.append(py::make_tuple(px, world));
                }
                return chains;
            },
            "Where the water meets the land (docs/LABELS.md, shoreline): a list of chains, each (points_px (N, 2): "
            "pixel corners in order along the edge, points_m (N, 3): the water's point at each, absolute world, m; "
            "NaN where its range is infinite).");

    // The class ids of Labels.semantic, from the header the shaders share.
    m.attr("CLASS_NONE") = SWELL_LABEL_NONE;
    m.attr("CLASS_SKY") = SWELL_LABEL_SKY;
    m.attr("CLASS_WATER") = SWELL_LABEL_WATER;
    m.attr("CLASS_WHITECAP_FOAM") = SWELL_LABEL_WHITECAP_FOAM;
    m.attr("CLASS_WAKE_FOAM") = SWELL_LABEL_WAKE_FOAM;
    m.attr("CLASS_TERRAIN") = SWELL_LABEL_TERRAIN;
    m.attr("CLASS_SURF") = SWELL_LABEL_SURF;
    m.attr("CLASS_WET_SAND") = SWELL_LABEL_WET_SAND;
    m.attr("CLASS_FIRST_OBJECT") = SWELL_LABEL_FIRST_OBJECT_CLASS;

    m.def("calibration_of", [](const Camera& camera, py::handle size) { return calibrationOf(camera, imageSize(size)); },
          py::arg("camera"), py::arg("size"), "The Calibration of the image of `size` (width, height) that `camera` renders.");
    m.def("horizon_of", &horizonOf, py::arg("calibration"), "The Horizon of the sea-level plane for a Calibration.");
}

} // namespace swell::python
