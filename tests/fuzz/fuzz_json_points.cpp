// libFuzzer target: this project's JSON point format (core/formats/json_format.hpp) and the
// write/read round trip of what it accepts. Contract: fuzz_common.hpp.
#include "core/formats/json_format.hpp"
#include "tests/fuzz/fuzz_common.hpp"

using namespace ppsynth;

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  fuzz::quiet_logging();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  PointSet ps;
  if (fuzz::accepts([&] { ps = parse_json_points(text, "fuzz.json"); }))
    fuzz::check_parsed(ps, Format::Json, "fuzz.json");
  return 0;
}
