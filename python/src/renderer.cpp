// The headless renderer: colour frames and their labels into NumPy arrays,
// the simulation stepped to a time (floating bodies, their wake, the foam),
// the bodies' transforms, and the water queried: the wave model's exact
// surface at any time, and the surface drawn at the simulated time.
//
// Every Renderer made in Python draws with one headless GL context (EGL,
// surfaceless), made on the first Renderer's thread and kept while any
// Renderer lives: a context of each renderer's own would not do, since
// destroying one terminates the EGL display the others use. A context is
// current on one thread, so a Renderer is used on that thread; another
// thread gets swell.Error, never a crash. Rendering and stepping release
// the GIL, so other Python threads run meanwhile.
#include "bindings.h"
#include "convert.h"
#include "labels.h"
#include "scene.h"

#include "swell/dataset/flow.h"
#include "swell/dataset/sensor.h"
#include "swell/error.h"
#include "swell/flat_model.h"
#include "swell/frame_request.h"
#include "swell/gl/context.h"
#include "swell/renderer.h"
#include "swell/scene/scene_file.h"

#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <optional>
#include <thread>

namespace swell::python {

namespace {

// The one headless context, with its driver messages logged once each to
// stderr as the swell executable logs them (same context flags, so a frame
// is the executable's frame bit for bit).
struct SharedContext {
    std::thread::id owner = std::this_thread::get_id();
    gl::DebugHandler debugHandler = gl::logOnceDebugHandler();
    gl::HeadlessContext context{true};
    SharedContext() { gl::installDebugHandler(&debugHandler); }
};

// Needs the GIL (which guards `current`).
std::shared_ptr<SharedContext> sharedContext()
{
    static std::weak_ptr<SharedContext> current;
    if (std::shared_ptr<SharedContext> context = current.lock())
        return context;
    auto context = std::make_shared<SharedContext>();
    current = context;
    return context;
}


// f(x, z) over NumPy's broadcast of x and z: a float for two scalars, else an
// array of the broadcast shape. Runs without the GIL.
template <class F>
py::object mapXZ(py::handle x, py::handle z, F f)
{
    const bool scalars = !py::isinstance<py::array>(x) && !py::isinstance<py::sequence>(x)
                         && !py::isinstance<py::array>(z) && !py::isinstance<py::sequence>(z);
    const py::module_ np = py::module_::import("numpy");
    py::tuple both;
    try {
        both = np.attr("broadcast_arrays")(np.attr("asarray")(x, "float64"), np.attr("asarray")(z, "float64"));
    } catch (const py::error_already_set& e) {
        // An int past a double's range (OverflowError), text, shapes that do not broadcast.
        throw py::type_error(std::string("x_m, z_m: numbers or arrays of numbers that broadcast together: ") + e.what());
    }
    const auto xs = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(both[0]);
    const auto zs = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(both[1]);
    py::array_t<double> out(std::vector<py::ssize_t>(xs.shape(), xs.shape() + xs.ndim()));
    const double* px = xs.data();
    const double* pz = zs.data();
    double* po = out.mutable_data();
    const py::ssize_t n = xs.size();
    {
        py::gil_scoped_release release;
        for (py::ssize_t i = 0; i < n; ++i)
            po[i] = f(px[i], pz[i]);
    }
    if (scalars)
        return py::float_(po[0]);
    return out;
}

class PyRenderer;

// Renderer::drawnSurface() as Python holds it: it refers to the renderer's
// wave model, so it keeps the renderer alive and refuses queries once the
// renderer's scene or wave model changed.
struct PyDrawnSurface {
    DrawnSurface surface;
    py::object owner; // the PyRenderer
    unsigned generation = 0;
};

class PyRenderer {
public:
    PyRenderer(const PyScene& scene) : context_(sharedContext()), file_(scene.file)
    {
        validateScene(scene.scene, scene.placeForErrors());
        use();
        py::gil_scoped_release release;
        renderer_ = std::make_unique<Renderer>(scene.scene);
    }

    ~PyRenderer()
    {
        // Its GL objects are deleted in its context, which must be current
        // here; on another thread (a collector's) it cannot be, and the
        // renderer is let go rather than crash.
        if (std::this_thread::get_id() == context_->owner) {
            context_->context.makeCurrent();
            renderer_.reset();
        } else {
            (void)renderer_.release();
        }
    }

    PyRenderer(const PyRenderer&) = delete;
    PyRenderer& operator=(const PyRenderer&) = delete;

    PyScene scene() const { return {renderer_->scene(), file_}; }

    void setScene(const PyScene& scene)
    {
        validateScene(scene.scene, scene.placeForErrors());
        use();
        {
            py::gil_scoped_release release;
            renderer_->setScene(scene.scene);
        }
        file_ = scene.file;
        ++generation_;
    }

