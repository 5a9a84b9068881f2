// swell._swell: libswell for Python (docs/PYTHON.md). The package swell
// (python/swell/__init__.py) re-exports it with the presets on top.
#include "bindings.h"

PYBIND11_MODULE(_swell, m)
{
    m.doc() = "Swell's ocean renderer: scenes, cameras, headless rendering of colour and labels to NumPy arrays, "
              "surface queries and floating bodies (docs/PYTHON.md).";
    // Errors first: the others' docstrings and signatures name them.
    swell::python::bindErrors(m);
    swell::python::bindScene(m);
    swell::python::bindCamera(m);
    swell::python::bindLabels(m);
    swell::python::bindRenderer(m);
    swell::python::bindImages(m);
}
