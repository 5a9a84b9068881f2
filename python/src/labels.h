// A frame's labels as Python sees them: the per-pixel buffers as NumPy
// arrays (which took the library's vectors over), the rest as the library
// gives it.
#pragma once

#include "constructed.h"

#include "swell/dataset/labels.h"

#include <pybind11/numpy.h>

#include <string>
#include <vector>

namespace swell::python {

struct PyLabels {
    glm::ivec2 size{0};
    pybind11::array_t<float> range_m;         // (H, W)
    pybind11::array_t<float> depth_m;         // (H, W): z-depth
    pybind11::array_t<float> normal;          // (H, W, 3)
    pybind11::array_t<std::uint16_t> semantic; // (H, W)
    pybind11::array_t<std::uint16_t> instance; // (H, W)
    pybind11::array_t<std::uint8_t> amodal;    // (N, H, W): each object's amodal mask
    std::vector<std::string> classes;
    std::vector<ObjectLabel> objects;
    CameraCalibration camera;
    HorizonLine horizon;
    double trueHorizonDip_deg = 0.0;
    std::vector<glm::dvec2> trueHorizon_px;
    std::vector<ShoreLine> shoreline;
};

// Takes the frame's buffers over. Needs the GIL.
PyLabels toPython(FrameLabels&& labels);
// What the optical flow reads of a frame's labels (swell/dataset/flow.h):
// its size, range, class, instance, calibration and objects, copied. Needs the GIL.
FrameLabels motionLabelsOf(const PyLabels& labels);

} // namespace swell::python

SWELL_PYTHON_CONSTRUCTED_ONLY(swell::python::PyLabels)
