// PNG files in and out of NumPy through the library's own reader and writer
// (swell/image.h), so a frame saved from Python is the file `swell render`
// writes for the same pixels.
#include "bindings.h"
#include "convert.h"

#include "swell/image.h"

#include <pybind11/stl/filesystem.h>

#include <cstring>

namespace swell::python {

namespace {

// "(2, 3)": an array's shape as Python writes it.
std::string shapeText(const py::array& a)
{
    py::tuple shape(a.ndim());
    for (py::ssize_t i = 0; i < a.ndim(); ++i)
        shape[std::size_t(i)] = py::int_(a.shape(i));
    return py::str(shape);
}

// The pixels of `rgba`: a NumPy array of uint8 (H, W, 4), each side 1..16384
// as `swell render --size` takes them. Nothing is converted: a float image
// cast to uint8 would be written black (0.5 becomes 0), so another dtype is
// refused with the conversion to make.
Image rgbaImage(py::handle rgba)
{
    if (!py::isinstance<py::array>(rgba))
        throw py::type_error("write_png: rgba must be a NumPy array of uint8 (H, W, 4), got "
                             + std::string(py::str(py::type::handle_of(rgba).attr("__name__"))));
    const py::array array = py::reinterpret_borrow<py::array>(rgba);
    const std::string dtype = py::str(array.dtype());
    if (!array.dtype().is(py::dtype::of<std::uint8_t>()))
        throw py::type_error("write_png: rgba must be uint8 (H, W, 4), got " + dtype + " " + shapeText(array)
                             + "; a float image in 0..1 is (rgba * 255).round().astype(numpy.uint8)");
    if (array.ndim() != 3 || array.shape(2) != 4 || array.shape(0) < 1 || array.shape(1) < 1
        || array.shape(0) > kMaxFrameSide || array.shape(1) > kMaxFrameSide)
        throw py::type_error("write_png: rgba must be uint8 (H, W, 4), each side 1.." + std::to_string(kMaxFrameSide)
                             + ", got shape " + shapeText(array));
    const auto pixels = py::array_t<std::uint8_t, py::array::c_style>::ensure(array);
    Image image;
    image.width = int(pixels.shape(1));
    image.height = int(pixels.shape(0));
    image.rgba.resize(std::size_t(pixels.size()));
    std::memcpy(image.rgba.data(), pixels.data(), image.rgba.size());
    return image;
}

} // namespace

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
        [](py::handle rgba, const std::filesystem::path& path) {
            Image image = rgbaImage(rgba);
            py::gil_scoped_release release;
            writePng(image, path);
        },
        py::arg("rgba"), py::arg("path"),
        "Writes uint8 (H, W, 4) RGBA, rows top first, as a PNG, as `swell render` writes its frames. "
        "Raises TypeError naming rgba for anything else (another dtype, another shape), and swell.Error "
        "when the file cannot be written.");
}

} // namespace swell::python
