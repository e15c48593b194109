#pragma once
// The pybind11 module ppsynth._ppsynth, in parts. The bindings take and return plain Python
// values -- point sets as dicts of NumPy arrays, configs, metrics and parameters as dicts
// (json_python.hpp) -- and call
// the same library functions as the command; the package's Python files (python/ppsynth)
// build the documented NumPy-first API on them.
//
//   points      read / write / parse / format / validate / generate       bind_points.cpp
//   evaluation  evaluate (the dict of `ppsynth eval --json`)             bind_evaluation.cpp
//   synthesis   resolve a config, synthesize in memory, run / resume a
//               run directory; progress, Ctrl-C, checkpoints              bind_synthesis.cpp
//   terms       loss terms written in Python, registered by name          bind_terms.cpp
//   errors      InputError -> ValueError, MissingFileError -> FileNotFoundError
#include <pybind11/pybind11.h>

#include <string>

#include "core/point_set.hpp"

namespace ppsynth::python {

namespace py = pybind11;

void bind_errors(py::module_& m);
void bind_points(py::module_& m);
void bind_evaluation(py::module_& m);
void bind_synthesis(py::module_& m);
void bind_terms(py::module_& m);

// A point set as the package's Python side holds it:
//   {"positions": (N, 2) float64, "classes": (N,) int64, "attributes": (N, A) float64,
//    "attribute_names": [str], "domain": (x0, y0, x1, y1), "periodic": bool,
//    "class_labels": [int]}
py::dict to_python(const PointSet& ps);
// The inverse; `source` names the point set in errors ("exemplar", a file name). Shapes and
// types are checked here (ValueError naming the array); validate() is the caller's choice.
PointSet from_python(const py::handle& points, const std::string& source);

}  // namespace ppsynth::python
