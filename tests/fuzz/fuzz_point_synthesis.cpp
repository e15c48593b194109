// libFuzzer target: the Point-Synthesis format of Tu et al. 2019
// (core/formats/point_synthesis_format.hpp) under both axis scalings, and the write/read
// round trip of what it accepts. Contract: fuzz_common.hpp.
#include "core/formats/point_synthesis_format.hpp"
#include "tests/fuzz/fuzz_common.hpp"

using namespace ppsynth;

PPSYNTH_FUZZ_TEXT_TARGET {
  for (AxisScaling scaling : {AxisScaling::PerAxisMinMax, AxisScaling::Uniform}) {
    ReadOptions opts;
    opts.format = Format::PointSynthesis;
    opts.scaling = scaling;
    PointSet ps;
    if (fuzz::accepts([&] { ps = parse_point_synthesis(text, "fuzz.txt", opts); }))
      fuzz::check_parsed(ps, Format::PointSynthesis, "fuzz.txt");
  }
  return 0;
}
