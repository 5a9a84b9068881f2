// The camera: a pose and a lens in world metres and degrees. Each field is
// checked on assignment against the range the parameter table gives the
// scene's camera key of the same name (camera.pitch_deg: -89..89 deg), so
// a camera built in Python accepts exactly what a scene file does.
#include "bindings.h"
#include "convert.h"

#include "swell/camera.h"
#include "swell/scene/parameters.h"


namespace swell::python {

namespace {

// The table's parameter for a camera field ("camera.fov_y_deg").
const Parameter& cameraParameter(const char* key)
{
    const Parameter* p = findParameter(key);
    if (!p)
        throw Error(std::string("swell.Camera: no parameter ") + key + " in the table");
    return *p;
}

double checked(const char* key, const char* field, double x)
{
    const Parameter& p = cameraParameter(key);
    if (!inRange(p, x))
        throw py::value_error(rangeMessage(p, std::string("Camera.") + field, x));
    return x;
}

glm::dvec3 checkedPosition(py::handle value)
{
    const glm::dvec3 v = toVec3(value, "Camera.position_m");
    const Parameter& p = cameraParameter("camera.position_m");
    for (int i = 0; i < 3; ++i)
        if (!inRange(p, v[i]))
            throw py::value_error(rangeMessage(p, "Camera.position_m[" + std::to_string(i) + "]", v[i]));
    return v;
}

// A scalar field bound with its range check.
template <double Camera::*Field>
void bindField(py::class_<Camera>& c, const char* name, const char* key, const char* doc)
{
    c.def_property(
        name, [](const Camera& camera) { return camera.*Field; },
        [name, key](Camera& camera, double x) { camera.*Field = checked(key, name, x); }, doc);
}

} // namespace

void bindCamera(py::module_& m)
{
    py::class_<Camera> c(m, "Camera",
                         "A perspective camera: position_m (world, m, y up), yaw_deg (heading from -z towards "
                         "+x), pitch_deg (up +), roll_deg (about the view direction, + banks right), "
                         "fov_y_deg (vertical field of view), near_m and far_m (clip planes). Each field is "
                         "checked against the range of the scene key camera.<field>.");
    c.def(py::init([](py::handle position_m, double yaw_deg, double pitch_deg, double roll_deg, double fov_y_deg,
                      double near_m, double far_m) {
              Camera camera;
              camera.position_m = checkedPosition(position_m);
              camera.yaw_deg = checked("camera.yaw_deg", "yaw_deg", yaw_deg);
              camera.pitch_deg = checked("camera.pitch_deg", "pitch_deg", pitch_deg);
              camera.roll_deg = checked("camera.roll_deg", "roll_deg", roll_deg);
              camera.fovY_deg = checked("camera.fov_y_deg", "fov_y_deg", fov_y_deg);
              camera.near_m = checked("camera.near_m", "near_m", near_m);
              camera.far_m = checked("camera.far_m", "far_m", far_m);
              return camera;
          }),
          py::arg("position_m") = py::make_tuple(0.0, 6.0, 0.0), py::arg("yaw_deg") = 0.0, py::arg("pitch_deg") = 0.0,
          py::arg("roll_deg") = 0.0, py::arg("fov_y_deg") = 60.0, py::arg("near_m") = 0.1, py::arg("far_m") = 20000.0);
    c.def_property(
        "position_m", [](const Camera& camera) { return toTuple(camera.position_m); },
        [](Camera& camera, py::handle v) { camera.position_m = checkedPosition(v); },
        "World position (x, y, z), m; y is up. Read as a tuple: assign a whole new position.");
    bindField<&Camera::yaw_deg>(c, "yaw_deg", "camera.yaw_deg", "Heading, degrees from -z towards +x.");
    bindField<&Camera::pitch_deg>(c, "pitch_deg", "camera.pitch_deg", "Up (+) or down (-) from the horizon, degrees.");
    bindField<&Camera::roll_deg>(c, "roll_deg", "camera.roll_deg",
                                 "About the view direction, degrees: + banks the camera to the right.");
    bindField<&Camera::fovY_deg>(c, "fov_y_deg", "camera.fov_y_deg", "Vertical field of view, degrees.");
    bindField<&Camera::near_m>(c, "near_m", "camera.near_m", "Near clip plane, m.");
    bindField<&Camera::far_m>(c, "far_m", "camera.far_m", "Far clip plane, m (more than near_m when rendering).");
    c.def_property_readonly(
        "forward", [](const Camera& camera) { return toTuple(camera.forward()); }, "The unit view direction, world axes.");
    c.def("__repr__", [](const Camera& camera) {
        return "swell.Camera(position_m=" + std::string(py::repr(toTuple(camera.position_m)))
               + ", yaw_deg=" + std::string(py::repr(py::float_(camera.yaw_deg)))
               + ", pitch_deg=" + std::string(py::repr(py::float_(camera.pitch_deg)))
               + ", roll_deg=" + std::string(py::repr(py::float_(camera.roll_deg)))
               + ", fov_y_deg=" + std::string(py::repr(py::float_(camera.fovY_deg)))
               + ", near_m=" + std::string(py::repr(py::float_(camera.near_m)))
               + ", far_m=" + std::string(py::repr(py::float_(camera.far_m))) + ")";
    });
}

} // namespace swell::python
