// libFuzzer target: a run directory's metrics.json as gather reads it (core/metrics/
// metric_values.hpp, after the file's JSON parse): every value it returns is one of the
// file's numbers, under a key it names. Contract: fuzz_common.hpp.
#include "core/config/json_text.hpp"
#include "core/metrics/metric_values.hpp"
#include "tests/fuzz/fuzz_common.hpp"

using namespace ppsynth;

PPSYNTH_FUZZ_TEXT_TARGET {
  std::vector<std::pair<std::string, double>> v;
  if (!fuzz::accepts([&] { v = metric_values(parse_json_text(text, "metrics.json", false), "metrics.json"); })) return 0;
  for (const auto& [key, value] : v)
    if (key.find('/') == std::string::npos) fuzz::fail("a metric without its scope: " + key);
  return 0;
}
