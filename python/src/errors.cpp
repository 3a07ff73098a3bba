// python/src/errors.cpp: tessera.Error (a RuntimeError) and one subclass per status code, each also
// deriving from the natural Python exception (InvalidArgument is a ValueError, ...). Every class has a
// class attribute `code`, the status code's name ("invalid_argument").
#include <array>

#include "bindings.hpp"
#include "common.hpp"

namespace tessera::python {
namespace {
std::array<PyObject*, 10> exception_classes{};  // indexed by status_code; [0] is tessera.Error
}  // namespace

PyObject* exception_for(status_code code) {
  const auto i = static_cast<std::size_t>(code);
  PyObject* e = i < exception_classes.size() ? exception_classes[i] : nullptr;
  return e != nullptr ? e : (exception_classes[0] != nullptr ? exception_classes[0] : PyExc_RuntimeError);
}

void bind_errors(py::module_& m) {
  struct spec {
    status_code code;
    const char* name;
    PyObject* base;
    const char* doc;
  };
  const spec specs[] = {
      {status_code::invalid_argument, "InvalidArgument", PyExc_ValueError, "A parameter is outside its domain."},
      {status_code::out_of_range, "OutOfRange", PyExc_IndexError, "An index or window lies outside the valid range."},
      {status_code::size_overflow, "SizeOverflow", PyExc_OverflowError,
       "Sizes whose product or byte count is too large, or memory that cannot be allocated."},
      {status_code::io_error, "IOError", PyExc_OSError, "A file could not be opened, read or written."},
      {status_code::parse_error, "ParseError", PyExc_ValueError, "A file or byte string is malformed or truncated."},
      {status_code::unsupported, "Unsupported", PyExc_NotImplementedError,
       "A valid request this build or format cannot serve."},
      {status_code::cancelled, "Cancelled", nullptr, "The progress callable returned False."},
      {status_code::not_converged, "NotConverged", nullptr, "An iterative solver did not reach its tolerance."},
      {status_code::internal_error, "InternalError", nullptr, "A failure that is not the caller's fault."},
  };
  py::object error = py::reinterpret_steal<py::object>(PyErr_NewExceptionWithDoc(
      "tessera.Error", "Base class of tessera's errors; `code` names the status code.", PyExc_RuntimeError, nullptr));
  if (!error) throw py::error_already_set();
  error.attr("code") = py::none();
  m.attr("Error") = error;
  exception_classes[0] = error.release().ptr();  // kept alive for the interpreter's lifetime
  PyObject* base = exception_classes[0];
  for (const spec& s : specs) {
    py::object bases = s.base != nullptr ? py::object(py::make_tuple(py::handle(base), py::handle(s.base)))
                                         : py::object(py::make_tuple(py::handle(base)));
    const std::string qualified = std::string("tessera.") + s.name;
    py::object cls =
        py::reinterpret_steal<py::object>(PyErr_NewExceptionWithDoc(qualified.c_str(), s.doc, bases.ptr(), nullptr));
    if (!cls) throw py::error_already_set();
    cls.attr("code") = std::string(to_string(s.code));
    m.attr(s.name) = cls;
    exception_classes[static_cast<std::size_t>(s.code)] = cls.release().ptr();
  }
}

}  // namespace tessera::python