    void setFlatWater(bool flat)
    {
        use();
        renderer_->setWaveModel(flat ? std::make_shared<FlatModel>() : nullptr);
        ++generation_;
    }

    double renderScale() const { return renderer_->renderScale(); }
    void setRenderScale(double scale)
    {
        if (!(scale >= kMinRenderScale && scale <= kMaxRenderScale))
            throw InputError({"render_scale"}, outsideRangeMessage(std::string(py::repr(py::float_(scale))),
                                                                   kMinRenderScale, kMaxRenderScale));
        use();
        renderer_->setRenderScale(scale);
    }

    py::array_t<std::uint8_t> render(const Camera& camera, double time_s, py::handle size)
    {
        const glm::ivec2 s = imageSize(size);
        checkCamera(camera);
        checkSteps(frameTime(time_s));
        use();
        Image image;
        {
            py::gil_scoped_release release;
            image = renderer_->renderImage(camera, time_s, s);
        }
        viewpoint_m_ = camera.position_m;
        return arrayOwning<std::uint8_t>(std::move(image.rgba), {image.height, image.width, 4});
    }

    PyLabels renderLabels(const Camera& camera, py::handle size)
    {
        const glm::ivec2 s = imageSize(size);
        checkCamera(camera);
        use();
        FrameLabels labels;
        {
            py::gil_scoped_release release;
            labels = renderer_->renderLabels(camera, s);
        }
        return toPython(std::move(labels));
    }

    // The frame through the scene camera's lens and sensor (swell/dataset/sensor.h).
    // camera: None for the scene's own camera at each draw's time (on its
    // path or on a deck: its motion blurs with the shutter).
    py::tuple renderSensor(const std::optional<Camera>& camera, double time_s, py::handle size, bool labels)
    {
        const glm::ivec2 s = imageSize(size);
        if (camera)
            checkCamera(*camera);
        checkSteps(frameTime(time_s));
        // The sensor draws up to half its span after time_s (SensorTiming).
        const SensorTiming timing = sensorTimingOf(renderer_->scene().camera, time_s, 0);
        checkSteps(frameTime(timing.drawTimes_s.back()));
        use();
        SensorFrame frame;
        {
            py::gil_scoped_release release;
            frame = camera ? renderSensorFrame(*renderer_, *camera, time_s, s, labels)
                           : renderSensorFrame(
                                 *renderer_, [this](double t) { return renderer_->sceneCameraAt(t); }, time_s, s,
                                 labels);
        }
        viewpoint_m_ = frame.camera.position_m;
        py::object image = arrayOwning<std::uint8_t>(std::move(frame.image.rgba), {s.y, s.x, 4});
        return py::make_tuple(image, frame.labels ? py::cast(toPython(std::move(*frame.labels))) : py::none());
    }

    Camera sceneCameraAt(double time_s)
    {
        frameTime(time_s);
        // A camera on a floating body stands where the body is stepped to.
        if (renderer_->scene().camera.mountObject >= 0)
            checkSteps(time_s);
        use();
        py::gil_scoped_release release;
        return renderer_->sceneCameraAt(time_s);
    }

    void advanceTo(double time_s, py::handle viewpoint)
    {
        checkSteps(frameTime(time_s));
        const glm::dvec3 v = viewpoint.is_none() ? cameraAt(renderer_->scene().camera, time_s).position_m
                                                 : toVec3(viewpoint, "viewpoint_m");
        if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)))
            throw py::value_error("viewpoint_m must be finite");
        use();
        {
            py::gil_scoped_release release;
            renderer_->advanceTo(time_s, v);
        }
        viewpoint_m_ = v;
    }

    // The forward optical flow from `now` (drawn at time_s) to `next` (drawn
    // interval_s later) with this renderer's sea (swell/dataset/flow.h).
    py::tuple opticalFlow(const PyLabels& now, double time_s, const PyLabels& next, double interval_s)
    {
        frameTime(time_s);
        frameTime(time_s + interval_s);
        if (now.size != next.size)
            throw py::value_error("next_labels: its size differs from labels'");
        use();
        const FrameLabels a = motionLabelsOf(now), b = motionLabelsOf(next);
        FrameFlow flow;
        {
            py::gil_scoped_release release;
            flow = opticalFlowOf(a, time_s, b, interval_s, seaMotionOf(renderer_->scene(), renderer_->waveModel()));
        }
        return py::make_tuple(arrayOwning<float>(std::move(flow.flow_px), {now.size.y, now.size.x, 2}),
                              arrayOwning<std::uint8_t>(std::move(flow.valid), {now.size.y, now.size.x}));
    }

    std::optional<double> simulatedTime() const { return renderer_->simulatedTime_s(); }

    py::array_t<double> objectTransforms()
    {
        use();
        requireSimulation("object_transforms");
        const std::vector<glm::dmat4> transforms = renderer_->objectTransforms();
        py::array_t<double> out({py::ssize_t(transforms.size()), py::ssize_t(4), py::ssize_t(4)});
        for (std::size_t i = 0; i < transforms.size(); ++i)
            copyRows(transforms[i], out.mutable_data() + 16 * i);
        return out;
    }

    py::object surfaceHeight(py::handle x_m, py::handle z_m, double time_s)
    {
        frameTime(time_s);
        use();
        const SurfaceQuery& model = renderer_->waveModel();
        const SeaFrame sea = seaFrameOf(renderer_->scene());
        return mapXZ(x_m, z_m,
                     [&](double x, double z) { return sea.heightInWorld(model.heightAt({x, z}, time_s)); });
    }

    PyDrawnSurface drawnSurface(py::object self, py::handle viewpoint)
    {
        use();
        requireSimulation("drawn_surface");
        const glm::dvec3 v = viewpoint.is_none() ? *viewpoint_m_ : toVec3(viewpoint, "viewpoint_m");
        return {renderer_->drawnSurface(v), std::move(self), generation_};
    }

    // Checks a drawn surface of this renderer may still be queried.
    void checkCurrent(const PyDrawnSurface& surface) const
    {
        use();
        if (surface.generation != generation_)
            throw Error("swell.DrawnSurface: the renderer's scene or wave model changed since it was taken; "
                        "take a new one with drawn_surface()");
    }

    std::string glDescription() const
    {
        use();
        return context_->context.description();
    }

