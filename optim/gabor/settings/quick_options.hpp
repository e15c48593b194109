#pragma once
// method.quick, typed: what --quick shrinks (tests and smoke runs: every knob that sets the
// cost), each key declared once in its table (quick_options.cpp). Each is a cap: a setting
// already below it stays.
#include "core/config/params.hpp"

namespace ppsynth {

struct QuickOptions {
  int res = 24;            // method.grid's resolved res
  int channels = 8;        // the filters of a network that has a count of them (`channels`)
  int max_iterations = 4;  // per sigma stage
  int num_sigmas = 2;

  static const ParamTable<QuickOptions>& params();
};

}  // namespace ppsynth
