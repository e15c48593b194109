// Point sets between NumPy and the library: conversion, the four formats of the command
// (core/formats/point_io.hpp), validation, generators, the defaults catalog.
// .npy / .npz are NumPy's own and handled by the package's Python side (ppsynth/points.py).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>

#include "bindings.hpp"
#include "json_python.hpp"
#include "core/config/defaults_catalog.hpp"
#include "core/error.hpp"
#include "core/formats/point_io.hpp"
#include "core/formats/text_table.hpp"
#include "core/generators/generator.hpp"
#include "core/paths.hpp"

namespace ppsynth::python {

namespace {

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Ints = py::array_t<int64_t, py::array::c_style | py::array::forcecast>;

ReadOptions read_options(const std::string& format, const std::string& scaling,
                         const std::vector<std::string>& attribute_names) {
  ReadOptions o;
  o.format = parse_format(format);
  o.scaling = parse_axis_scaling(scaling);
  o.attribute_names = attribute_names;
  return o;
}

Domain domain_of(const py::handle& d, bool periodic, const std::string& source) {
  const auto v = py::cast<std::vector<double>>(d);
  if (v.size() != 4) throw InputError(source + ": domain: expected (x0, y0, x1, y1)");
  Domain dom{v[0], v[1], v[2], v[3], periodic};
  if (!(dom.width() > 0) || !(dom.height() > 0) || !std::isfinite(dom.area()))
    throw InputError(source + ": domain: need finite x0 < x1 and y0 < y1");
  return dom;
}

}  // namespace

py::dict to_python(const PointSet& ps) {
  const auto n = static_cast<py::ssize_t>(ps.size());
  const auto a = static_cast<py::ssize_t>(ps.num_attributes());
  Doubles pos({n, py::ssize_t(2)});
  Ints cls({n});
  Doubles attrs({n, a});
  auto P = pos.mutable_unchecked<2>();
  auto C = cls.mutable_unchecked<1>();
  auto A = attrs.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i) {
    P(i, 0) = ps[i].x;
    P(i, 1) = ps[i].y;
    C(i) = ps.cls(i);
    for (py::ssize_t j = 0; j < a; ++j) A(i, j) = ps.attr(i, j);
  }
  const Domain& d = ps.domain();
  py::dict r;
  r["positions"] = pos;
  r["classes"] = cls;
  r["attributes"] = attrs;
  r["attribute_names"] = ps.attribute_names();
  r["domain"] = py::make_tuple(d.x0, d.y0, d.x1, d.y1);
  r["periodic"] = d.periodic;
  r["class_labels"] = ps.class_labels();
  return r;
}

