// libFuzzer target: this project's JSON point format (core/formats/json_format.hpp) and the
// write/read round trip of what it accepts. Contract: fuzz_common.hpp.
#include "core/formats/json_format.hpp"
#include "tests/fuzz/fuzz_common.hpp"

using namespace ppsynth;

PPSYNTH_FUZZ_TEXT_TARGET {
  PointSet ps;
  if (fuzz::accepts([&] { ps = parse_json_points(text, "fuzz.json"); }))
    fuzz::check_parsed(ps, Format::Json, "fuzz.json");
  return 0;
}
