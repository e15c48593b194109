// Errors cross into Python with the command's messages (file and line, or key path):
//   MissingFileError -> FileNotFoundError   (a named input file is not there)
//   InputError       -> ValueError          (everything else the input caused)
// std::bad_alloc and the rest keep pybind11's mapping (MemoryError, RuntimeError).
#include "bindings.hpp"

#include "core/error.hpp"

namespace ppsynth::python {

void bind_errors(py::module_& m) {
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const MissingFileError& e) {
      PyErr_SetString(PyExc_FileNotFoundError, e.what());
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
}

}  // namespace ppsynth::python
