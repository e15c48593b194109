// libFuzzer target: a run directory's config.json as its readers take it (core/run_json.hpp):
// parsed as a file's JSON, then check_run_config. What it accepts must hold what every reader
// of a run's config uses (the method's type, the seed, the name, the exemplar) with their
// types, and write back as JSON. Contract: fuzz_common.hpp.
#include "core/config/json_text.hpp"
#include "core/content_hash.hpp"
#include "core/run_json.hpp"
#include "tests/fuzz/fuzz_common.hpp"

using namespace ppsynth;

PPSYNTH_FUZZ_TEXT_TARGET {
  nlohmann::json c;
  if (!fuzz::accepts([&] {
        c = parse_json_text(text, "config.json", false);
        check_run_config(c, "config.json");
      }))
    return 0;
  try {  // what the readers of an accepted config take from it, unchecked
    (void)c["method"]["type"].get<std::string>();
    if (c["seed"].get<uint64_t>() > kMaxSeed) fuzz::fail("an accepted seed past 2^63 - 1");
    (void)c["name"].get<std::string>();
    (void)c["exemplar"].get<std::string>();
    (void)json_id(c);
  } catch (const nlohmann::json::exception& e) {
    fuzz::fail(std::string("an accepted config.json breaks a reader: ") + e.what());
  }
  return 0;
}
