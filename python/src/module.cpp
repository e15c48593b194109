// ppsynth._ppsynth: the compiled half of the Python package (see bindings.hpp). Importing it
// starts no thread and leaves the allocator alone: configure_runtime() runs at the first
// synthesis, as in the command.
#include "bindings.hpp"

PYBIND11_MODULE(_ppsynth, m) {
  m.doc() = "ppsynth's compiled bindings; use the package `ppsynth`, not this module";
  ppsynth::python::bind_errors(m);
  ppsynth::python::bind_points(m);
  ppsynth::python::bind_evaluation(m);
  ppsynth::python::bind_synthesis(m);
  ppsynth::python::bind_terms(m);
}
