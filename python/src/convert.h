// Conversions between libswell's GLM types and Python: vectors in as any
// sequence of numbers (a tuple, a list, a NumPy array), out as tuples (so
// that `camera.position_m[1] = 5` cannot silently change a copy) or NumPy
// arrays; matrices out as 4x4 NumPy arrays indexed [row, column]; pixel
// buffers out as NumPy arrays that own the library's vector (no copy).
#pragma once

#include "constructed.h"

#include "swell/camera.h"
#include "swell/dataset/labels.h"
#include "swell/frame_request.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace swell::python {

namespace py = pybind11;

// A Python number as a double; TypeError naming `name` for one that will
// not be one (an int past 1.8e308, an object whose __float__ raises, a
// complex or empty array).
inline double numberOf(py::handle value, const std::string& name)
{
    try {
        return value.cast<double>();
    } catch (const py::cast_error&) {
        throw py::type_error(name + ": expected a number that is a double (at most 1.8e308 in size), got "
                             + std::string(py::str(py::type::of(value).attr("__name__"))));
    }
}

// The numbers of a sequence of exactly `n`; TypeError naming `name` otherwise.
inline std::vector<double> numbersOf(py::handle value, std::size_t n, const std::string& name)
{
    if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value))
        throw py::type_error(name + ": expected a sequence of " + std::to_string(n) + " numbers");
    const py::sequence items = py::reinterpret_borrow<py::sequence>(value);
    if (items.size() != n)
        throw py::type_error(name + ": expected " + std::to_string(n) + " numbers, got " + std::to_string(items.size()));
    std::vector<double> out;
    for (std::size_t i = 0; i < n; ++i) {
        // An owned reference, never a borrowed handle: a sequence may make
        // the item when asked (a NumPy array makes a new scalar or view for
        // each element), and then this reference is its only owner.
        const py::object item = items[i];
        if (py::isinstance<py::bool_>(item) || !(py::isinstance<py::float_>(item) || py::isinstance<py::int_>(item)
                                                  || py::hasattr(item, "__float__")))
            throw py::type_error(name + ": expected numbers, got " + std::string(py::str(py::type::of(item).attr("__name__"))));
        out.push_back(numberOf(item, name));
    }
    return out;
}

inline glm::dvec3 toVec3(py::handle value, const std::string& name)
{
    const std::vector<double> v = numbersOf(value, 3, name);
    return {v[0], v[1], v[2]};
}

inline glm::dvec2 toVec2(py::handle value, const std::string& name)
{
    const std::vector<double> v = numbersOf(value, 2, name);
    return {v[0], v[1]};
}

// An image size (width, height), pixels: whole numbers 1..kMaxFrameSide a
// side, as `swell render --size` takes them, with its message; ValueError
// otherwise.
inline glm::ivec2 imageSize(py::handle size)
{
    const glm::dvec2 s = toVec2(size, "size");
    const bool whole = s.x == std::floor(s.x) && s.y == std::floor(s.y);
    const double most = kMaxFrameSide;
    if (!(whole && s.x >= 1.0 && s.x <= most && s.y >= 1.0 && s.y <= most))
        throw py::value_error("size: " + frameSizeMessage(std::string(py::repr(size))));
    return {int(s.x), int(s.y)};
}

// A frame's time, s: 0..kMaxFrameTime_s, as `swell render --time` takes it,
// with its message; ValueError otherwise.
inline double frameTime(double time_s)
{
    if (!(time_s >= 0.0 && time_s <= kMaxFrameTime_s))
        throw py::value_error("time_s: "
                              + outsideRangeMessage(std::string(py::repr(py::float_(time_s))), 0.0, kMaxFrameTime_s));
    return time_s;
}

inline py::tuple toTuple(glm::dvec3 v) { return py::make_tuple(v.x, v.y, v.z); }
inline py::tuple toTuple(glm::dvec2 v) { return py::make_tuple(v.x, v.y); }

inline py::array_t<double> toArray(glm::dvec3 v)
{
    py::array_t<double> a(3);
    auto m = a.mutable_unchecked<1>();
    for (int i = 0; i < 3; ++i)
        m(i) = v[i];
    return a;
}

// GLM is column-major (m[column][row]); NumPy's arrays read a[row, column],
// as the matrix is written on paper: 16 doubles, row after row.
inline void copyRows(const glm::dmat4& matrix, double* rows)
{
    for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column)
            rows[4 * row + column] = matrix[column][row];
}

inline py::array_t<double> toArray(const glm::dmat4& matrix)
{
    py::array_t<double> a({4, 4});
    copyRows(matrix, a.mutable_data());
    return a;
}

// A NumPy array of `shape` over the elements of `data`, which it takes over:
// the vector is moved into a capsule that the array keeps alive, so a frame's
// pixels are never copied. Element is what the array holds (float for a
// vector of glm::vec3, whose three floats are packed).
template <class Element, class T>
py::array_t<Element> arrayOwning(std::vector<T>&& data, const std::vector<py::ssize_t>& shape)
{
    static_assert(sizeof(T) % sizeof(Element) == 0);
    auto owned = std::make_unique<std::vector<T>>(std::move(data));
    const Element* first = reinterpret_cast<const Element*>(owned->data());
    py::capsule owner(owned.get(), [](void* p) { delete static_cast<std::vector<T>*>(p); });
    owned.release();
    return py::array_t<Element>(shape, first, owner);
}

} // namespace swell::python

SWELL_PYTHON_CONSTRUCTED_ONLY(swell::Camera)
SWELL_PYTHON_CONSTRUCTED_ONLY(swell::CameraCalibration)
SWELL_PYTHON_CONSTRUCTED_ONLY(swell::HorizonLine)
SWELL_PYTHON_CONSTRUCTED_ONLY(swell::ObjectLabel)
