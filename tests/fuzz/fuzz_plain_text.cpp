// libFuzzer target: this project's plain text format (core/formats/plain_text_format.hpp)
// and the write/read round trip of what it accepts. Contract: fuzz_common.hpp.
#include "core/formats/plain_text_format.hpp"
#include "tests/fuzz/fuzz_common.hpp"

using namespace ppsynth;

PPSYNTH_FUZZ_TEXT_TARGET {
  PointSet ps;
  if (fuzz::accepts([&] { ps = parse_plain_text(text, "fuzz.txt"); }))
    fuzz::check_parsed(ps, Format::Plain, "fuzz.txt");
  return 0;
}
