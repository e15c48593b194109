// libFuzzer target: the published Gabor integer format (core/formats/gabor_int_format.hpp),
// its detector, and the write/read round trip of what it accepts. Contract: fuzz_common.hpp.
#include "core/formats/gabor_int_format.hpp"
#include "tests/fuzz/fuzz_common.hpp"

using namespace ppsynth;

PPSYNTH_FUZZ_TEXT_TARGET {
  (void)looks_like_gabor_int(text);
  // Two names: the stem decides a single attribute column's name ("disk" -> radius).
  for (const char* source : {"fuzz.txt", "fuzz_disk.txt"}) {
    PointSet ps;
    if (fuzz::accepts([&] { ps = parse_gabor_int(text, source, ReadOptions{}); }))
      fuzz::check_parsed(ps, Format::GaborInt, source);
  }
  return 0;
}
