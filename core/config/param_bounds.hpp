#pragma once
// The allowed range of every numeric parameter, declared beside its default (core/registry.hpp:
// each registered part gives its defaults and their bounds together). A bound is a string in
// interval notation, with "int" in front for whole numbers:
//     "[0, 1]"   "(0, inf)"   "int [1, inf)"   "int [0, 4096]"
// or alternatives joined by " or ", each an interval or one number: "0 or int [8, 8192]"
// (0 asks for the automatic choice).
// Bounds mirror the defaults' nesting: {"convergence": {"window": "int [1, inf)"}}.
// A parameter whose default is a number must have a bound (a test walks every registry).
#include <string>

#include <nlohmann/json.hpp>

namespace ppsynth {

// Throws config_error naming `key_path` + the key when a value in `params` lies outside its
// bound, is not a whole number where the bound says "int", or is not a number at all. Keys
// of `bounds` missing from `params`, and null or "auto" values (an optional parameter's none,
// core/config/params.hpp), are skipped; a malformed bound is a std::logic_error (a
// programming error, caught by the registry test).
void check_bounds(const nlohmann::json& params, const nlohmann::json& bounds, const std::string& key_path);

// The numeric leaves of `defaults` that `bounds` does not cover ("a.b", ...): the registry
// test asserts this is empty for every registered part.
std::vector<std::string> unbounded_numbers(const nlohmann::json& defaults, const nlohmann::json& bounds,
                                           const std::string& key_path = "");

}  // namespace ppsynth
