#pragma once
// The "pcf2017" method's parameters, typed, each key declared once in its table
// (pcf2017_options.cpp): the PCF estimator's (pcf_params.hpp) and the descent's
// (pcf_synthesizer.hpp), whose structs' members are the defaults, and --quick's iterations.
#include "core/config/params.hpp"
#include "optim/baselines/pcf2017/pcf_params.hpp"
#include "optim/baselines/pcf2017/pcf_synthesizer.hpp"

namespace ppsynth::pcf2017 {

struct Pcf2017Options {
  PcfParams pcf;
  DescentOptions descent;
  int quick_iterations = 30;  // --quick caps the descent's iterations at this

  static const ParamTable<Pcf2017Options>& params();
  // From the method's params (defaults merged); errors name `key`.<key>, and the checks
  // between two keys (r_a < r_b, step <= max_step) are made here.
  static Pcf2017Options read(const nlohmann::json& p, const std::string& key);
};

}  // namespace ppsynth::pcf2017
