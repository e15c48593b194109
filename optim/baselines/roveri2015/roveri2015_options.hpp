#pragma once
// The "roveri2015" method's parameters, typed, each key declared once in its table
// (roveri2015_options.cpp): RoveriParams' (params.hpp), whose members are the defaults, and
// --quick's scales.
#include "core/config/params.hpp"
#include "optim/baselines/roveri2015/params.hpp"

namespace ppsynth::roveri2015 {

struct Roveri2015Options {
  RoveriParams roveri;
  int quick_scales = 2;  // --quick: the window sizes (scales) at most

  static const ParamTable<Roveri2015Options>& params();
};

}  // namespace ppsynth::roveri2015
