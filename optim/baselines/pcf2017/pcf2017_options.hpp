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
  // The checks between two keys, which no one key's range can make (r_a < r_b, step <=
  // max_step); errors name `key`.<key>.
  void check(const std::string& key) const;
};

}  // namespace ppsynth::pcf2017