PointSet from_python(const py::handle& points, const std::string& source) {
  const py::dict p = py::reinterpret_borrow<py::dict>(points);
  auto need = [&](const char* key) -> py::object {
    if (!p.contains(key)) throw InputError(source + ": no '" + key + "'");
    return p[key];
  };
  const Doubles pos = Doubles::ensure(need("positions"));
  if (!pos || pos.ndim() != 2 || pos.shape(1) != 2)
    throw InputError(source + ": positions: expected an (N, 2) array of numbers");
  const py::ssize_t n = pos.shape(0);
  const Ints cls = Ints::ensure(need("classes"));
  if (!cls || cls.ndim() != 1 || cls.shape(0) != n)
    throw InputError(source + ": classes: expected an (N,) integer array, N = " + std::to_string(n));
  const Doubles attrs = Doubles::ensure(need("attributes"));
  const auto names = py::cast<std::vector<std::string>>(need("attribute_names"));
  if (!attrs || attrs.ndim() != 2 || attrs.shape(0) != n || attrs.shape(1) != static_cast<py::ssize_t>(names.size()))
    throw InputError(source + ": attributes: expected an (N, A) array, N = " + std::to_string(n) +
                     ", A = " + std::to_string(names.size()) + " (one column per attribute name)");
  PointSet ps(domain_of(need("domain"), py::cast<bool>(need("periodic")), source));
  for (const auto& name : names) {
    if (name.empty() || name == "x" || name == "y" || name == "class")
      throw InputError(source + ": attribute_names: '" + name + "' is not a valid attribute name");
    if (ps.attribute_index(name)) throw InputError(source + ": attribute_names: '" + name + "' twice");
    ps.add_attribute(name);
  }
  ps.reserve(static_cast<size_t>(n));
  auto P = pos.unchecked<2>();
  auto C = cls.unchecked<1>();
  auto A = attrs.unchecked<2>();
  std::vector<double> row(names.size());
  for (py::ssize_t i = 0; i < n; ++i) {
    if (C(i) < 0 || C(i) > 1000000)
      throw InputError(source + ": classes[" + std::to_string(i) + "] = " + std::to_string(C(i)) +
                       ": class ids are dense, 0..K-1");
    for (size_t j = 0; j < row.size(); ++j) row[j] = A(i, j);
    ps.add({P(i, 0), P(i, 1)}, static_cast<int>(C(i)), row);
  }
  // Each label as a Python integer of any size, so that one past 64 bits (1e20) is refused
  // like one past 32, with its value and the range.
  std::vector<int> l;
  for (const py::handle h : need("class_labels")) {
    const py::int_ v(py::reinterpret_borrow<py::object>(h));
    int overflow = 0;
    const long long x = PyLong_AsLongLongAndOverflow(v.ptr(), &overflow);
    if (overflow != 0 || x < INT32_MIN || x > INT32_MAX)
      throw InputError(source + ": class_labels: " + py::repr(v).cast<std::string>() +
                       " is out of range (a class label is a 32-bit integer, " + std::to_string(INT32_MIN) + ".." +
                       std::to_string(INT32_MAX) + ")");
    l.push_back(static_cast<int>(x));
  }
  if (!l.empty()) {
    if (ps.num_classes() > static_cast<int>(l.size()))
      throw InputError(source + ": class_labels: " + std::to_string(l.size()) + " labels for " +
                       std::to_string(ps.num_classes()) + " classes");
    ps.set_class_labels(l);
  }
  return ps;
}

void bind_points(py::module_& m) {
  m.def(
      "read_points",
      [](const std::string& path, const std::string& format, const std::string& scaling,
         const std::vector<std::string>& attribute_names) {
        return to_python(read_points(path, read_options(format, scaling, attribute_names)));
      },
      py::arg("path"), py::arg("format") = "auto", py::arg("scaling") = "per-axis",
      py::arg("attribute_names") = std::vector<std::string>{});
  m.def(
      "write_points",
      [](const py::dict& points, const std::string& path, const std::string& format) {
        write_points(path, from_python(points, path), parse_format(format));
      },
      py::arg("points"), py::arg("path"), py::arg("format") = "auto");
  m.def(
      "format_points",
      [](const py::dict& points, const std::string& format) {
        return format_points(from_python(points, "points"), parse_format(format));
      },
      py::arg("points"), py::arg("format") = "plain");
  m.def(
      "parse_points",
      [](const std::string& text, const std::string& source, const std::string& format, const std::string& scaling) {
        return to_python(parse_points(text, source, read_options(format, scaling, {})));
      },
      py::arg("text"), py::arg("source") = "<text>", py::arg("format") = "auto", py::arg("scaling") = "per-axis");
  m.def(
      "validate",
      [](const py::dict& points, const std::string& source) { validate(from_python(points, source), source); },
      py::arg("points"), py::arg("source"));
  m.def("resolve_data_path", &resolve_data_path, py::arg("path"));
  // What read_points checks before it opens a file, for the NumPy readers of ppsynth/points.py.
  m.def("check_input_file", [](const std::string& path) { check_input_file(path); }, py::arg("path"));
  m.def(
      "generate",
      [](const py::object& spec, long long n, uint64_t seed, const py::tuple& domain, bool periodic) {
        if (n < 0) throw InputError("n must be >= 0");
        return to_python(
            generate_points(from_python_json(spec, "generator"), static_cast<size_t>(n), seed,
                            domain_of(domain, periodic, "generate"), "generator"));
      },
      py::arg("spec"), py::arg("n"), py::arg("seed"), py::arg("domain"), py::arg("periodic"));
  m.def("defaults", [] { return defaults_catalog(); });
}

}  // namespace ppsynth::python
