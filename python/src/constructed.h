// Objects Python made without constructing them are refused, never used.
//
// `swell.Renderer.__new__(swell.Renderer)` makes an instance whose __init__
// never ran; pybind11 then hands its methods raw memory in place of the C++
// object (it allocates the storage lazily on first use, uninitialised), and
// reading it crashed the interpreter. Each bound class's caster here first
// asks whether the instance holds a C++ object at all (its value pointer is
// set by every constructor, by a C++ value returned to Python, and by a
// reference into another object such as Labels.camera), and raises
// TypeError naming the class if not, before any method sees it.
//
// SWELL_PYTHON_CONSTRUCTED_ONLY(Type) must be visible wherever Type is cast
// (every file that binds or takes it), before its first use: the headers
// that declare the Python-side types use it, and convert.h for the
// library's own types.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace swell::python {

// The caster of a bound class, refusing instances whose __init__ never ran.
template <class T>
class ConstructedCaster : public pybind11::detail::type_caster_base<T> {
    using Base = pybind11::detail::type_caster_base<T>;

public:
    bool load(pybind11::handle src, bool convert)
    {
        refuseUnconstructed(src);
        return Base::load(src, convert);
    }

private:
    static void refuseUnconstructed(pybind11::handle src)
    {
        namespace detail = pybind11::detail;
        if (!src || src.is_none())
            return;
        detail::type_info* info = detail::get_type_info(typeid(T));
        if (!info || !PyObject_TypeCheck(src.ptr(), info->type))
            return; // not ours: the base caster refuses it as usual
        auto* instance = reinterpret_cast<detail::instance*>(src.ptr());
        const detail::value_and_holder held = instance->get_value_and_holder(info, false);
        if (held && held.value_ptr() != nullptr)
            return;
        const std::string name = pybind11::str(pybind11::type::handle_of(src).attr("__name__"));
        throw pybind11::type_error("swell." + name + ": this object was made by " + name
                                   + ".__new__() without its __init__(), so it holds nothing; use one made by its "
                                     "constructor or returned by swell");
    }
};

} // namespace swell::python

#define SWELL_PYTHON_CONSTRUCTED_ONLY(Type)                                                                          \
    namespace pybind11::detail {                                                                                     \
    template <>                                                                                                      \
    class type_caster<Type> : public swell::python::ConstructedCaster<Type> {};                                      \
    }
