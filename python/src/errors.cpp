// libswell's errors as Python exceptions with the same message:
// swell::Error is swell.Error (a RuntimeError), swell::InputError is
// swell.InputError (a swell.Error), carrying the place as attributes; any
// other exception from the library is swell.Error too (only the bindings'
// own argument errors and MemoryError are Python's).
#include "bindings.h"

#include "swell/error.h"

#include <exception>
#include <new>

namespace swell::python {

namespace py = pybind11;

namespace {

// The exception types. Never destroyed: they must outlive every exception
// raised, and a static destructor would run after the interpreter is gone.
py::exception<Error>* error = nullptr;
py::exception<InputError>* inputError = nullptr;

} // namespace

void bindErrors(py::module_& m)
{
    error = new py::exception<Error>(m, "Error", PyExc_RuntimeError);
    inputError = new py::exception<InputError>(m, "InputError", error->ptr());
    error->doc() = "An error from Swell's library (no GL context, a failed GL call, a call out of order).";
    inputError->doc() = "Bad input (a scene file, a value, an asset, a shader source), with its place: "
                        "str() reads 'path:line:column: message'; the attributes path, line, column "
                        "(0 when unknown) and message hold the parts.";

    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p)
                std::rethrow_exception(p);
        } catch (const InputError& e) {
            py::object exception = py::handle(inputError->ptr())(e.what());
            exception.attr("path") = e.place().path;
            exception.attr("line") = e.place().line;
            exception.attr("column") = e.place().column;
            exception.attr("message") = e.message();
            PyErr_SetObject(inputError->ptr(), exception.ptr());
        } catch (const Error& e) {
            PyErr_SetString(error->ptr(), e.what());
        } catch (const py::builtin_exception&) {
            throw; // the bindings' own TypeError, ValueError, KeyError...: as pybind11 raises them
        } catch (const py::error_already_set&) {
            throw;
        } catch (const std::bad_alloc&) {
            throw; // MemoryError
        } catch (const std::exception& e) {
            // Whatever else the library lets through (a standard library
            // error, a filesystem error) is still the library's error.
            PyErr_SetString(error->ptr(), e.what());
        }
    });
}

} // namespace swell::python
