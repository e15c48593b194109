#pragma once
// The JSON files of a run directory (optim/run/run_store.hpp), read so that whatever is on
// disk -- edited by hand, truncated, or crafted -- is an InputError naming the file and the
// key, never a crash or an exception of the JSON library:
//   config.json   the resolved run config          read_run_config
//   run.json      what the run recorded of itself   read_run_record
//   metrics.json  the evaluation of its output      metric_values (core/metrics/metric_values.hpp)
// The directory's marker is core/run_directory.hpp's; a sweep's manifest core/sweep_manifest.hpp's.
// Torch-free: the readers are fuzzed (tests/fuzz).
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

namespace ppsynth {

// Seeds are integers in [0, 2^63): every front end (a config, --seed, a sweep's seeds, Python)
// takes exactly these.
inline constexpr uint64_t kMaxSeed = (uint64_t{1} << 63) - 1;
// True for a JSON integer in [0, 2^63).
bool is_seed(const nlohmann::json& value);

// A JSON file of a run directory; InputError naming it when missing, unreadable or not JSON.
nlohmann::json read_run_json(const std::string& path);

// The checks every reader of a resolved run config relies on: an object whose "name",
// "description", "exemplar", "format" and "scaling" are strings, whose "method" is an object
// with a string "type", whose "seed" is an integer in [0, 2^63), whose "quick"-independent
// "output" (when there) is an object. InputError naming `source` and the key otherwise.
void check_run_config(const nlohmann::json& config, const std::string& source);
// config.json, checked.
nlohmann::json read_run_config(const std::string& path);

// run.json: what a run recorded of itself. Absent keys (runs made before they were recorded)
// keep these values; a key of another type is an InputError naming the file and the key.
struct RunRecord {
  std::string name, revision;
  uint64_t seed = 0;
  bool quick = false;
  int threads = 0;          // 0: not recorded
  std::string processor;    // "": not recorded
  // The preset's variant that ran (run.json preset.variant, optim/run/presets.hpp): "every
  // processor" or "without bf16 units"; "": no preset, or not recorded.
  std::string preset_variant;
  double synthesis_seconds = 0, total_seconds = 0;
  double cpu_seconds = 0;   // the synthesis's CPU time (0: not recorded, runs before 2026-11-30)
  nlohmann::json method_stats = nlohmann::json::object();
};
RunRecord parse_run_record(const nlohmann::json& run, const std::string& source);
RunRecord read_run_record(const std::string& path);

}  // namespace ppsynth