private:
    void use() const
    {
        if (std::this_thread::get_id() != context_->owner)
            throw Error("swell.Renderer: called on a thread other than the one its GL context was made on "
                        "(the first Renderer's); use every Renderer on that thread");
        context_->context.makeCurrent();
    }

    void requireSimulation(const char* what) const
    {
        if (!renderer_->simulatedTime_s() || !viewpoint_m_)
            throw Error(std::string("swell.Renderer.") + what + ": nothing simulated yet; call advance_to() or render() first");
    }

    // Refuses, as `swell render` does, a time whose bodies would be stepped
    // for longer than a still may take (swell/frame_request.h): from where
    // the simulation stands when time_s is later, else from their start.
    void checkSteps(double time_s) const
    {
        if (const std::string problem = historyProblem(renderer_->scene(), time_s, renderer_->simulatedTime_s());
            !problem.empty())
            throw py::value_error("time_s: " + problem);
    }

    static void checkCamera(const Camera& camera)
    {
        if (!(camera.near_m < camera.far_m))
            throw py::value_error("camera: near_m (" + std::string(py::str(py::float_(camera.near_m)))
                                  + ") must be less than far_m (" + std::string(py::str(py::float_(camera.far_m))) + ")");
    }

    std::shared_ptr<SharedContext> context_;
    std::unique_ptr<Renderer> renderer_;
    std::string file_;
    std::optional<glm::dvec3> viewpoint_m_; // of the last advance, for drawn_surface()
    unsigned generation_ = 0;               // bumped when drawn surfaces taken before go stale
};

} // namespace
} // namespace swell::python

SWELL_PYTHON_CONSTRUCTED_ONLY(swell::python::PyRenderer)
SWELL_PYTHON_CONSTRUCTED_ONLY(swell::python::PyDrawnSurface)

