// ppsynth._ppsynth: the compiled half of the Python package (see bindings.hpp). Importing it
// starts no thread and leaves the allocator alone: configure_runtime() runs at the first
// synthesis, as in the command.
#include "bindings.hpp"
#include "core/log.hpp"

PYBIND11_MODULE(_ppsynth, m) {
  m.doc() = "ppsynth's compiled bindings; use the package `ppsynth`, not this module";
  // The library logs through spdlog's default logger, which writes to stdout: a Python
  // program's stdout is its own. Warnings and errors go to stderr, as the command's do; a
  // run's progress is the caller's to show (the `progress` callback).
  ppsynth::configure_logging(-1);
  ppsynth::python::bind_errors(m);
  ppsynth::python::bind_points(m);
  ppsynth::python::bind_evaluation(m);
  ppsynth::python::bind_synthesis(m);
  ppsynth::python::bind_terms(m);
}
