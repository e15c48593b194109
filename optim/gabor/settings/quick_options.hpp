#pragma once
// method.quick, typed: what --quick shrinks (tests and smoke runs: every knob that sets the
// cost), each declared once, here, with its default and its range (gabor_defaults() and
// gabor_bounds() list its block from defaults() and bounds()). Each is a cap: a setting
// already below it stays.
#include <nlohmann/json.hpp>

namespace ppsynth {

struct QuickOptions {
  int res = 0;             // method.grid's resolved res
  int channels = 0;        // the filters of a network that has a count of them (`channels`)
  int max_iterations = 0;  // per sigma stage
  int num_sigmas = 0;

  static nlohmann::json defaults();
  static nlohmann::json bounds();
  // From the method's quick block (defaults merged, bounds checked by the method's registry).
  static QuickOptions resolve(const nlohmann::json& block);
};

}  // namespace ppsynth
