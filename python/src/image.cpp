// PNG files in and out of NumPy through the library's own reader and writer
// (swell/image.h), so a frame saved from Python is the file `swell render`
// writes for the same pixels.
#include "bindings.h"
#include "convert.h"

#include "swell/image.h"

#include <pybind11/stl/filesystem.h>

#include <cstring>

namespace swell::python {

void bindImages(py::module_& m)
{
    m.def(
        "read_image",
        [](const std::filesystem::path& path) {
            Image image = readImage(path);
            return arrayOwning<std::uint8_t>(std::move(image.rgba), {image.height, image.width, 4});
        },
        py::arg("path"),
        "Reads a PNG (or another format the library decodes) as uint8 (H, W, 4) RGBA, rows top first. "
        "Raises swell.InputError naming the file when it cannot.");
    m.def(
        "write_png",
        [](py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast> rgba, const std::filesystem::path& path) {
            if (rgba.ndim() != 3 || rgba.shape(2) != 4 || rgba.shape(0) < 1 || rgba.shape(1) < 1)
                throw py::value_error("write_png: expected uint8 (H, W, 4) RGBA, got shape "
                                      + std::string(py::str(py::tuple(py::cast(std::vector<py::ssize_t>(
                                          rgba.shape(), rgba.shape() + rgba.ndim()))))));
            Image image;
            image.width = int(rgba.shape(1));
            image.height = int(rgba.shape(0));
            image.rgba.resize(std::size_t(rgba.size()));
            std::memcpy(image.rgba.data(), rgba.data(), image.rgba.size());
            py::gil_scoped_release release;
            writePng(image, path);
        },
        py::arg("rgba"), py::arg("path"),
        "Writes uint8 (H, W, 4) RGBA, rows top first, as a PNG, as `swell render` writes its frames. "
        "Raises swell.Error when the file cannot be written.");
}

} // namespace swell::python
