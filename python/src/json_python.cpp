#include "json_python.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

#include "core/config/json_text.hpp"
#include "core/error.hpp"

namespace ppsynth::python {

namespace py = pybind11;

namespace {

bool is_numpy_scalar(const py::handle& v) {
  const py::object numpy = py::module_::import("sys").attr("modules").attr("get")("numpy");
  return !numpy.is_none() && py::isinstance(v, numpy.attr("generic"));
}

// The value with NumPy scalars replaced by Python numbers, checked on the way down.
py::object checked(const py::handle& v, const std::string& path, int depth) {
  if (depth > kMaxJsonDepth)
    throw InputError(path + ": nested deeper than " + std::to_string(kMaxJsonDepth) +
                     " levels (or a container that holds itself)");
  if (v.is_none() || py::isinstance<py::bool_>(v) || py::isinstance<py::str>(v))
    return py::reinterpret_borrow<py::object>(v);
  if (py::isinstance<py::int_>(v)) {
    const py::int_ lo(std::numeric_limits<int64_t>::min()), hi(std::numeric_limits<uint64_t>::max());
    if (v < lo || v > hi)
      throw InputError(path + ": " + py::repr(v).cast<std::string>() + " is beyond the range of a 64-bit integer");
    return py::reinterpret_borrow<py::object>(v);
  }
  if (py::isinstance<py::float_>(v)) {
    if (!std::isfinite(v.cast<double>()))
      throw InputError(path + ": " + py::repr(v).cast<std::string>() + " is not a finite number");
    return py::reinterpret_borrow<py::object>(v);
  }
  if (py::isinstance<py::dict>(v)) {
    py::dict out;
    for (auto item : py::reinterpret_borrow<py::dict>(v)) {
      if (!py::isinstance<py::str>(item.first))
        throw InputError(path + ": the key " + py::repr(item.first).cast<std::string>() + " is not a string");
      out[item.first] = checked(item.second, path + "." + item.first.cast<std::string>(), depth + 1);
    }
    return std::move(out);
  }
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    py::list out;
    size_t i = 0;
    for (auto item : v) out.append(checked(item, path + "[" + std::to_string(i++) + "]", depth + 1));
    return std::move(out);
  }
  if (is_numpy_scalar(v) && py::hasattr(v, "item")) {
    py::object plain = v.attr("item")();
    if (py::isinstance<py::bool_>(plain) || py::isinstance<py::int_>(plain) || py::isinstance<py::float_>(plain))
      return checked(plain, path, depth);
  }
  throw InputError(path + ": a " + py::str(py::type::of(v).attr("__name__")).cast<std::string>() +
                   " has no JSON form (expected a dict, list, str, number, bool or None)");
}

}  // namespace

nlohmann::json from_python_json(const py::handle& value, const std::string& what) {
  return pyjson::to_json(checked(value, what, 0));
}

}  // namespace ppsynth::python
