#pragma once
// A sweep's plan on disk (DIR/manifest.json; experiments/plan/sweep_plan.hpp plans it): one row per
// run, and what a task needs to run it. Read back, every value is checked before anything uses
// it -- the executors build job scripts and run directories from it -- so that an edited or
// crafted manifest is an InputError naming the file and the key, never a shell line, a path
// outside the sweep, or a resource out of range. Torch-free: the reader is fuzzed (tests/fuzz).
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ppsynth {

struct SweepRow {
  std::string id;      // 12 hex digits
  std::string label;   // "<group label> seed <s>"
  std::string group;   // id of the config without its seed (rows pooled by gather)
  std::string group_label;
  std::string source;  // the run or figure config it came from
  std::vector<std::string> overrides;
  uint64_t seed = 0;
  bool quick = false;
  std::string dir;     // relative to the sweep directory: runs/<id>
  nlohmann::json config;  // resolved run config (seed included)
};

// Per task (SLURM's --cpus-per-task, --mem, --time). The bounds are the checks of a manifest
// read back and of the command's overrides.
struct SweepResources {
  int cpus = 1;
  int memory_mb = 4096;
  int time_minutes = 240;
};
inline constexpr int kMaxSweepCpus = 4096;
inline constexpr int kMaxSweepMemoryMb = 64 * 1024 * 1024;  // 64 TiB
inline constexpr int kMaxSweepMinutes = 366 * 24 * 60;       // a year
// "resources.cpus" and the like: InputError naming `key` when `value` is outside its range.
void check_sweep_resource(const std::string& key, long long value);

struct SweepManifest {
  std::string name;
  std::string spec_source;
  nlohmann::json spec;
  SweepResources resources;
  std::vector<SweepRow> rows;
};

nlohmann::json sweep_manifest_json(const SweepManifest& m);
// The manifest's identity: a content hash of its JSON (16 hex digits). A task names the
// manifest it was given by it, so that a plan changed since is noticed.
std::string sweep_manifest_hash(const SweepManifest& m);
// `j` read from `source`, checked: a sweep's name and row ids are plain names, every row's
// directory is runs/<id>, ids are unique, seeds in [0, 2^63), configs resolved run configs
// (core/run_json.hpp), resources in range.
SweepManifest parse_sweep_manifest(const nlohmann::json& j, const std::string& source);

}  // namespace ppsynth
