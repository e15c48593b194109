#pragma once
// Configs, metrics and parameters cross the binding as Python objects (dicts, lists, numbers),
// never as JSON text. pybind11_json converts them; from_python_json first checks what a user
// can get wrong, so that each flaw is a ValueError naming the key path, as a config file's
// flaws name their line:
//   - a value of a type JSON has no place for (a set, a NumPy array, an object);
//   - a float that is NaN or infinite (JSON has no such number; a bound check would pass NaN);
//   - nesting deeper than kMaxJsonDepth, which also catches a dict that contains itself.
// NumPy scalars (np.int64, np.float32, np.bool_) are taken as the Python numbers they hold.
#include <pybind11/pybind11.h>

#include <string>

#include <nlohmann/json.hpp>
#include <pybind11_json/pybind11_json.hpp>

namespace ppsynth::python {

// `what` names the value in errors ("config", "loss 'ring' defaults").
nlohmann::json from_python_json(const pybind11::handle& value, const std::string& what);

}  // namespace ppsynth::python