namespace swell::python {

void bindRenderer(py::module_& m)
{
    py::class_<PyRenderer>(m, "Renderer",
                           "A headless renderer of one scene (OpenGL 4.5 through EGL, no display needed). "
                           "Raises swell.InputError naming the key or file when the scene does not pass "
                           "Scene.validate(), or an asset or shader is bad. Use it on the thread that made the "
                           "first Renderer (they share its GL context).")
        .def(py::init<const PyScene&>(), py::arg("scene"))
        .def_property_readonly("scene", &PyRenderer::scene, "A copy of the scene it draws.")
        .def("set_scene", &PyRenderer::setScene, py::arg("scene"),
             "Switches to another scene, rebuilding only what the changes need; on an error the old "
             "scene stays.")
        .def("set_flat_water", &PyRenderer::setFlatWater, py::arg("flat"),
             "True: draws flat water (the sea at rest, a mirror) instead of the scene's waves; False: the "
             "scene's waves again.")
        .def_property("render_scale", &PyRenderer::renderScale, &PyRenderer::setRenderScale,
                      "Every pass drawn at this times the output's size, then scaled to it: 0.1..2.")
        .def("render", &PyRenderer::render, py::arg("camera"), py::arg("time_s"), py::arg("size"),
             "Advances to time_s (s) at the camera and draws one frame of size (width, height) pixels, "
             "as `swell render` does. Returns uint8 (H, W, 4) RGBA, rows top first.")
        .def("render_labels", &PyRenderer::renderLabels, py::arg("camera"), py::arg("size"),
             "The labels (swell.Labels) of the frame render() draws for this camera at the simulated time, "
             "aligned pixel for pixel with the colour image of size (width, height). Raises swell.Error "
             "before the first render() or advance_to().")
        .def("render_sensor", &PyRenderer::renderSensor, py::arg("camera"), py::arg("time_s"), py::arg("size"),
             py::arg("labels") = true,
             "As `swell render` draws a frame: through the scene camera's lens distortion, shutter, "
             "exposure and noise (camera.distortion_*, shutter_s, readout_s, exposure_ev, noise_*; "
             "docs/LABELS.md), its labels resampled through the same lens. camera=None: the scene's own "
             "camera at each time the sensor draws (its motion blurs). Returns (uint8 (H, W, 4) RGBA, "
             "swell.Labels or None).")
        .def("optical_flow", &PyRenderer::opticalFlow, py::arg("labels"), py::arg("time_s"), py::arg("next_labels"),
             py::arg("interval_s"),
             "The forward optical flow from labels (drawn at time_s) to next_labels (drawn interval_s later), as "
             "`swell render --labels` writes it (docs/LABELS.md, \"Optical flow\"): (float32 (H, W, 2) pixels "
             "where each pixel's point is seen in the next frame less its centre, uint8 (H, W) 1 where it is seen "
             "there).")
        .def("scene_camera_at", &PyRenderer::sceneCameraAt, py::arg("time_s"),
             "The scene's camera at time_s; a camera mounted on an object (camera.mount_object) placed "
             "on that object's pose there (it heaves, rolls and pitches with a floating body).")
        .def("advance_to", &PyRenderer::advanceTo, py::arg("time_s"), py::arg("viewpoint_m") = py::none(),
             "Moves the simulation (the ocean, the floating bodies, their wake) to time_s (absolute, s; any "
             "order: the same time gives the same state). viewpoint_m (world, m): where the foam's windows "
             "and the drawn surface are centred; None: the scene camera's position at time_s.")
        .def_property_readonly("simulated_time_s", &PyRenderer::simulatedTime,
                               "The time the last advance_to() or render() reached, s; None before.")
        .def("object_transforms", &PyRenderer::objectTransforms,
             "float64 (N, 4, 4): each scene object's transform (object to absolute world, m) at the "
             "simulated time, [row, column]; floating objects sit on the drawn water.")
        .def("surface_height_m", &PyRenderer::surfaceHeight, py::arg("x_m"), py::arg("z_m"), py::arg("time_s"),
             "The height (absolute world y, m) of the wave model's exact surface above world (x, z) at "
             "time_s: every wave, no grid filtering, no wake (drawn_surface() has what is drawn). x_m and "
             "z_m: numbers or arrays (broadcast); returns a float or an array.")
        .def(
            "drawn_surface",
            [](py::object self, py::handle viewpoint) { return self.cast<PyRenderer&>().drawnSurface(self, viewpoint); },
            py::arg("viewpoint_m") = py::none(),
            "The water exactly as drawn at the simulated time (the grid's triangles, the wake included), "
            "for a view whose grid is centred at viewpoint_m (None: the last advance's viewpoint or "
            "camera). Raises swell.Error before the first render() or advance_to().")
        .def_property_readonly("gl_description", &PyRenderer::glDescription,
                               "The GL renderer and version it draws with.");

    py::class_<PyDrawnSurface>(m, "DrawnSurface",
                               "The water as one view draws it at one time: flat triangles over the grid, the "
                               "wake in them. Valid until its renderer's scene or wave model changes.")
        .def(
            "at",
            [](const PyDrawnSurface& s, double x_m, double z_m) -> py::object {
                s.owner.cast<const PyRenderer&>().checkCurrent(s);
                const std::optional<DrawnPoint> p = s.surface.at({x_m, z_m});
                if (!p)
                    return py::none();
                return py::make_tuple(toArray(p->position_m), toArray(p->normal));
            },
            py::arg("x_m"), py::arg("z_m"),
            "(position_m, normal) where the vertical through world (x, z) meets the drawn water: "
            "absolute world, m, and the triangle's unit normal; None where no triangle is.")
        .def(
            "height_m",
            [](const PyDrawnSurface& s, py::handle x_m, py::handle z_m) {
                s.owner.cast<const PyRenderer&>().checkCurrent(s);
                const DrawnSurface& surface = s.surface;
                return mapXZ(x_m, z_m, [&](double x, double z) {
                    const std::optional<DrawnPoint> p = surface.at({x, z});
                    return p ? p->position_m.y : std::nan("");
                });
            },
            py::arg("x_m"), py::arg("z_m"),
            "The drawn water's height (absolute world y, m) above world (x, z): numbers or arrays "
            "(broadcast); NaN where no triangle is.");
}

} // namespace swell::python
