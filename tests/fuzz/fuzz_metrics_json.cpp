// libFuzzer target: a run directory's metrics.json as gather reads it (core/metrics/
// metric_values.hpp, after the file's JSON parse): every value it returns is one of the
// file's numbers, under a key it names. Contract: fuzz_common.hpp.
#include "core/config/json_text.hpp"
#include "core/metrics/metric_values.hpp"
#include "tests/fuzz/fuzz_common.hpp"

using namespace ppsynth;

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  fuzz::quiet_logging();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::pair<std::string, double>> v;
  if (!fuzz::accepts([&] { v = metric_values(parse_json_text(text, "metrics.json", false), "metrics.json"); })) return 0;
  for (const auto& [key, value] : v)
    if (key.find('/') == std::string::npos) fuzz::fail("a metric without its scope: " + key);
  return 0;
}
