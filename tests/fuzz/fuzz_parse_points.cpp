// libFuzzer target: the auto-detecting entry point parse_points (core/formats/point_io.hpp):
// detection, then whichever reader it picks, then the write/read round trip in the
// detected format. Contract: fuzz_common.hpp.
#include "tests/fuzz/fuzz_common.hpp"

using namespace ppsynth;

PPSYNTH_FUZZ_TEXT_TARGET {
  const std::string source = "fuzz.txt";
  Format format = Format::Auto;
  if (!fuzz::accepts([&] { format = detect_format_of_text(text, source); })) return 0;
  PointSet ps;
  if (fuzz::accepts([&] { ps = parse_points(text, source); })) fuzz::check_parsed(ps, format, source);
  return 0;
}
