// The Python module swell._swell, bound by concern: each bind*() adds one
// part of libswell's public API to the module (errors.cpp, scene.cpp,
// camera.cpp, labels.cpp, renderer.cpp, image.cpp); module.cpp calls them
// in order.
#pragma once

#include <pybind11/pybind11.h>

namespace swell::python {

void bindErrors(pybind11::module_& m);
void bindScene(pybind11::module_& m);
void bindCamera(pybind11::module_& m);
void bindLabels(pybind11::module_& m);
void bindRenderer(pybind11::module_& m);
void bindImages(pybind11::module_& m);

} // namespace swell::python
