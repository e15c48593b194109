// libFuzzer target: a run directory's run.json as its readers take it (core/run_json.hpp's
// parse_run_record, after the file's JSON parse). Contract: fuzz_common.hpp.
#include "core/config/json_text.hpp"
#include "core/run_json.hpp"
#include "tests/fuzz/fuzz_common.hpp"

using namespace ppsynth;

PPSYNTH_FUZZ_TEXT_TARGET {
  RunRecord r;
  if (!fuzz::accepts([&] { r = parse_run_record(parse_json_text(text, "run.json", false), "run.json"); })) return 0;
  if (r.seed > kMaxSeed || r.threads < 0 || r.threads > 1024 || !(r.total_seconds >= 0) || !r.method_stats.is_object())
    fuzz::fail("an accepted run.json holds a value out of its range");
  return 0;
}
